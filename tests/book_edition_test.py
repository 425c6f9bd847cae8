#!/usr/bin/env python3
"""The student edition of the book holds no reference answer; the instructor edition does.

  book_edition_test.py ROOT BOOK_TOOL WORK_DIR

Builds both editions as Markdown (rtlab-book --markdown-only), then looks for every
substantial line of every exercise body in solutions/ (20 characters or more once trimmed).
None may appear in the student edition; the instructor edition must show the bodies its
excerpts include (so the check itself can fail). Closing line: "N passed, N failed".
"""
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from checks import check, finish  # noqa: E402

root, tool, work = (pathlib.Path(a) for a in sys.argv[1:4])




def edition(name):
    out = work / name
    subprocess.run([str(tool), "--root", str(root), "--out", str(out), "--edition", name, "--markdown-only"],
                   check=True)
    return "\n".join(p.read_text() for p in sorted((out / "md").glob("*.md")))


student, instructor = edition("student"), edition("instructor")
bodies = []
for source in sorted((root / "solutions").glob("*.cpp")):
    inside = None
    for line in source.read_text().splitlines():
        if re.match(r"\s*// @exercise\s", line):
            inside = line.split("|")[0].strip()[len("// @exercise"):].strip()
        elif re.match(r"\s*// @end\s*$", line):
            inside = None
        elif inside and len(line.strip()) >= 20:
            bodies.append((source.name, inside, line.strip()))
check(len(bodies) > 50, f"expected the exercise bodies of solutions/, found {len(bodies)} lines")
shown = 0
for name, exercise, line in bodies:
    check(line not in student, f"student edition shows exercise {exercise} ({name}): {line}")
    shown += line in instructor
check(shown > len(bodies) // 2, f"instructor edition shows only {shown} of {len(bodies)} body lines")
check("yours to write" in student, "student edition has no exercise placeholders")
finish("book_edition_test")
