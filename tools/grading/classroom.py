"""./lab grade-class SUBMISSIONS --out DIR [--chapters 01-08] [--jobs N] [--points FILE] [--no-sandbox]

Grades a whole class against the instructor's own lab: its tests, golden images, CMake files
and grader, never a student's. SUBMISSIONS holds one entry per student (a folder, a git
checkout, a .zip or a .tar.gz with the handout's exercises/ inside); the entry's name is the
student's. For each student, only the exercise regions of their files are taken (submission.py),
compiled, checked (symbols.py), linked with the class's build (classbuild.py) and run, each step
in the student's own sandbox (sandbox.py); their tests' verdicts come from the harness's channel
(units.py) and their pictures are judged outside the sandbox (golden.py).

DIR gets gradebook.csv (a row per student), and per student STUDENT/scorecard.txt,
STUDENT/report.html and STUDENT/results.json (Gradescope's format). Points: every chapter 10,
every check in a chapter an equal share, unless --points names a JSON table {"02": 20, ...}.
"""
import argparse
import csv
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from types import SimpleNamespace

from . import chapter, golden, sandbox, submission, symbols, units
from .classbuild import ClassBuild
from .settings import ROOT, setting

sys.path.insert(0, str(ROOT / "tools"))
import grade_report  # noqa: E402  (the scorecard and the HTML report, as ./lab grade shows them)

FIRST_UID = 61000  # each student's processes run as FIRST_UID + their slot
# A student's programs may run, in all, this many times as long as the reference's did when the
# class's run graded it first (and at least MIN_BUDGET s): an exercise that never returns costs
# that much, not a minute for every test and render that goes through it.
BUDGET_FACTOR, MIN_BUDGET = 3, 60


def chapters_arg(text, released, prog="grade-class"):
    """'01-08', '02;05', '3,4' -> ['01', ...] within the released chapters; a refusal names `prog`."""
    out = []
    for part in re.split(r"[;, ]+", text.strip()):
        m = re.fullmatch(r"(\d{1,2})(?:-(\d{1,2}))?", part)
        if not m:
            raise SystemExit(f"{prog}: --chapters '{text}': give chapters like 01-08 or 02,05")
        first, last = int(m.group(1)), int(m.group(2) or m.group(1))
        for n in range(first, last + 1):
            ch = f"{n:02d}"
            if ch not in released:
                raise SystemExit(f"{prog}: --chapters '{text}': {ch} is not a chapter "
                                 f"(chapters: {' '.join(released)})")
            if ch not in out:
                out.append(ch)
    return sorted(out)


def folder_name(name, taken):
    """A folder name for the student that no name can turn into a path or markup."""
    safe = re.sub(r"[^A-Za-z0-9._@-]", "_", name).strip("._") or "student"
    safe, n = safe[:60], 2
    base = safe
    while safe.lower() in taken:
        safe, n = f"{base}-{n}", n + 1
    taken.add(safe.lower())
    return safe


class Points:
    def __init__(self, path, chapters):
        table = {}
        if path:
            try:
                table = json.loads(Path(path).read_text())
                assert isinstance(table, dict) and all(isinstance(v, (int, float)) and v >= 0 for v in table.values())
            except (OSError, ValueError, AssertionError):
                raise SystemExit(f"grade-class: --points {path}: give a JSON object of chapter to points, "
                                 'e.g. {"01": 10, "02": 20}')
        self.chapter = {ch: float(table.get(ch, 10)) for ch in chapters}

    def of(self, ch, record):
        """(points, each check's share) of a chapter's record."""
        checks = record["unit_total"] + record["golden_total"]
        share = self.chapter[ch] / checks if checks else 0.0
        return share * (record["unit_passed"] + record["golden_passed"]), share


class Student:
    def __init__(self, entry, slot, folder):
        self.entry = entry
        self.name = submission.display_name(entry)
        self.slot = slot
        self.folder = folder


class Grader:
    def __init__(self, args):
        self.args = args
        self.out = args.out
        self.work = self.out / ".work"
        self.cache = self.out / ".cache"
        self.lock = threading.Lock()

    def prepare(self):
        # A run stopped by force may have left its students' scratch folders mounted.
        for line in Path("/proc/mounts").read_text().splitlines():
            where = line.split()[1].replace("\\040", " ")
            m = re.match(r"^/tmp/rtlab-class-(\d+)-", where)
            stale = m and not Path(f"/proc/{m.group(1)}").exists()
            if where.startswith(str(self.work) + "/") or stale:
                subprocess.run(["umount", "--lazy", where], check=False)
        shutil.rmtree(self.work, ignore_errors=True)
        # The students' scratch folders, where every user id can reach them (a sandbox runs as
        # the student, and --out may be anywhere, in a folder only its owner may enter).
        self.scratch_root = Path(tempfile.mkdtemp(prefix=f"rtlab-class-{os.getpid()}-", dir="/tmp"))
        os.chmod(self.scratch_root, 0o755)
        shutil.rmtree(self.cache, ignore_errors=True)
        for d in (self.work, self.cache / "obj", self.cache / "bin"):
            d.mkdir(parents=True)
        self.build = ClassBuild(self.args.chapters, self.args.jobs)
        self.build.make()
        trusted = sandbox.Plain(self.work / "trusted")
        trusted.open()
        self.cases = self.build.cases(trusted, self.work)
        self.reference, self.others = self.build.symbol_tables()
        self.judge = golden.Judge(self.build.bin / "rtlab-diff", self.build.bin / "rtlab-stat")
        self.genex = self.build.bin / "rtlab-genex"
        self.solutions = {ch: next((ROOT / "solutions").glob(f"ch{ch}_*.cpp")) for ch in self.args.chapters}

    # The student's three sandboxes: what each step may see.
    def runner(self, student, scratch, step):
        if not self.args.sandbox:
            return sandbox.Plain(scratch)
        # A compile sees the headers and the chapters' precompiled headers, never an object; a
        # link, the class's objects and libraries (the linker runs no code of the student's); a
        # run, the chapters' scene files only: no compiler input, no reference, no object.
        headers = [self.build.dir / "CMakeFiles" / f"rtlab_exercise_{ch}.dir" for ch in self.args.chapters]
        read_only = {"compile": [ROOT / "common", self.build.dir / "layers", *headers],
                     "link": [ROOT / "common", self.build.dir],
                     "run": [ROOT / "chapters"]}[step]
        # A build writes objects and programs of a few megabytes; a run, a picture and its
        # output: a flood of output stops at that size (SIGXFSZ).
        limits = sandbox.Limits(file_bytes=(64 << 20) if step != "run" else (8 << 20))
        return sandbox.Sandbox(scratch, FIRST_UID + student.slot, [p for p in read_only if p.exists()], limits)

    def compile_all(self, runner, files, log):
        """Compiles chapters' files ({chapter: (source, object)}) in one start of the sandbox, each
        once: an object a student with the very same file had is taken from the class's cache.
        Returns {chapter: (error or None, warnings)}."""
        from .build import diagnostics
        todo, texts, keys = [], {}, {}
        for ch, (source, obj) in files.items():
            spec = self.build.compile[ch]
            keys[ch] = hashlib.sha256(source.read_bytes() + "\0".join(spec["argv"]).encode()).hexdigest()
            cached, said = self.cache / "obj" / f"{keys[ch]}.o", self.cache / "obj" / f"{keys[ch]}.txt"
            if cached.exists() and said.exists():
                shutil.copyfile(cached, obj)
                texts[ch] = (True, said.read_text())
            else:
                todo.append(ch)
        commands = [[w.replace("{SOURCE}", str(files[ch][0])).replace("{OUTPUT}", str(files[ch][1]))
                     for w in self.build.compile[ch]["argv"]] for ch in todo]
        cwd = self.build.compile[todo[0]]["cwd"] if todo else "/"
        for ch, (outcome, text) in zip(todo, sandbox.run_batch(runner, commands, cwd=cwd, seconds_each=120, log=log)):
            obj = files[ch][1]
            ok = outcome.code == 0 and golden.take(runner.scratch, obj, str(obj) + ".taken")
            if outcome.stopped:
                text += f"\nexercises/{self.build.compile[ch]['file']}: error: the compiler {outcome.stopped}"
            if ok:
                os.replace(str(obj) + ".taken", obj)
                # Stored now, before any code of the student's has run: nothing can change it.
                shutil.copyfile(obj, self.cache / "obj" / f"{keys[ch]}.o")
                (self.cache / "obj" / f"{keys[ch]}.txt").write_text(text)
            texts[ch] = (ok, text)
        out = {}
        for ch, (ok, text) in texts.items():
            spec = self.build.compile[ch]
            found = diagnostics(text.replace(str(files[ch][0]), f"exercises/{spec['file']}")).get(ch, {})
            if ok:
                out[ch] = (None, found.get("warnings", []))
            else:
                out[ch] = (found.get("error") or (text.strip().splitlines() or ["the compiler failed"])[-1][:300], [])
        return out

    def link_all(self, runner, programs, objects, log):
        """Links programs ({name: output path}) in one start of the sandbox, from the class's
        build and the student's objects ({chapter: path}); a program the very same objects made
        for another student is taken from the class's cache. Returns {name: first error or None}."""
        todo, out, keys = [], {}, {}
        for program, output in programs.items():
            digest = hashlib.sha256("\0".join(self.build.link[program]).encode())
            for ch in sorted(objects):
                digest.update(ch.encode() + Path(objects[ch]).read_bytes())
            keys[program] = self.cache / "bin" / digest.hexdigest()
            if keys[program].exists():
                shutil.copyfile(keys[program], output)
                os.chmod(output, 0o755)
                out[program] = None
            else:
                todo.append(program)
        commands = []
        for program in todo:
            argv = []
            for word in self.build.link[program]:
                m = re.fullmatch(r"\{EXERCISE_(\d\d)\}", word)
                argv.append(str(objects[m.group(1)]) if m else word.replace("{OUTPUT}", str(programs[program])))
            commands.append(argv)
        for program, (outcome, text) in zip(todo, sandbox.run_batch(runner, commands, cwd=self.build.dir,
                                                                      seconds_each=120, log=log)):
            if outcome.code != 0:
                first = next((line for line in text.splitlines() if "error" in line or "undefined" in line), "")
                out[program] = (first or outcome.describe())[:300]
            else:
                shutil.copyfile(programs[program], keys[program])
                out[program] = None
        return out

    def grade(self, student, budget=None, report=True):
        """One student: their records, their report files and their gradebook row (or, with
        report=False, their records and where their time went)."""
        began = time.monotonic()
        chapters = self.args.chapters
        mine = self.work / student.folder
        staged, sources, scratch = mine / "staged", mine / "src", self.scratch_root / student.folder
        state = mine / "state"
        for d in (staged, sources, state):
            d.mkdir(parents=True)
        wanted = {self.build.compile[ch]["file"]: ch for ch in chapters}
        reasons = {}  # chapter -> why it scores 0 before anything runs
        try:
            found = submission.collect(student.entry, set(wanted), staged)
        except submission.Refused as e:
            found = {}
            for ch in chapters:
                reasons[ch] = f"the submission cannot be read: {e}"
        for name, ch in wanted.items():
            if ch in reasons:
                continue
            if name not in found:
                reasons[ch] = f"exercises/{name} is missing (renamed, or not handed in?)"
            elif found[name]:
                reasons[ch] = found[name]
            else:
                why = submission.transplant(self.genex, self.solutions[ch], staged / name, sources / name)
                if why:
                    reasons[ch] = why

        objects, warnings = {}, {}
        records = {}
        clock = {"take": time.monotonic() - began}
        # Three views of one scratch folder (mounted once): each step sees only what it needs.
        setups = {step: self.runner(student, scratch, step) for step in ("compile", "link", "run")}
        setups["compile"].open()
        try:
            files = {}
            for ch in chapters:
                if ch in reasons:
                    continue
                name = self.build.compile[ch]["file"]
                source = scratch / name
                shutil.copyfile(sources / name, source)
                files[ch] = (source, scratch / f"ch{ch}.o")
            for ch, (error, said) in self.compile_all(setups["compile"], files, mine / "compile.log").items():
                if error:
                    reasons[ch] = f"did not compile: {error}"
                    continue
                bad = symbols.problems(files[ch][1], self.reference[ch], self.others)
                if bad:
                    reasons[ch] = "refused before linking: the object " + "; ".join(bad)
                    continue
                objects[ch], warnings[ch] = files[ch][1], said
            clock["compile"] = time.monotonic() - began - sum(clock.values())
            # Programs of a chapter link the student's exercises up to it; a chapter that
            # failed stands in with the reference's bodies, so later chapters are still graded.
            for ch in [c for c in setting("RTLAB_CHAPTERS") if c not in chapters or c in reasons]:
                objects.setdefault(ch, self.build.solution_object(ch))
            bin_dir = scratch / "bin"
            bin_dir.mkdir(exist_ok=True)
            if self.args.sandbox:
                os.chown(bin_dir, FIRST_UID + student.slot, FIRST_UID + student.slot)
            wanted = {f"{kind}{ch}": bin_dir / f"{kind}{ch}" for ch in chapters if ch not in reasons
                      for kind in ("test_ch", "ch")}
            linked = self.link_all(setups["link"], wanted, objects, mine / "link.log")
            programs = {}
            for ch in chapters:
                if ch in reasons:
                    continue
                error = linked[f"test_ch{ch}"] or linked[f"ch{ch}"]
                if error:
                    reasons[ch] = f"did not link: {error}"
                else:
                    programs[ch] = {"test": wanted[f"test_ch{ch}"], "chapter": wanted[f"ch{ch}"]}
            clock["link"] = time.monotonic() - began - sum(clock.values())
            jobs = []
            for ch in chapters:
                if ch in reasons:
                    continue
                work = mine / "work" / f"ch{ch}"
                jobs += [(ch, job) for job in chapter.jobs(ch, setups["run"], self.judge, programs[ch], work,
                                                           self.cases[ch], False, budget)]
            parts = {ch: [] for ch in chapters}
            for ch, job in jobs:  # one student's jobs one after the other: students run in parallel
                parts[ch].append(job())
            clock["run"] = time.monotonic() - began - sum(clock.values())
            for ch in chapters:
                if ch in reasons:
                    records[ch] = chapter.not_compiled(ch, self.cases[ch], reasons[ch], False)
                    records[ch]["reasons"] = [f"  ch{ch}: {reasons[ch]}"]
                else:
                    records[ch] = chapter.record(ch, parts[ch], False, state / "img" / f"ch{ch}")
                    records[ch]["warnings"] = [f"  ch{ch}: {w}" for w in warnings.get(ch, [])]
                (state / f"ch{ch}.json").write_text(json.dumps(records[ch], indent=1) + "\n")
                (state / "img" / f"ch{ch}").mkdir(parents=True, exist_ok=True)
        finally:
            setups["compile"].close()
            if getattr(setups["compile"], "cpu", None) is not None:
                clock["cpu"] = setups["compile"].cpu  # the student's own processes, all of them
        # Where a student's time goes, for bench/class_grade.sh.
        (mine / "seconds.json").write_text(json.dumps({k: round(v, 3) for k, v in clock.items()}) + "\n")
        if not report:
            return records, clock
        return self.write_student(student, records, state, time.monotonic() - began)

    def calibrate(self, slot):
        """The reference's own bodies, graded first as a student would be: they must get full
        marks (else the class's build is broken, and no student's grade would mean anything),
        and the time their programs take sets every student's budget."""
        entry = self.work / "reference-submission"
        (entry / "exercises").mkdir(parents=True)
        for ch in self.args.chapters:
            source = self.solutions[ch]
            why = submission.transplant(self.genex, source, source, entry / "exercises" / self.build.compile[ch]["file"])
            if why:
                raise SystemExit(f"grade-class: the reference's own {source.name}: {why}")
        records, clock = self.grade(Student(entry, slot, "reference-of-the-class"), report=False)
        wrong = [line for ch in self.args.chapters for line in records[ch]["reasons"]]
        if wrong:
            raise SystemExit("grade-class: the reference's own bodies do not get full marks in this class's build, so "
                             "no student's grade would mean anything; first:\n" + "\n".join(wrong[:10]))
        return max(MIN_BUDGET, BUDGET_FACTOR * clock["run"]), clock["run"]

    def write_student(self, student, records, state, seconds):
        folder = self.out / student.folder
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
        args = SimpleNamespace(build=Path("the class's build"), state=state, report=folder,
                               chapters=" ".join(self.args.chapters), solved="", graded=self.args.chapters,
                               units=False, who=student.name)
        card, _, _ = grade_report.scorecard(args)
        card = [line for line in card if not line.startswith(("report:", "chapters taken from solutions/"))]
        header = f"{student.name} ({self.sandbox_line})"
        (folder / "scorecard.txt").write_text(header + "\n" + "\n".join(card) + "\n")
        row, tests, total, maximum = {"student": student.name, "folder": student.folder}, [], 0.0, 0.0
        for ch in self.args.chapters:
            r = records[ch]
            points, share = self.points.of(ch, r)
            row.update({f"ch{ch} units": f"{r['unit_passed']}/{r['unit_total']}",
                        f"ch{ch} golden": f"{r['golden_passed']}/{r['golden_total']}",
                        f"ch{ch} points": round(points, 2)})
            total, maximum = total + points, maximum + self.points.chapter[ch]
            for case in r["units"]:
                tests.append({"name": f"ch{ch} unit test: {case['name']}", "score": round(share * case["passed"], 4),
                              "max_score": round(share, 4), "output": case["reason"], "visibility": "visible"})
            for g in r["rows"]:
                tests.append({"name": f"ch{ch} golden image: {g['scene']}", "score": round(share * g["passed"], 4),
                              "max_score": round(share, 4), "output": g.get("reason") or g.get("score", ""),
                              "visibility": "visible"})
            if not r["units"] and not r["rows"] and r["reasons"]:
                tests.append({"name": f"ch{ch}", "score": 0, "max_score": self.points.chapter[ch],
                              "output": r["reasons"][0].strip(), "visibility": "visible"})
        row.update({"total": round(total, 2), "max": round(maximum, 2), "seconds": round(seconds, 1)})
        results = {"score": round(total, 2), "output": "\n".join(card), "visibility": "visible",
                   "stdout_visibility": "hidden", "execution_time": round(seconds, 1), "tests": tests}
        (folder / "results.json").write_text(json.dumps(results, indent=1) + "\n")
        return row

    def run(self, entries):
        self.points = Points(self.args.points, self.args.chapters)
        self.sandbox_line = (sandbox.Sandbox(self.work, FIRST_UID, []).describe() if self.args.sandbox
                             else "NO SANDBOX: --no-sandbox, for submissions you trust")
        taken = set()
        students = [Student(e, k, None) for k, e in enumerate(entries)]
        for s in students:
            s.folder = folder_name(s.name, taken)
        rows, done = [None] * len(students), [0]

        def one(k):
            s = students[k]
            try:
                rows[k] = self.grade(s, sandbox.Budget(budget_seconds))
            except Exception as e:  # a bug of the grader's: the class goes on, the row says so
                rows[k] = {"student": s.name, "folder": s.folder, "total": 0, "error": f"grader error: {e}"}
            with self.lock:
                done[0] += 1
                print(f"grade-class: [{done[0]}/{len(students)}] {self.show(s.name)}: "
                      f"{rows[k].get('total', 0):g} of {sum(self.points.chapter.values()):g} points"
                      f"{' (' + rows[k]['error'] + ')' if 'error' in rows[k] else ''}"
                      f"{'' if self.args.sandbox else '  [NO SANDBOX]'}", flush=True)

        try:
            calibrated = time.monotonic()
            budget_seconds, took = self.calibrate(len(students))
            calibrated = time.monotonic() - calibrated
            print(f"grade-class: the reference, graded first as a student: full marks, its programs ran {took:.1f} s; "
                  f"each student's may run {budget_seconds:.0f} s in all "
                  f"({BUDGET_FACTOR} × the reference's, at least {MIN_BUDGET} s)",
                  flush=True)
            started = time.monotonic()
            with ThreadPoolExecutor(max_workers=self.args.jobs) as pool:
                list(pool.map(one, range(len(students))))
        finally:
            shutil.rmtree(self.scratch_root, ignore_errors=True)
        took = time.monotonic() - started
        self.write_gradebook(rows)
        print(f"grade-class: {len(students)} students, chapters {' '.join(self.args.chapters)}: {took:.0f} s "
              f"({took * self.args.jobs / max(1, len(students)):.1f} s of machine time per student with "
              f"{self.args.jobs} at once), after {calibrated:.0f} s for the reference; gradebook "
              f"{self.out / 'gradebook.csv'}{'' if self.args.sandbox else '  [NO SANDBOX]'}")

    @staticmethod
    def show(name):
        """A name as one line of plain text on the terminal."""
        return "".join(c if c.isprintable() else "?" for c in name)[:80]

    def write_gradebook(self, rows):
        fields = ["student", "folder"]
        for ch in self.args.chapters:
            fields += [f"ch{ch} units", f"ch{ch} golden", f"ch{ch} points"]
        fields += ["total", "max", "seconds", "error"]
        with open(self.out / "gradebook.csv", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
            w.writeheader()
            for row in rows:
                safe = dict(row)
                # A spreadsheet takes a cell starting with = + - @ for a formula: never a name.
                if str(safe["student"])[:1] in "=+-@\t\r":
                    safe["student"] = "'" + safe["student"]
                w.writerow(safe)


def main(argv):
    released = setting("RTLAB_RELEASED")
    parser = argparse.ArgumentParser(prog="./lab grade-class", description=__doc__.split("\n\n")[0])
    parser.add_argument("submissions", type=Path, nargs="?")
    parser.add_argument("--out", type=Path)
    parser.add_argument("--prepare", action="store_true", help="only make the class's build (Gradescope's set-up)")
    parser.add_argument("--chapters", default=" ".join(released))
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--points")
    parser.add_argument("--no-sandbox", dest="sandbox", action="store_false")
    parser.add_argument("--seconds", type=float, help=f"the longest a test case may run (default {units.CASE_SECONDS}"
                        f" s) and a render (default {golden.RENDER_SECONDS} s)")
    args = parser.parse_args(argv)
    args.chapters = chapters_arg(args.chapters, released)
    if args.seconds is not None:
        if not 0.5 <= args.seconds <= 600:
            raise SystemExit("grade-class: --seconds takes 0.5 to 600")
        units.CASE_SECONDS = golden.RENDER_SECONDS = args.seconds
    if args.prepare:
        ClassBuild(args.chapters, args.jobs).make()
        return
    if args.submissions is None or args.out is None:
        parser.error("give SUBMISSIONS and --out DIR")
    if not args.submissions.is_dir():
        raise SystemExit(f"grade-class: {args.submissions} is not a folder of submissions")
    if args.jobs < 1 or args.jobs > 64:
        raise SystemExit("grade-class: --jobs takes 1 to 64")
    if not (ROOT / "solutions").is_dir():
        raise SystemExit("grade-class: this is a students' handout: grade a class from the instructor's lab")
    if args.sandbox:
        why = sandbox.Sandbox.check()
        if why:
            raise SystemExit(f"grade-class: {why}")
    else:
        print("grade-class: NO SANDBOX (--no-sandbox): the students' code runs as you, with your files: "
              "only for submissions you trust", flush=True)
    entries = sorted(p for p in args.submissions.iterdir() if not p.name.startswith("."))
    if not entries:
        raise SystemExit(f"grade-class: {args.submissions} holds no submissions")
    args.out = args.out.resolve()
    args.out.mkdir(parents=True, exist_ok=True)
    grader = Grader(args)
    grader.prepare()
    grader.run(entries)
