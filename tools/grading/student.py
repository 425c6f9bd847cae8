"""./lab grade: a student's own grade, in their own checkout (tools/grade is its command line).

Builds what the chapters need in BUILD (build/exercises), each chapter's exercise file on its own
(build.py: one that does not compile costs its chapter only), runs each chapter's unit tests
through the verdict channel (units.py) and its golden images (golden.py), and prints the
scorecard (tools/grade_report.py). A chapter is graded again only when something it is graded on
changed: its two programs (test_chNN, chNN, reproducibly linked: a program of chapter NN links
the exercises of chapters 01..NN and the reference ones after), the image tools, its references,
its scene files, the tests' data or the grader. Otherwise its last record is shown, "cached".
"""
import argparse
import hashlib
import json
import os
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from . import build, chapter, golden, sandbox
from .settings import ROOT, setting

GRADER_FILES = ["tests/CMakeLists.txt", "tools/settings.cmake", "tools/grade", "tools/grade_report.py"]


def fail(message, code=2):
    print(f"grade: {message}", file=sys.stderr)
    sys.exit(code)


def parse_args(argv):
    released = setting("RTLAB_RELEASED")
    parser = argparse.ArgumentParser(prog="tools/grade", add_help=False)
    parser.add_argument("chapters", nargs="*")
    parser.add_argument("--solved")
    parser.add_argument("--units", action="store_true")
    parser.add_argument("--expect")
    parser.add_argument("--build", default="build/exercises")
    parser.add_argument("-h", "--help", action="store_true")
    args, unknown = parser.parse_known_args(argv)
    if args.help:
        print(sys.modules["__main__"].__doc__ or __doc__)
        sys.exit(0)
    if unknown:
        fail(f"unknown argument '{unknown[0]}'\nusage: tools/grade [NN ...] [--solved \"01;02\"] [--units] "
             "[--expect none|all] [--build DIR]")
    chosen = []
    for word in args.chapters:
        if not re.fullmatch(r"\d{1,2}", word) or f"{int(word):02d}" not in released:
            fail(f"'{word}' is not a chapter (chapters: {' '.join(released)})")
        chosen.append(f"{int(word):02d}")
    args.chapters = [ch for ch in released if ch in chosen] if chosen else released
    if args.expect not in (None, "none", "all"):
        fail(f"--expect takes none or all, not '{args.expect}'")
    if args.solved is not None:
        # Two-digit chapters that exist, separated by ';', no empty item; sorted, once each
        # ("06;02;06" is "02;06"). CMake checks the same rules (CMakeLists.txt).
        items = args.solved.split(";") if args.solved else []
        bad = "an empty item" if re.search(r"(^;|;;|;$)", args.solved) else ""
        for item in items:
            if item and item not in released:
                bad = f"'{item}' is not a chapter"
        if bad:
            fail(f"--solved \"{args.solved}\": {bad}: give two-digit chapters separated by ';', e.g. \"01;02\" "
                 f"(chapters: {' '.join(released)})")
        args.solved = ";".join(sorted(set(i for i in items if i)))
    args.build = Path(args.build)
    return args


def cached(build_dir, name):
    try:
        for line in (build_dir / "CMakeCache.txt").read_text().splitlines():
            if line.startswith(name + ":"):
                return line.split("=", 1)[1]
    except OSError:
        pass
    return None


def configure(build_dir, solved, stand_in):
    """Configures when there is no build yet or a choice changed; else ninja re-runs CMake
    itself when a CMakeLists.txt changed."""
    if cached(build_dir, "CMAKE_GENERATOR") not in (None, "Ninja"):  # an older lab's Makefiles
        (build_dir / "CMakeCache.txt").unlink()
    wanted = {"RTLAB_STAND_IN": stand_in}
    if solved is not None:
        wanted["RTLAB_SOLVED"] = solved
    if (build_dir / "CMakeCache.txt").exists() and all(cached(build_dir, k) == v for k, v in wanted.items()):
        return
    command = ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
               "-DRTLAB_TRACK=exercises", "-DRTLAB_BENCH=OFF", "-DRTLAB_IPO=OFF"]
    command += [f"-D{k}={v}" for k, v in wanted.items()]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        block = re.search(r"CMake Error.*?\n(.*?)(\n\n|\Z)", result.stdout + result.stderr, re.S)
        msg = " ".join((block.group(1) if block else "").split())
        fail(f"configuring {build_dir} failed: {msg or 'see cmake -S . -B ' + str(build_dir)}")


def key_of(build_dir, ch, units):
    """What a chapter's result depends on, hashed; the programs are linked reproducibly."""
    files = [build_dir / "bin" / f"test_ch{ch}"]
    if not units:
        files += [build_dir / "bin" / f"ch{ch}", build_dir / "bin" / "rtlab-diff", build_dir / "bin" / "rtlab-stat"]
    folders = [ROOT / "tests" / "golden" / f"ch{ch}", *ROOT.glob(f"chapters/ch{ch}_*"), ROOT / "tests" / "data",
               ROOT / "tools" / "grading"]
    for folder in folders:
        files += sorted(p for p in folder.rglob("*") if p.is_file() and "__pycache__" not in p.parts)
    files += [ROOT / f for f in GRADER_FILES]
    digest = hashlib.sha256()
    for path in files:
        digest.update(str(path.relative_to(ROOT) if path.is_relative_to(ROOT) else path.name).encode())
        try:
            digest.update(path.read_bytes())
        except OSError:
            digest.update(b"(missing)")
    return digest.hexdigest()


def main(argv):
    args = parse_args(argv)
    build_dir = args.build if args.build.is_absolute() else ROOT / args.build
    jobs = os.cpu_count() or 1
    previous_stand_in = cached(build_dir, "RTLAB_STAND_IN") or ""
    configure(build_dir, args.solved, previous_stand_in)
    solved = (cached(build_dir, "RTLAB_SOLVED") or "").split(";")
    solved = [ch for ch in solved if ch]
    print(f"grade: {args.build}, chapters taken from solutions/: {' '.join(solved) or 'none'}; grading: "
          f"{' '.join(args.chapters)}", flush=True)

    # Each exercise file the graded chapters link, on its own; one that fails stands in with the
    # reference's bodies for the programs of later chapters (RTLAB_STAND_IN).
    last = max(args.chapters)
    released = setting("RTLAB_RELEASED")
    mine = [ch for ch in released if ch <= last and ch not in solved]
    failed, warnings = build.compile_exercises(build_dir, mine, jobs)
    stand_in = ";".join(sorted(failed))
    configure(build_dir, None, stand_in)
    targets = ["rtlab-diff", "rtlab-stat", "rtlab-genex"]
    for ch in args.chapters:
        targets.append(f"test_ch{ch}")
        if not args.units:
            targets.append(f"ch{ch}")
    result = subprocess.run(["cmake", "--build", str(build_dir), "-j", str(jobs), "--target", *targets],
                            capture_output=True, text=True)
    if result.returncode != 0:
        errors = [line for line in (result.stdout + result.stderr).splitlines() if "error" in line][:20]
        print("\n".join(errors), file=sys.stderr)
        fail("the build failed (first errors above)", 1)

    state = build_dir / "grade" / ("units" if args.units else "")
    state.mkdir(parents=True, exist_ok=True)
    # Warnings of a file compiled now replace its old ones; a file not compiled keeps them.
    for ch, lines in warnings.items():
        (state / f"ch{ch}.warnings").write_text("".join(f"  ch{ch}: {line}\n" for line in lines))

    # A chapter taken from solutions/ whose exercise file has bodies of the student's: they are
    # not graded, which a value stored long ago would otherwise hide.
    written = subprocess.run([str(build_dir / "bin" / "rtlab-genex"), str(ROOT / "solutions"),
                              str(ROOT / "exercises"), "--written"], capture_output=True, text=True).stdout
    for line in written.splitlines():
        file, _, bodies = line.partition(": ")
        m = re.search(r"/ch(\d\d)_", file)
        if m and m.group(1) in solved:
            rest = ";".join(c for c in solved if c != m.group(1))
            print(f"grade: warning: chapter {m.group(1)} is taken from solutions/, so your bodies of {bodies} in "
                  f"exercises/{Path(file).name} are not graded; to grade them: ./lab grade --solved \"{rest}\"")

    keys = {ch: key_of(build_dir, ch, args.units) + stand_in for ch in args.chapters}
    to_run = [ch for ch in args.chapters
              if not ((state / f"ch{ch}.key").exists() and (state / f"ch{ch}.key").read_text().strip() == keys[ch]
                      and (state / f"ch{ch}.json").exists())]
    runner = sandbox.Plain(state / "scratch")
    runner.open()
    judge = golden.Judge(build_dir / "bin" / "rtlab-diff", build_dir / "bin" / "rtlab-stat")
    grade_chapters(to_run, failed, runner, judge, build_dir / "bin", state, args.units)

    for ch in args.chapters:  # the compiler's words, current or kept
        path = state / f"ch{ch}.warnings"
        record_path = state / f"ch{ch}.json"
        rec = json.loads(record_path.read_text())
        rec["warnings"] = path.read_text().splitlines() if path.exists() and ch not in failed else []
        record_path.write_text(json.dumps(rec, indent=1) + "\n")
    for ch in to_run:
        (state / f"ch{ch}.key").write_text(keys[ch] + "\n")
    if failed:
        later = [ch for ch in args.chapters if ch > min(failed)]
        print(f"grade: chapter{'s' if len(failed) > 1 else ''} {' '.join(sorted(failed))} did not compile: "
              f"{'the programs of ' + ' '.join(later) + ' took their bodies from solutions/ to be graded' if later else 'nothing else was affected'}")
    report = [sys.executable, str(ROOT / "tools" / "grade_report.py"), "--build", str(args.build), "--state",
              str(state), "--report", str(ROOT / "out" / "grade"), "--chapters", " ".join(args.chapters),
              "--solved", " ".join(solved)]
    for ch in to_run:
        report += ["--graded", ch]
    if args.units:
        report.append("--units")
    if args.expect:
        report += ["--expect", args.expect]
    # exec discards what Python has not written yet: when the output is a pipe or a file, the
    # warnings above would be lost (./lab distro-check found it: the student session's check
    # of the --solved warning failed wherever PYTHONUNBUFFERED was not set).
    sys.stdout.flush()
    sys.stderr.flush()
    os.execv(sys.executable, report)


def grade_chapters(to_run, failed, runner, judge, bin_dir, state, units_only):
    """Every job of every chapter to run, spread over the cores, the slowest chapters first."""
    order = sorted(to_run, key=lambda ch: -float((state / f"ch{ch}.seconds").read_text())
                   if (state / f"ch{ch}.seconds").exists() else 0)
    work = {ch: state / "work" / f"ch{ch}" for ch in order}
    plan = []
    for ch in order:
        if ch in failed:
            continue
        programs = {"test": bin_dir / f"test_ch{ch}", "chapter": bin_dir / f"ch{ch}"}
        plan += [(ch, job) for job in chapter.jobs(ch, runner, judge, programs, work[ch], None, units_only)]
    parts = {ch: [] for ch in order}
    seconds = {ch: 0.0 for ch in order}

    def timed(item):
        began = time.monotonic()
        part = item[1]()
        return item[0], part, time.monotonic() - began

    with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        for ch, part, took in pool.map(timed, plan):
            parts[ch].append(part)
            seconds[ch] += took
    for ch in order:
        (state / f"ch{ch}.seconds").write_text(f"{seconds[ch]:.1f}\n")
    for ch in order:
        if ch in failed:
            cases = chapter_cases(runner, bin_dir, ch, state)
            rec = chapter.not_compiled(ch, cases, failed[ch], units_only)
        else:
            rec = chapter.record(ch, parts[ch], units_only, state / "img" / f"ch{ch}")
        (state / f"ch{ch}.json").write_text(json.dumps(rec, indent=1) + "\n")


def chapter_cases(runner, bin_dir, ch, state):
    """A chapter whose file did not compile still has its denominator: its test program, linked
    with the reference's bodies in their place, lists its tests."""
    from . import units
    work = state / "work" / f"ch{ch}"
    work.mkdir(parents=True, exist_ok=True)
    cases, _ = units.list_cases(runner, bin_dir / f"test_ch{ch}", work)
    return cases or []
