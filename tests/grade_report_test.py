#!/usr/bin/env python3
"""The grade's report (tools/grade_report.py) on chapter records made by hand: what the
student_session meets only by chance. A failure that ran an earlier chapter's failing
exercise points back to it, and names the exercise that is wrong, not one that fails only
through it; what waits for an unwritten exercise is one scorecard line; a passed golden
image and a missing one get their rows; --expect sets the exit code; text is escaped in the
page; a compiler warning is shown; a chapter without a record is not reported from nothing.

  grade_report_test.py ROOT WORK
"""
import json
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from checks import check, finish  # noqa: E402  (the tally the test scripts share)

root, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
shutil.rmtree(work, ignore_errors=True)


def unit(name, passed, reason=""):
    return {"name": name, "passed": passed, "reason": reason}


def row(scene, passed, score, yours=True):
    return {"scene": scene, "passed": passed, "reference": True, "yours": yours, "heatmap": yours, "score": score,
            "reason": "" if passed else f"golden image {scene}: differs past the tolerance: {score}"}


def chapter(units, reasons, rows=(), warnings=()):
    """A record as tools/grading/chapter.py leaves it (STATE/chNN.json)."""
    rows = list(rows)
    return {"unit_passed": sum(u["passed"] for u in units), "unit_total": len(units), "units": units,
            "rows": rows, "reasons": list(reasons) + [f"  {r['reason']}" for r in rows if not r["passed"]],
            "golden_passed": sum(r["passed"] for r in rows), "golden_total": len(rows),
            "units_only": not rows, "warnings": list(warnings)}


def write(state, records):
    state.mkdir(parents=True, exist_ok=True)
    for ch, rec in records.items():
        (state / f"ch{ch}.json").write_text(json.dumps(rec))
        pictures = state / "img" / f"ch{ch}"
        pictures.mkdir(parents=True, exist_ok=True)
        for r in rec["rows"]:
            for name in ("reference", "yours", "heatmap"):
                if r[name]:
                    (pictures / f"{r['scene']}-{name}.png").write_bytes(b"png")


def grade(build, chapters, *extra):
    return subprocess.run([sys.executable, root / "tools" / "grade_report.py", "--build", build,
                           "--state", build / "grade", "--report", build / "report", "--chapters", chapters, *extra],
                          capture_output=True, text=True)


# Chapter 14: 1 of 3 unit tests pass; 14.1 fails its own test, 14.2 is not written yet.
# Chapter 15, from solutions/: a test that ran 14.1 (which fails in chapter 14) and 15.1; one
# golden image that ran 14.1 differs, and the compiler warned of something in chapter 14.
s14 = ['  ch14 unit test "14.1 strata cover the square": a < b is false: 2 < 1 (ran your exercises 14.1)',
       '  ch14 unit test "14.2 the tent": exercise 14.2 is not done yet (take chapter 14 from solutions/ with'
       ' ./lab grade --solved "01;14")']
s15 = ['  ch15 unit test "15.2 strata": 3 == 4 is false (ran your exercises 14.1 15.1)']
build = work / "build"
write(build / "grade", {
    "14": chapter([unit("14.1 strata cover the square", False), unit("14.2 the tent", False), unit("14.3", True)],
                  s14, [row("edges", True, "t-test: 8 renders <fine>")],
                  ["exercises/ch14.cpp:12:5: warning: unused variable 'u' [-Wunused-variable]"]),
    "15": chapter([unit("15.2 strata", False)], s15,
                  [row("fence", False, "t-test: 12 pixel-channels fail (ran your exercises 14.1)", yours=False)])})

r = grade(build, "14 15", "--solved", "15", "--graded", "14", "--graded", "15", "--expect", "all")
lines = r.stdout.splitlines()
check(r.returncode == 1 and "expected everything to pass" in r.stderr,
      f"--expect all with failures exits 1 and says so: {r.returncode} {r.stderr!r}")
edges = next((l for l in lines if l.startswith("ch14 ")), "")
check(edges.startswith("ch14       1 of 3       1 of 1") and edges.rstrip().endswith("yours"),
      f"ch14's scorecard line: {edges!r}")
check(any(l.startswith("ch15       0 of 1       0 of 1") and l.rstrip().endswith("solutions/") for l in lines),
      f"ch15 from solutions/: {lines}")
want = ('  ch15 unit test "15.2 strata": 3 == 4 is false (ran your exercises 14.1 15.1); start with 14.1, '
        "which fails its own tests in its chapter")
check(want in lines, f"a failure that ran a failing earlier exercise points back to it:\n{r.stdout}")
check('  ch14: 1 tests and images stop at exercises not done yet: 14.2 (or take chapter 14 from solutions/ with'
      ' ./lab grade --solved "01;14")' in lines, f"one line for what waits:\n{r.stdout}")
check(any("golden image fence: differs past the tolerance: t-test: 12 pixel-channels fail (ran your exercises 14.1)"
          in l for l in lines), f"the failed statistical image and the exercises it ran:\n{r.stdout}")
check("compiler warnings in your exercises (the report has all):" in lines and
      any("unused variable 'u'" in l for l in lines), f"the compiler's warning is shown:\n{r.stdout}")
check("chapters graded: 14 15 (0 cached)" in lines, f"nothing cached: {lines}")
page = (build / "report" / "report.html").read_text()
check("<code>t-test: 8 renders &lt;fine&gt;</code>" in page, "a score is escaped in the page")
check('<span class="pass">match</span>' in page and '<span class="fail">differs</span>' in page,
      "one match and one difference")
check("(no image of yours)" in page and (build / "report" / "img" / "ch14" / "edges-yours.png").is_file(),
      "a missing image says so; a present one is copied beside the page")
check("Noisy chapters (14 on)" in page and "average of 8 renders" in page and "1 % false-alarm rate" in page,
      "the legend's numbers come from tools/settings.cmake")

# Again, nothing graded now: both chapters come from their records, marked cached; --expect
# none fails since a test passed; without --expect the exit code is 0 whatever the score.
r = grade(build, "14 15", "--solved", "15", "--expect", "none")
check(r.returncode == 1 and "expected nothing to pass" in r.stderr, f"--expect none: {r.returncode} {r.stderr!r}")
check("chapters graded: 14 15 (2 cached)" in r.stdout.splitlines(), f"both cached:\n{r.stdout}")
r = grade(build, "14 15")
check(r.returncode == 0, f"without --expect the exit code is 0 whatever the score: {r.returncode}")
# A chapter without a record (a grade that stopped) is not reported from nothing.
(build / "grade" / "ch15.json").unlink()
r = grade(build, "14 15")
check(r.returncode == 1 and "no result for chapter 15" in r.stderr, f"a missing record: {r.stderr!r}")

# The hint names the exercise that is wrong, not one that fails only through it: a wrong 9.2
# fails the test named for 9.1 that runs both, and its own; 9.1 is right. Chapter 10's failure
# ran both, and points back to 9.2 alone.
build9 = work / "build9"
write(build9 / "grade", {
    "09": chapter([unit("9.1", False), unit("9.2", False), unit("9.3", True)], [
        '  ch09 unit test "9.1 instances hit where the mesh does": dot >= 0.999 is false: -1 >= 0.999'
        ' (ran your exercises 9.1 9.2)',
        '  ch09 unit test "9.2 mirrors and near-flat scales": dot > 0 is false: -1 > 0 (ran your exercises 9.2)']),
    "10": chapter([unit("10.4", False)],
                  ['  ch10 unit test "10.4 instances in the tree": 3 == 4 is false (ran your exercises 9.1 9.2 10.1'
                   ' 10.4)'])})
r = grade(build9, "09 10", "--units", "--graded", "09", "--graded", "10")
want = ('  ch10 unit test "10.4 instances in the tree": 3 == 4 is false (ran your exercises 9.1 9.2 10.1 10.4); '
        "start with 9.2, which fails its own tests in its chapter")
check(want in r.stdout.splitlines(), f"the hint names the wrong exercise, 9.2, not 9.1:\n{r.stdout}{r.stderr}")
finish("grade_report")
