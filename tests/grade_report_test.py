#!/usr/bin/env python3
"""The grade's report (tools/grade_report.py) on a grade state made by hand: what the
student_session meets only by chance. A failure that ran an earlier chapter's failing
exercise points back to it; what waits for an unwritten exercise is one scorecard line;
a passed golden image and a missing one get their rows; --expect sets the exit code; text
is escaped in the page; a chapter's key is written after its record; the hint names the
exercise that is wrong, not one that fails only through it.

  grade_report_test.py ROOT WORK
"""
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from checks import check, finish  # noqa: E402  (the tally the test scripts share)

root, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
shutil.rmtree(work, ignore_errors=True)
build, state, report = work / "build", work / "build" / "grade", work / "report"
state.mkdir(parents=True)

# Chapter 14: 1 of 3 unit tests pass; 14.1 fails its own test, 14.2 is not written yet.
(state / "ch14.unitscore").write_text("1 3\n")
(state / "ch14.unit").write_text(
    '  ch14 unit test "14.1 strata cover the square": a < b is false: 2 < 1 (ran your exercises 14.1)\n'
    '  ch14 unit test "14.2 the tent": exercise 14.2 is not done yet (take chapter 14 from solutions/ with'
    ' ./lab grade --solved "01;14")\n')
# Chapter 15: a test that ran 14.1 (which fails in chapter 14) and 15.1.
(state / "ch15.unitscore").write_text("0 1\n")
(state / "ch15.unit").write_text('  ch15 unit test "15.2 strata": 3 == 4 is false (ran your exercises 14.1 15.1)\n')
# ctest's log: one golden image of each chapter passed, the other never ran.
(state / "ctest.txt").write_text(
    " 1/2 Test  #7: golden_ch14_edges ................   Passed    0.41 sec\n"
    " 2/2 Test  #9: golden_ch15_fence ................***Failed    0.52 sec\n")
for ch, scene in (("14", "edges"), ("15", "fence")):
    out = build / "golden" / f"golden_ch{ch}_{scene}"
    out.mkdir(parents=True)
    (out / f"{scene}.txt").write_text("t-test: 8 renders <fine>\n")
fence = build / "golden" / "golden_ch15_fence" / "fence"
fence.with_name("fence.txt").write_text("t-test: 12 pixel-channels fail\n")
fence.with_name("fence.uses").write_text("14.1\n")


def grade(*extra):
    return subprocess.run([sys.executable, root / "tools" / "grade_report.py", "--build", build, "--state", state,
                           "--report", report, "--chapters", "14 15", "--solved", "15", *extra],
                          capture_output=True, text=True)


r = grade("--graded", "14=key14", "--graded", "15=key15", "--expect", "all")
lines = r.stdout.splitlines()
check(r.returncode == 1 and "expected everything to pass" in r.stderr,
      f"--expect all with failures exits 1 and says so: {r.returncode} {r.stderr!r}")
check((state / "ch14.key").read_text() == "key14\n", "the key of chapter 14 is written")
# The real grade lists every golden scene the chapter has; this state made two of them.
edges = next((l for l in lines if l.startswith("ch14 ")), "")
check(edges.startswith("ch14       1 of 3   ") and edges.endswith("yours     "), f"ch14's scorecard line: {edges!r}")
check(any(l.startswith("ch15       0 of 1   ") and l.endswith("solutions/") for l in lines),
      f"ch15 from solutions/: {lines}")
want = ('  ch15 unit test "15.2 strata": 3 == 4 is false (ran your exercises 14.1 15.1); start with 14.1, '
        "which fails its own tests in its chapter")
check(want in lines, f"a failure that ran a failing earlier exercise points back to it:\n{r.stdout}")
check('  ch14: 1 tests and images stop at exercises not done yet: 14.2 (or take chapter 14 from solutions/ with'
      ' ./lab grade --solved "01;14")' in lines, f"one line for what waits:\n{r.stdout}")
check(any("golden image fence: differs past the tolerance: t-test: 12 pixel-channels fail (ran your exercises 14.1)"
          in l for l in lines), f"the failed statistical image and the exercises it ran:\n{r.stdout}")
check("chapters graded: 14 15 (0 cached)" in lines, f"nothing cached: {lines}")
page = (report / "report.html").read_text()
check("<code>t-test: 8 renders &lt;fine&gt;</code>" in page, "a score is escaped in the page")
check('<span class="pass">match</span>' in page and '<span class="fail">differs</span>' in page,
      "one match and one difference")
check("Noisy chapters (14 on)" in page and "average of 8 renders" in page and "1 % false-alarm rate" in page,
      "the legend's numbers come from tools/settings.cmake")

# Again, nothing graded: both chapters come from their records, marked cached; --expect none
# fails since a test passed.
r = grade("--expect", "none")
check(r.returncode == 1 and "expected nothing to pass" in r.stderr, f"--expect none: {r.returncode} {r.stderr!r}")
check("chapters graded: 14 15 (2 cached)" in r.stdout.splitlines(), f"both cached:\n{r.stdout}")
r = grade()
check(r.returncode == 0, f"without --expect the exit code is 0 whatever the score: {r.returncode}")
# A chapter without a record (a grade that stopped) is not reported from nothing.
(state / "ch15.json").unlink()
r = grade()
check(r.returncode == 1 and "no result for chapter 15" in r.stderr, f"a missing record: {r.stderr!r}")

# The hint names the exercise that is wrong, not one that fails only through it: a wrong 9.2
# fails the test named for 9.1 that runs both, and its own; 9.1 is right. Chapter 10's failure
# ran both, and points back to 9.2 alone (it used to say "start with 9.1, 9.2").
state9 = work / "build9" / "grade"
state9.mkdir(parents=True)
(state9 / "ch09.unitscore").write_text("1 3\n")
(state9 / "ch09.unit").write_text(
    '  ch09 unit test "9.1 instances hit where the mesh does": dot >= 0.999 is false: -1 >= 0.999'
    ' (ran your exercises 9.1 9.2)\n'
    '  ch09 unit test "9.2 mirrors and near-flat scales": dot > 0 is false: -1 > 0 (ran your exercises 9.2)\n')
(state9 / "ch10.unitscore").write_text("0 1\n")
(state9 / "ch10.unit").write_text(
    '  ch10 unit test "10.4 instances in the tree": 3 == 4 is false (ran your exercises 9.1 9.2 10.1 10.4)\n')
r = subprocess.run([sys.executable, root / "tools" / "grade_report.py", "--build", work / "build9", "--state", state9,
                    "--report", work / "report9", "--chapters", "09 10", "--units", "--graded", "09=k9",
                    "--graded", "10=k10"], capture_output=True, text=True)
want = ('  ch10 unit test "10.4 instances in the tree": 3 == 4 is false (ran your exercises 9.1 9.2 10.1 10.4); '
        "start with 9.2, which fails its own tests in its chapter")
check(want in r.stdout.splitlines(), f"the hint names the wrong exercise, 9.2, not 9.1:\n{r.stdout}{r.stderr}")
finish("grade_report")
