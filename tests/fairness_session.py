#!/usr/bin/env python3
"""The fairness session (issue 28): is the grader fair to answers that differ from solutions/?

    fairness_session.py ROOT WORK_DIR [VARIANT ...]

On a copy of the lab in WORK_DIR (the student's exercises/ are never touched), every exercise is
answered with the reference's body, and each variant of tests/fairness/ (or only those named)
takes the place of one of them. tools/grade then grades the variant's chapter, and:

- a `pass` variant (a correct answer that differs legitimately) must get full marks, unit tests
  and images;
- a `fail` variant (a subtly wrong one) must not, and a failure line must name its exercise:
  a unit test named for it ("11.2 ..."), or a failure that says it ran it; with `expect: TEXT`,
  one of the chapter's failure lines must also contain TEXT (e.g. "crashed");
- either way the chapter's unit-test denominator is the reference's: nothing a student writes
  changes it.

A variant file:  // fairness 11.2 fail: why ...   then optional comment lines (and "// expect: TEXT",
"// images" to grade a fail variant's images too), an optional "// @helpers" section (lines
for the file's helper region), and "// @body" followed by the body.

To keep it quick, variants share rounds: one grade per round, on the round's chapters only.
A wrong body in chapter c also reaches the programs of later chapters (they link the
student's exercises up to theirs), so a round holds at most one fail variant of a chapter,
and only pass variants of earlier chapters beside it. Pass variants of different exercises
of one chapter share its file in a round (correct answers together are still correct);
should that chapter miss full marks, each of them is graded again alone, to say which. A
fail variant whose every line about it also ran another wrong body of its round is graded
again, in a round with others whose lines ran none of their exercises (what hid each is in
its lines), and alone if it is hidden once more. Fail variants are graded on their unit
tests only (tools/grade --units) unless they say "// images". Rounds run in as many lanes
as there are cores, each on a copy of its own.
"""
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from checks import check, finish  # noqa: E402  (the tally the test scripts share)
from exercise_text import put, region  # noqa: E402  (a region of an exercise file, replaced)

HEADER = re.compile(r"^// fairness (\d+)\.(\d+) (pass|fail): (.+)$")


class Variant:
    def __init__(self, path):
        self.path = path
        self.name = path.stem
        lines = path.read_text().splitlines()
        m = HEADER.match(lines[0]) if lines else None
        if not m:
            raise SystemExit(f"{path}: the first line must be '// fairness N.M pass|fail: why'")
        self.chapter = f"{int(m[1]):02d}"
        self.exercise = f"{int(m[1])}.{m[2]}"
        self.verdict = m[3]
        self.why = m[4]
        self.expect = None
        self.images = self.verdict == "pass"
        self.helpers = ""
        section = None
        body = []
        for line in lines[1:]:
            if section is None:
                if line.startswith("// expect:"):
                    self.expect = line.split(":", 1)[1].strip()
                elif line.strip() == "// images":
                    self.images = True
                elif line.strip() == "// @helpers":
                    section = "helpers"
                elif line.strip() == "// @body":
                    section = "body"
            elif section == "helpers":
                if line.strip() == "// @body":
                    section = "body"
                else:
                    self.helpers += line + "\n"
            else:
                body.append(line)
        if section != "body":
            raise SystemExit(f"{path}: no '// @body' line")
        self.body = "\n".join(body).rstrip("\n") + "\n"


def exercise_file(root, work, chapter, variants=()):
    """The chapter's exercise file with the reference's bodies and the variants' ones (of
    different exercises), their helper lines one after another."""
    solution = next((root / "solutions").glob(f"ch{chapter}_*.cpp"))
    target = work / "exercises" / solution.name
    stub = target.read_text()
    reference = solution.read_text()
    for m in re.finditer(r"^[ \t]*// @exercise (\S+) \|", reference, re.M):
        number = m[1]
        a, b = region(reference, r"// @exercise " + re.escape(number) + r" \|")
        stub = put(stub, r"// @exercise " + re.escape(number) + r" \|", reference[a:b])
    helpers = ""
    for variant in variants:
        stub = put(stub, r"// @exercise " + re.escape(variant.exercise) + r" \|", variant.body)
        helpers += variant.helpers
    if helpers:
        stub = put(stub, r"// @helpers", helpers)
    target.write_text(stub)


def rounds(variants):
    """Rounds of variants, as the module doc says: at most one fail variant of a chapter each,
    and pass variants of one chapter only beside others of different exercises."""
    fails = sorted((v for v in variants if v.verdict == "fail"), key=lambda v: (v.chapter, v.name))
    passes = sorted((v for v in variants if v.verdict == "pass"), key=lambda v: (v.chapter, v.name))
    out = []
    # Wrong bodies of different chapters share a round (the first round without their
    # chapter). One that crashes or hangs (it says what to expect) has a round of its own: it
    # would stop later chapters' programs too, and each stop costs a rerun of every test case.
    for f in fails:
        if f.expect:
            out.append([f])
            continue
        group = next((g for g in out if not g[0].expect and all(f.chapter != x.chapter for x in g)), None)
        if group is None:
            out.append([f])
        else:
            group.append(f)
    # Correct ones go where no wrong body of their chapter or an earlier one reaches them, one
    # per exercise.
    for group in out:
        lowest = min(g.chapter for g in group)
        for p in list(passes):
            if p.chapter < lowest and all(p.exercise != g.exercise for g in group):
                group.append(p)
                passes.remove(p)
    while passes:
        group = []
        for p in list(passes):
            if all(p.exercise != g.exercise for g in group):
                group.append(p)
                passes.remove(p)
        out.append(group)
    return out


def score(out, chapter):
    m = re.search(rf"^ch{chapter} +(\d+) of (\d+) +(?:(\d+) of (\d+)|\(not run\))", out, re.M)
    if not m:
        return None
    return [int(x) if x is not None else None for x in m.groups()]


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__.split("\n\n")[1])
    root = Path(sys.argv[1]).resolve()
    work = Path(sys.argv[2]).resolve()
    wanted = set(sys.argv[3:])
    variants = [Variant(p) for p in sorted((root / "tests" / "fairness").glob("*.cpp"))]
    if wanted:
        variants = [v for v in variants if v.name in wanted]
    chapters = subprocess.run(["cmake", "-DGET=RTLAB_CHAPTERS", "-P", str(root / "tools" / "settings.cmake")],
                              check=True, capture_output=True, text=True).stdout.split()

    # Each chapter's denominator, counted in its source: what the grade must say, whatever runs.
    totals = {c: len(re.findall(r"^\s*TEST_CASE\(", (root / "tests" / f"test_ch{c}.cpp").read_text(), re.M))
              for c in chapters}

    # A round mostly waits on one chapter's test program, one core: as many lanes as cores,
    # each a copy of the lab of its own, take the rounds in turn.
    shutil.rmtree(work, ignore_errors=True)
    lanes = max(1, min(os.cpu_count() or 1, 4))
    copies = []
    for k in range(lanes):
        copy = work / f"lane{k}"
        shutil.copytree(root, copy, ignore=shutil.ignore_patterns(".git", "build", "out"), symlinks=True)
        # Every exercise answered as the reference does, as a student who finished them all:
        # one configuration serves every round (no --solved to change), and a round
        # recompiles only the files of its variants.
        for c in chapters:
            exercise_file(root, copy, c)
        copies.append((copy, {p.name: p.read_text() for p in (copy / "exercises").glob("*.cpp")}))

    def grade(lane, group):
        copy, pristine = copies[lane]
        for name, text in pristine.items():
            (copy / "exercises" / name).write_text(text)
        mine = sorted({v.chapter for v in group})
        for c in mine:
            exercise_file(root, copy, c, [v for v in group if v.chapter == c])
        units = all(not v.images for v in group)
        command = ["tools/grade", *mine, "--build", "build/exercises", "--solved", ""] + (["--units"] if units else [])
        start = time.monotonic()
        run = subprocess.run(command, cwd=copy, capture_output=True, text=True)
        return mine, units, run.stdout + run.stderr, time.monotonic() - start

    def run_rounds(groups):
        with ThreadPoolExecutor(lanes) as pool:
            # Lane k takes rounds k, k + lanes, ...: each lane's rounds run one after another.
            jobs = [pool.submit(lambda k=k: [grade(k, g) for g in groups[k::lanes]]) for k in range(lanes)]
            results = {}
            for k, job in enumerate(jobs):
                for g, r in zip(groups[k::lanes], job.result()):
                    results[id(g)] = r
        return results

    def judge(v, group, out):
        """The checks of one variant, its row, and the exercises its lines ran; checks None
        when another body of its round hides what its own did (another wrong body, whether its
        failure is named; another correct one of its chapter, which of them cost the full
        marks): then it is graded again (the exercises None when it must be alone)."""
        s = score(out, v.chapter)
        if s is None:
            return [(False, f"{v.name}: no scorecard row for ch{v.chapter}:\n{out}")], "", None
        unit_ok, unit_total, g_ok, g_total = s
        full = unit_ok == unit_total and (g_ok is None or g_ok == g_total)
        lines = [l for l in out.splitlines() if l.startswith(f"  ch{v.chapter} ")]
        row = f"ch{v.chapter} {unit_ok} of {unit_total}" + ("" if g_ok is None else f", images {g_ok} of {g_total}")
        row += f"; {lines[0].strip()[:160]}" if lines else ""
        checks = [(unit_total == totals[v.chapter],
                   f"{v.name}: the denominator is {unit_total}; tests/test_ch{v.chapter}.cpp has {totals[v.chapter]}")]
        # A failure prints values: never "{?}" (a type doctest cannot print) or a pointer.
        unreadable = [l for l in lines if "{?}" in l or re.search(r"\b0x[0-9a-f]{6,}\b", l)]
        checks.append((not unreadable, f"{v.name}: a failure line prints no value:\n" + "\n".join(unreadable)))
        if v.verdict == "pass":
            if not full and any(w is not v and w.chapter == v.chapter for w in group):
                return None, row, None
            checks.append((full, f"{v.name} (a correct answer: {v.why}) did not get full marks: {row}\n" +
                           "\n".join(lines)))
            return checks, row, None
        # A line names the variant when it is about its exercise (a test named for it, or one
        # that ran it) and ran no other wrong body of this round.
        others = {w.exercise for w in group if w.verdict == "fail" and w.chapter < v.chapter}

        def ran(line):
            m = re.search(r"\(ran your exercises ([0-9. ]+)\)", line)
            return set(m[1].split()) if m else None

        def about(line):
            return bool(re.search(rf'unit test "{re.escape(v.exercise)} ', line) or v.exercise in (ran(line) or ()))

        def names(line, excluded):
            if ran(line) is None and excluded:
                return False
            return about(line) and not (ran(line) or set()) & excluded

        if others and not any(names(l, others) for l in lines):
            # What hid it: every exercise its lines ran (none known for a line that does not say).
            said = [ran(l) for l in lines if about(l)]
            return None, row, None if None in said else set().union(*said) - {v.exercise}
        checks.append((not full, f"{v.name} (wrong: {v.why}) got full marks: {row}"))
        checks.append((any(names(l, others) for l in lines),
                       f"{v.name}: no failure line names exercise {v.exercise}:\n" + "\n".join(lines)))
        if v.expect:
            checks.append((any(v.expect in l for l in lines),
                           f"{v.name}: no failure line says '{v.expect}':\n" + "\n".join(lines)))
        return checks, row, None

    def regroup(hidden):
        """Rounds for the variants graded again: a wrong one shares a round with others of
        other chapters when none of theirs is an exercise that ran in its lines (what hid it),
        nor its exercise in theirs; the rest alone."""
        out = []
        for v, ran in hidden:
            fits = [g for g in out if ran is not None and all(
                b is not None and w.chapter != v.chapter and w.exercise not in ran and v.exercise not in b
                for w, b in g)]
            if v.verdict == "fail" and fits:
                fits[0].append((v, ran))
            else:
                out.append([(v, ran)])
        return [[v for v, _ in g] for g in out]

    # Graded again: first in rounds that keep apart what hid each variant, then whatever is
    # still hidden alone, where nothing can hide it.
    groups = rounds(variants)
    for attempt in (1, 2, 3):
        results = run_rounds(groups)
        hidden = []
        for group in groups:
            mine, units, out, seconds = results[id(group)]
            print(f"-- round {', '.join(v.name for v in group)}: grade {' '.join(mine)}"
                  f"{' --units' if units else ''} ({seconds:.0f} s)")
            for v in group:
                checks, row, ran = judge(v, group, out)
                if checks is None:
                    hidden.append((v, ran))
                    print(f"   {v.name} ({v.verdict}): {row}; graded again: another body of this round hides what"
                          " its own did")
                    continue
                for ok, what in checks:
                    check(ok, what)
                print(f"   {v.name} ({v.verdict}): {row}")
        if not hidden:
            break
        groups = regroup(hidden) if attempt == 1 else [[v] for v, _ in hidden]
    finish(f"fairness session ({len(variants)} variants)")


if __name__ == "__main__":
    main()
