#!/usr/bin/env python3
"""The JSON Schema of scene files, tested as a schema (python3-jsonschema, Draft 2020-12).

  schema_test.py ROOT LIMITS_TOOL CHAPTER_BINARY WORK_DIR

- The schema is itself a valid Draft 2020-12 schema.
- Every limit of common/geometry/limits.hpp (printed by LIMITS_TOOL) is what the schema
  states at the place the table names: one table, and the schema agrees with it.
- Every scene file in the repository and every ```json example of book appendix A
  validates, and loads and renders in CHAPTER_BINARY (exit 0).
- Every file in tests/data/bad/ fails both: the schema rejects it, and the loader exits 2.
- Every surface and light type a module of common/io/types/ defines is listed in the schema
  (whose lists the loader's table is generated from).
Prints one line per failure and a closing "N passed, N failed" line; exit 1 on any failure.
"""
import json
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from checks import check, finish  # noqa: E402

import jsonschema

root, limits_tool, chapter, work = (pathlib.Path(a) for a in sys.argv[1:5])
work.mkdir(parents=True, exist_ok=True)
schema = json.loads((root / "common/io/scene.schema.json").read_text())




def resolve(pointer):
    node = schema
    for part in pointer.strip("/").split("/"):
        node = node[int(part)] if isinstance(node, list) else node[part.replace("~1", "/").replace("~0", "~")]
    return node


jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)

limits = json.loads(subprocess.run([str(limits_tool)], check=True, capture_output=True, text=True).stdout)
check(len([x for x in limits if x["schema"]]) >= 10, "expected the scene limits of limits.hpp")
for limit in limits:
    if not limit["schema"]:  # a resource limit (file sizes, image size): not a scene value
        continue
    node = resolve(limit["schema"])
    lo, hi = ("minItems", "maxItems") if node.get("type") == "array" or "minItems" in node else ("minimum", "maximum")
    check(node.get(lo) == limit["min"] and node.get(hi) == limit["max"],
          f'{limit["name"]}: code says {limit["min"]}..{limit["max"]}, schema at {limit["schema"]} says '
          f'{node.get(lo)}..{node.get(hi)}')


def loads(path):
    r = subprocess.run([str(chapter), "--scene", str(path), "--width", "4", "--height", "3",
                        "-o", str(work / "schema-test.pfm")], capture_output=True, text=True)
    return r.returncode, r.stderr.strip()


# Every type a module of common/io/types/ defines is one the schema lists: the loader's
# table is generated from the schema's lists (common/CMakeLists.txt), so a module whose type
# the schema lacks would never be linked in, and its type would be silently unknown.
for kind in ("surface", "light"):
    listed = {entry["properties"]["type"]["const"] for entry in schema["$defs"][kind]["oneOf"]}
    defined = set()
    for module in sorted((root / "common/io/types").glob("*.cpp")):
        for name in re.findall(rf"^RTLAB_{kind.upper()}_TYPE\((\w+),", module.read_text(), re.M):
            defined.add(name)
            check(name in listed, f"{module.name}: {kind} type '{name}' is not in the schema's $defs/{kind}/oneOf")
    check(len(defined) >= (9 if kind == "surface" else 3), f"expected the {kind} types' modules, found {sorted(defined)}")

good = sorted(root.glob("chapters/*/scenes/*.json")) + sorted(root.glob("bench/scenes/*.json"))
check(len(good) >= 6, f"expected the repository's scene files, found {len(good)}")
appendix = (root / "book/appendix-a-scene-format.md").read_text()
for i, block in enumerate(re.findall(r"```json\n(.*?)```", appendix, re.S)):
    path = work / f"appendix-example-{i}.json"
    path.write_text(block)
    good.append(path)
for path in good:
    doc = json.loads(path.read_text())
    errors = [e.message for e in validator.iter_errors(doc)]
    check(not errors, f"{path}: schema rejects a good file: {errors[:1]}")
    code, err = loads(path)
    check(code == 0, f"{path}: loader exit {code}: {err}")

bad = sorted((root / "tests/data/bad").glob("*.json"))
check(len(bad) >= 10, f"expected at least 10 bad files, found {len(bad)}")
for path in bad:
    check(not validator.is_valid(json.loads(path.read_text())), f"{path}: the schema accepts a bad file")
    code, err = loads(path)
    check(code == 2 and err.count("\n") == 0 and path.name in err, f"{path}: loader exit {code}, message {err!r}")

finish("schema_test")
