#!/usr/bin/env bash
# Book §B.8: what grading a class costs, in machine time per student (issue 42's target: at most
# 30 s for all 18 chapters on the 2-core machine).
#
#   bench/class_grade.sh OUT_MD [STUDENTS] [--no-sandbox]
#
# Makes STUDENTS submissions (default 20, at least 20 for the book): the reference's bodies,
# the stubs, mixes (each chapter's file from one or the other, by a fixed pattern) and the cheats
# of tests/adversarial/ (as 2.2). Every body written carries a comment naming its student, so no
# two students hand in the same file and none is graded from another's compiled object: the
# figure is a class whose files all differ, the grader's cache helping only with untouched stubs.
# Then ./lab grade-class on every released chapter, with as many students at once as there are
# cores, and the time: the class's build once, then the run's wall time times the cores over
# the students, and where a student's time goes (unpacking, compiling, linking, running).
set -euo pipefail
cd "$(dirname "$0")/.."
out_md=${1:?usage: bench/class_grade.sh OUT_MD [STUDENTS] [--no-sandbox]}
students=${2:-20}
[[ $students =~ ^[0-9]+$ && $students -ge 1 ]] || { echo "class_grade: STUDENTS must be a whole number" >&2; exit 2; }
sandbox=()
[[ ${3-} == --no-sandbox ]] && sandbox=(--no-sandbox)
work=build/bench-class
rm -rf "$work"
mkdir -p "$work/submissions"
python3 - "$work/submissions" "$students" <<'PY'
import sys
from pathlib import Path
sys.path.insert(0, "tests")
from exercise_text import exercise_text, file_name  # noqa: E402
import subprocess
root = Path(".")
subs, n = Path(sys.argv[1]), int(sys.argv[2])
chapters = subprocess.run(["cmake", "-DGET=RTLAB_RELEASED", "-P", "tools/settings.cmake"], capture_output=True,
                          text=True, check=True).stdout.split()
cheats = sorted((root / "tests" / "adversarial").glob("*.cpp"))
for k in range(n):
    name = f"student-{k:02d}"
    d = subs / name / "exercises"
    d.mkdir(parents=True)
    kind = ["reference", "stubs", "mix", "mix", "cheat"][k % 5]
    for j, ch in enumerate(chapters):
        if kind == "stubs" or (kind == "mix" and (j + k) % 3 == 0):
            text = (root / "exercises" / file_name(root, ch)).read_text()
        elif kind == "cheat" and ch == "02":
            lines = cheats[k // 5 % len(cheats)].read_text().replace("RTLAB_ROOT", f'"{root.resolve()}"').splitlines()
            helpers = "\n".join(lines[lines.index("// @helpers") + 1:lines.index("// @body")]) + "\n"
            body = "\n".join(lines[lines.index("// @body") + 1:]) + "\n"
            text = exercise_text(root, ch, {"2.2": body}, helpers, mark=name)
        else:
            text = exercise_text(root, ch, mark=name)
        (d / file_name(root, ch)).write_text(text)
PY
jobs=$(nproc)
start=$(date +%s.%N)
tools/grade-class --prepare
prepared=$(date +%s.%N)
tools/grade-class "$work/submissions" --out "$work/out" --jobs "$jobs" "${sandbox[@]}" | tee "$work/run.txt"
end=$(date +%s.%N)
python3 - "$work" "$students" "$jobs" "$start" "$prepared" "$end" "$out_md" "${sandbox[@]}" <<'PY'
import json, re, statistics, sys, subprocess
from pathlib import Path
work, n, jobs, start, prepared, end, out_md = Path(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), *map(float, sys.argv[4:7]), sys.argv[7]
plain = len(sys.argv) > 8
run = (work / "run.txt").read_text()
m = re.search(r"students, chapters [0-9 ]+: (\d+) s \(([0-9.]+) s of machine time per student with \d+ at once\), "
              r"after (\d+) s for the reference", run)
if not m:
    sys.exit("class_grade: grade-class did not say its times:\n" + run[-2000:])
wall, per, reference = float(m[1]), float(m[2]), float(m[3])
budget = re.search(r"each student's may run (\d+) s in all \(([^)]*)\)", run)
steps = [json.loads(p.read_text()) for p in sorted((work / "out" / ".work").glob("student-*/seconds.json"))]
cpu = subprocess.run(["sh", "-c", "sed -n 's/^model name\\s*: //p' /proc/cpuinfo | head -1"], capture_output=True, text=True).stdout.strip()
lines = [f"_Measured by `./lab bench class-grade` (`bench/class_grade.sh`): {n} students, every released chapter, "
         f"{jobs} at once{' without the sandbox' if plain else ' in the sandbox'}, on {cpu}._", "",
         "| | seconds |", "|---|---|",
         f"| the class's build, once (`grade-class --prepare`, nothing to rebuild) | {prepared - start:.1f} |",
         f"| the reference, graded first as a student (once per class run) | {reference:.0f} |",
         f"| the {n} students, wall time | {wall:.0f} |",
         f"| **machine time per student** (wall × {jobs} cores / {n}) | **{per:.1f}** |"]
if budget:
    lines.append(f"| a student's runs may take, in all ({budget[2]}) | {budget[1]} |")
for step in ("take", "compile", "link", "run"):
    values = [s.get(step, 0) for s in steps]
    if values:
        lines.append(f"| a student's {step} (median, wall) | {statistics.median(values):.1f} |")
Path(out_md).parent.mkdir(parents=True, exist_ok=True)
Path(out_md).write_text("\n".join(lines) + "\n")
print("\n".join(lines))
PY
