#!/usr/bin/env bash
# The scorecard book §0.1 and §0.6 show, made by grading a student's work for real
# (./lab bench scorecard), so its counts are the chapters' real ones:
#   chapter 1 taken from solutions/; chapter 2 written (the reference bodies) except exercise
#   2.2, written with the textbook's formula (tests/fairness/2.2_textbook_form.cpp); chapter 3
#   not started. Then: ./lab grade 01 02 03 --solved "01".
# Writes OUT_DIR/scorecard.md (the whole output, long lines cut where they say "..."),
# OUT_DIR/scorecard-rows.md (the rows alone) and OUT_DIR/scorecard-says.md (what the rows say).
# Works on a fresh clone of the committed lab; builds the exercises track (minutes).
#
#   bench/scorecard.sh OUT_DIR [WORK_DIR]     (default: a new temporary folder, removed after)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(cd "${1:?usage: bench/scorecard.sh OUT_DIR [WORK_DIR]}" && pwd)
work=${2:-$(mktemp -d /tmp/rtlab-scorecard.XXXXXX)}
[[ -n ${2-} ]] || trap 'rm -rf "$work"' EXIT  # a folder of its own making goes when done
rm -rf "$work/lab"
git clone -q "$root" "$work/lab"
cd "$work/lab"
python3 - <<'PY'
# Chapter 2's reference bodies into exercises/, then 2.2's textbook variant over its own.
import glob, os, re
def put(text, number, body):
    return re.sub(r"(// @exercise " + re.escape(number) + r" .*?\n).*?(\n\s*// @end)",
                  lambda e: e.group(1) + body.rstrip("\n") + e.group(2), text, count=1, flags=re.S)
solution = glob.glob("solutions/ch02_*.cpp")[0]
exercise = "exercises/" + os.path.basename(solution)
sol, ex = open(solution).read(), open(exercise).read()
for m in re.finditer(r"// @exercise (\S+) .*?\n(.*?)\n\s*// @end", sol, re.S):
    ex = put(ex, m.group(1), m.group(2))
variant = open("tests/fairness/2.2_textbook_form.cpp").read()
ex = put(ex, "2.2", variant.split("// @body\n", 1)[1])
open(exercise, "w").write(ex)
PY
command=(./lab grade 01 02 03 --solved "01")
"${command[@]}" >"$work/grade.txt" 2>&1 || { cat "$work/grade.txt"; echo "scorecard: the grade did not run" >&2; exit 1; }
python3 - "$work/grade.txt" "$out" "${command[*]}" <<'PY'
import re, sys
text, out, command = open(sys.argv[1]).read(), sys.argv[2], sys.argv[3]
lines = [l.rstrip() for l in text.splitlines() if not l.startswith(("==", "lab:", "--", "[")) and l.strip()]
start = next(i for i, l in enumerate(lines) if l.startswith("grade: "))
lines = lines[start:]
rows = [l for l in lines if re.match(r"^ch\d\d\s", l) or l.startswith("chapter ")]
def cut(l, width=330):
    """A long failure line keeps its first captured input: 'check [a := 1; b := 2] (ran ...)' -> '[a := 1; ...]'."""
    m = re.match(r"^(.*? \[.*?); .*(\] \(ran .*)$", l)
    if len(l) <= width or not m:
        return l
    return m.group(1) + "; ..." + m.group(2)
command = command.replace("--solved 01", '--solved "01"')
with open(f"{out}/scorecard.md", "w") as f:
    f.write("```\n$ " + command + "\n" + "\n".join(cut(l) for l in lines) + "\n```\n")
with open(f"{out}/scorecard-rows.md", "w") as f:
    f.write("```\n" + "\n".join(rows) + "\n```\n")
r = {m.group(1): m for m in (re.match(r"^ch(\d\d)\s+(\d+) of (\d+)\s+(\d+) of (\d+)\s+(\S+)", l) for l in rows) if m}
two, three = r["02"], r["03"]
if not (r["01"].group(2) == r["01"].group(3) and int(two.group(2)) < int(two.group(3)) and three.group(2) == "0"):
    sys.exit("scorecard: the rows no longer say what the book explains (01 full, 02 short of full, 03 none)")
with open(f"{out}/scorecard-says.md", "w") as f:
    golden = (f"all {two.group(5)} of its" if two.group(4) == two.group(5) else f"{two.group(4)} of its {two.group(5)}")
    f.write(f"Chapter 2 passes {two.group(2)} of its {two.group(3)} unit tests and {golden} golden images (renders compared with reference pictures, §0.7), with your code; "
            f"chapter 1 came from `solutions/`; chapter 3 is not written yet.\n")
print(open(f"{out}/scorecard.md").read())
PY
