#!/usr/bin/env python3
"""One golden-image test: a chapter program renders a scene, and the lab's own tools judge the
picture against the reference (book §0.7, §14.6). The one implementation, for ./lab test's
ctest tests, ./lab grade and ./lab grade-class alike.

The render runs through a Runner (sandbox.py): in a class grade, inside the student's sandbox,
which sees neither the references nor the judging tools. What it wrote is then taken out
without following links (a student's program could leave a link to the reference where its
picture should be) and judged outside, by rtlab-diff (a plain picture, within
RTLAB_GOLDEN_TOLERANCE) or rtlab-stat (a noisy chapter: the average of RTLAB_STAT_SEEDS renders,
a t-test per pixel-channel). A render that fails, crashes, hangs or leaves a NaN or an infinite
sample fails the test, with the reason.

As a ctest test:
  golden.py --program chNN --scene S --out DIR --diff rtlab-diff --reference REF.png
  golden.py --program chNN --scene S --out DIR --stat rtlab-stat --mean M.pfm --var V.pfm
            [--expect pass|fail] [--groups G --first-seed K] [-- EXTRA RENDER ARGS]
"""
import argparse
import json
import os
import shutil
import stat
import subprocess
import sys
from pathlib import Path

if __package__ in (None, ""):
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
    __package__ = "grading"

from . import sandbox  # noqa: E402
from .settings import settings  # noqa: E402

# The golden sizes render in well under a second (a second or two under ASan, whose ctest
# tests give --seconds 60); a render past this is an exercise that never returns.
RENDER_SECONDS = 20
LARGEST_PICTURE = 64 << 20


def take(scratch, path, into):
    """Copies the file a student's process wrote at `path` (under `scratch`) to `into`, following
    no link on the way; False (and nothing copied) when it is not a plain file of a sane size."""
    scratch, path = Path(scratch), Path(path)
    try:
        parts = path.relative_to(scratch).parts
    except ValueError:
        return False
    fd = os.open(scratch, os.O_RDONLY | os.O_DIRECTORY)
    try:
        for i, part in enumerate(parts):
            last = i == len(parts) - 1
            flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | (0 if last else os.O_DIRECTORY)
            try:
                next_fd = os.open(part, flags, dir_fd=fd)
            except OSError:
                return False
            os.close(fd)
            fd = next_fd
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode) or info.st_size > LARGEST_PICTURE:
            return False
        with os.fdopen(os.dup(fd), "rb") as source, open(into, "wb") as target:
            shutil.copyfileobj(source, target)
        return True
    finally:
        os.close(fd)


class Judge:
    """The trusted side: the tools and references, never seen by the student's processes."""

    def __init__(self, diff=None, stat_tool=None):
        self.diff = diff
        self.stat = stat_tool


def render(runner, program, scene, args, output, work, log_name, budget=None):
    """Renders into the runner's scratch and takes the picture out into `output`. Returns
    (reason, exercises): reason empty when the render succeeded."""
    inside = Path(runner.scratch) / f"render-{output.name}"
    log = work / log_name
    outcome = sandbox.run(runner, [str(program), "--scene", scene, *args, "-o", str(inside), "--stats"],
                          cwd=runner.scratch, stdout=log, seconds=RENDER_SECONDS, budget=budget)
    text = log.read_bytes()[:1 << 20].decode("utf-8", "replace") if log.exists() else ""
    stats = None
    for line in reversed(text.splitlines()):
        if line.startswith("{"):
            try:
                stats = json.loads(line)
            except ValueError:
                pass
            break
    exercises = stats.get("your_exercises", "") if isinstance(stats, dict) else ""
    exercises = exercises if isinstance(exercises, str) else ""
    if outcome.stopped:
        if budget is not None and outcome.stopped == budget.reason():
            return outcome.stopped, exercises
        return f"did not finish in {RENDER_SECONDS:g} s (an exercise that never returns?)", exercises
    if outcome.code != 0:
        last = next((line for line in reversed(text.splitlines()) if line.strip()), "")
        if outcome.code < 0 or not last:
            last = outcome.describe()
        return last[:300], exercises
    taken = take(runner.scratch, inside, output)
    try:
        inside.unlink()  # the scratch folder has a size: keep it for what is still to come
    except OSError:
        pass
    if not taken:
        return "wrote no picture", exercises
    nonfinite = stats.get("nonfinite_samples") if isinstance(stats, dict) else None
    if nonfinite != 0:
        return (f"{nonfinite} samples were NaN or infinite" if isinstance(nonfinite, int)
                else "printed no --stats line"), exercises
    return "", exercises


def plain(runner, judge, program, scene, reference, out, extra=(), budget=None):
    """A picture against its reference within the tolerance. Returns the row the report shows."""
    args, tolerance = settings("RTLAB_GOLDEN_ARGS", "RTLAB_GOLDEN_TOLERANCE")
    out.mkdir(parents=True, exist_ok=True)
    yours, heatmap = out / f"{scene}.png", out / f"{scene}-heatmap.png"
    for stale in (yours, heatmap):
        stale.unlink(missing_ok=True)
    row = {"scene": scene, "passed": False, "reference": str(reference), "yours": None, "heatmap": None}
    why, exercises = render(runner, program, scene, [*args, *extra], yours, out, f"{scene}.render.log", budget)
    row["exercises"] = exercises
    if why:
        row.update(score="not rendered", reason=f"did not render: {why}")
        return row
    result = subprocess.run([str(judge.diff), str(reference), str(yours), *tolerance, "--heatmap", str(heatmap)],
                            capture_output=True, text=True)
    report = (result.stdout + result.stderr).strip()
    row.update(score=report, yours=str(yours), passed=result.returncode == 0)
    if result.returncode != 0:
        row["heatmap"] = str(heatmap) if heatmap.exists() else None
        row["reason"] = "differs past the tolerance: " + report.replace("\n", " ")[:400]
    return row


def statistical(runner, judge, program, scene, mean, var, out, extra=(), groups=1, first_seed=None, budget=None):
    """The average of the seeds' renders tested against the reference's mean (book §14.6); with
    groups > 1, that many groups of seeds, and the row counts the groups that failed."""
    args, seeds, tolerance = settings("RTLAB_STAT_ARGS", "RTLAB_STAT_SEEDS", "RTLAB_STAT_TOLERANCE")
    first_seed = int(seeds[0]) if first_seed is None else first_seed
    out.mkdir(parents=True, exist_ok=True)
    names = {k: out / f"{scene}{k}" for k in ("-yours.png", "-map.png", "-reference.png", ".json")}
    for stale in names.values():
        stale.unlink(missing_ok=True)
    row = {"scene": scene, "passed": False, "reference": str(names["-reference.png"]), "yours": None,
           "heatmap": None, "failed_groups": 0}
    # The reference's picture first, so the report shows it even when no render succeeds.
    subprocess.run([str(judge.stat), "test", str(mean), str(var), str(mean), str(mean), "--reference-image",
                    str(names["-reference.png"])], capture_output=True, check=True)
    reports = []
    for group in range(groups):
        images = []
        for k in range(len(seeds)):
            seed = first_seed + group * len(seeds) + k
            image = out / f"{scene}-{seed}.pfm"
            why, exercises = render(runner, program, scene, [*args, *extra, "--seed", str(seed)], image, out,
                                    f"{scene}.render.log", budget)
            row["exercises"] = exercises
            if why:
                for done in images:
                    done.unlink(missing_ok=True)
                row.update(score="not rendered", reason=f"did not render: {why}")
                return row
            images.append(image)
        result = subprocess.run([str(judge.stat), "test", str(mean), str(var), *map(str, images), *tolerance,
                                 "--map", str(names["-map.png"]), "--json", str(names[".json"]),
                                 "--average", str(names["-yours.png"]),
                                 "--reference-image", str(names["-reference.png"])], capture_output=True, text=True)
        for image in images:
            image.unlink(missing_ok=True)
        if result.returncode not in (0, 1):
            raise RuntimeError(f"rtlab-stat failed on {scene}: {result.stderr.strip()}")
        reports.append((result.stdout + result.stderr).strip())
        row["failed_groups"] += result.returncode == 1
    row.update(score=reports[-1], yours=str(names["-yours.png"]), passed=row["failed_groups"] == 0)
    if not row["passed"]:
        row["heatmap"] = str(names["-map.png"])
        row["reason"] = "differs past the tolerance: " + reports[-1].replace("\n", " ")[:400]
    return row


def set_seconds(seconds):
    global RENDER_SECONDS
    RENDER_SECONDS = seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--program", type=Path, required=True)
    parser.add_argument("--scene", required=True)
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--diff", type=Path)
    parser.add_argument("--reference", type=Path)
    parser.add_argument("--stat", type=Path)
    parser.add_argument("--mean", type=Path)
    parser.add_argument("--var", type=Path)
    parser.add_argument("--expect", choices=["pass", "fail"], default="pass")
    parser.add_argument("--groups", type=int, default=1)
    parser.add_argument("--first-seed", type=int)
    parser.add_argument("--max-false-alarms", type=int, default=1)
    parser.add_argument("--seconds", type=float, default=RENDER_SECONDS, help="the longest a render may take")
    parser.add_argument("extra", nargs="*")
    a = parser.parse_args()
    set_seconds(a.seconds)
    runner = sandbox.Plain(a.out / "scratch")
    runner.open()
    judge = Judge(a.diff, a.stat)
    if a.reference:
        row = plain(runner, judge, a.program, a.scene, a.reference, a.out, a.extra)
    else:
        row = statistical(runner, judge, a.program, a.scene, a.mean, a.var, a.out, a.extra, a.groups, a.first_seed)
    print(row["score"])
    if row["score"] == "not rendered":
        sys.exit(f"{a.scene}: {row['reason']}")
    if a.groups > 1:
        print(f"{row['failed_groups']} of {a.groups} correct renders failed (allowed: {a.max_false_alarms})")
        if row["failed_groups"] > a.max_false_alarms:
            sys.exit(f"false alarms: {row['failed_groups']} of {a.groups} correct renders of {a.scene} failed")
    elif a.expect == "fail" and row["passed"]:
        sys.exit(f"{a.scene} with {' '.join(a.extra)} passed: the test missed a planted mistake")
    elif a.expect == "pass" and not row["passed"]:
        sys.exit(f"{a.scene}: {row['reason']}; map: {row.get('heatmap')}")


if __name__ == "__main__":
    main()
