"""The class's build, made once per class run and shared by every student (./lab grade-class):
the library, the tests, the chapter programs and the reference bodies, built by CMake in
build/class exactly as a student's own grade builds them (tools/grading/student.py's flags), and
from it the two things a student costs: the command that compiles one chapter's exercise file,
and the command that links one program, with the student's objects in place of the stubs.

Also what the student's code is checked against, taken from this trusted build: each chapter's
list of test cases (from its stub program: no student code in it) and the names the rest of the
programs define (symbols.py).
"""
import json
import re
import shlex
import subprocess
from pathlib import Path

from . import symbols, units
from .settings import ROOT

EXERCISE_OBJECT = re.compile(r"^CMakeFiles/rtlab_exercise_(\d\d)\.dir/exercises/ch\d\d_[A-Za-z0-9_]+\.cpp\.o$")


class ClassBuild:
    def __init__(self, chapters, jobs):
        self.dir = ROOT / "build" / "class"
        self.chapters = chapters
        self.jobs = jobs

    def configure(self):
        configure = ["cmake", "-S", str(ROOT), "-B", str(self.dir), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                     "-DRTLAB_TRACK=exercises", "-DRTLAB_BENCH=OFF", "-DRTLAB_IPO=OFF", "-DRTLAB_SOLVED=",
                     "-DRTLAB_STAND_IN=", "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON"]
        subprocess.run(configure, check=True, capture_output=True)

    def launcher(self):
        """The compiler launcher of this build (tools/ccache.cmake: ccache, or nothing), as argv."""
        for line in (self.dir / "CMakeCache.txt").read_text().splitlines():
            if line.startswith("RTLAB_CXX_LAUNCHER:INTERNAL="):
                value = line.split("=", 1)[1]
                return value.split(";") if value else []
        return []

    def make(self):
        """Configures and builds (ninja does only what changed); then reads the commands."""
        self.configure()
        targets = ["rtlab-diff", "rtlab-stat", "rtlab-genex"]
        for ch in self.chapters:
            targets += [f"test_ch{ch}", f"ch{ch}"]
        result = subprocess.run(["cmake", "--build", str(self.dir), "-j", str(self.jobs), "--target", *targets],
                                capture_output=True, text=True)
        if result.returncode != 0:
            raise SystemExit("grade-class: the class's own build failed:\n" + "\n".join(
                (result.stdout + result.stderr).splitlines()[-15:]))
        self.compile = self._compile_commands()
        self.link = {}
        for ch in self.chapters:
            for program in (f"test_ch{ch}", f"ch{ch}"):
                self.link[program] = self._link_command(program)
        self.bin = self.dir / "bin"

    def _compile_commands(self):
        """{chapter: argv that compiles exercises/chNN_*.cpp, with SOURCE and OUTPUT placeholders}"""
        out = {}
        for entry in json.loads((self.dir / "compile_commands.json").read_text()):
            m = re.search(r"/exercises/(ch(\d\d)_[A-Za-z0-9_]+\.cpp)$", entry["file"])
            if not m or m.group(2) not in self.chapters:
                continue
            argv = shlex.split(entry["command"])
            fixed, skip = [], 0
            for i, word in enumerate(argv):
                if skip:
                    skip -= 1
                    continue
                if word in ("-MT", "-MF"):  # dependency files: not the student's concern
                    skip = 1
                    continue
                if word in ("-MD", "-MMD"):
                    continue
                if word == "-o":
                    fixed += ["-o", "{OUTPUT}"]
                    skip = 1
                    continue
                fixed.append("{SOURCE}" if word == entry["file"] else word)
            out[m.group(2)] = {"argv": fixed, "cwd": entry["directory"], "file": m.group(1)}
        return out

    def _link_command(self, program):
        """argv linking bin/PROGRAM, relative to the build folder, {OUTPUT} for its output and
        {EXERCISE_NN} where chapter NN's exercise object goes."""
        lines = subprocess.run(["ninja", "-C", str(self.dir), "-t", "commands", f"bin/{program}"], check=True,
                               capture_output=True, text=True).stdout.splitlines()
        line = lines[-1].strip()
        line = re.sub(r"^:\s*&&\s*", "", line)
        line = re.sub(r"\s*&&\s*:\s*$", "", line)
        argv, out = shlex.split(line), []
        skip = False
        for word in argv:
            if skip:
                out.append("{OUTPUT}")
                skip = False
                continue
            if word == "-o":
                skip = True
                out.append(word)
                continue
            m = EXERCISE_OBJECT.match(word)
            out.append("{EXERCISE_%s}" % m.group(1) if m else word)
        return out

    def solution_object(self, ch):
        """The reference's object of chapter CH, which stands in for a file that does not compile."""
        found = sorted((self.dir / "CMakeFiles" / f"rtlab_solution_{ch}.dir").rglob("*.o"))
        return found[0]

    def cases(self, runner, work):
        """{chapter: [test case names]}, from the stub programs: trusted, no student code in them."""
        out = {}
        for ch in self.chapters:
            names, why = units.list_cases(runner, self.bin / f"test_ch{ch}", work)
            if names is None:
                raise SystemExit(f"grade-class: the class's own test_ch{ch} could not list its tests ({why})")
            out[ch] = names
        return out

    def symbol_tables(self):
        """(reference: {chapter: names its reference object defines}, others: {name: kind} of
        everything else the programs link, the shared libraries they load included)."""
        reference = {ch: set(symbols.defined(self.solution_object(ch))) for ch in self.chapters}
        others = {}
        inputs = set()
        for argv in self.link.values():
            for word in argv:
                if word.endswith((".a", ".o")) and not word.startswith("{"):
                    inputs.add(word)
        for word in sorted(inputs):
            path = Path(word) if Path(word).is_absolute() else self.dir / word
            if path.exists():
                for name, kind in symbols.defined(path).items():
                    if kind in symbols.STRONG or name not in others:
                        others[name] = kind
        ldd = subprocess.run(["ldd", str(self.bin / f"test_ch{self.chapters[-1]}")], capture_output=True,
                             text=True).stdout
        for lib in re.findall(r"=> (/\S+)", ldd):
            for line in subprocess.run(["nm", "-D", "--defined-only", "-P", lib], capture_output=True,
                                       text=True).stdout.splitlines():
                parts = line.split()
                if len(parts) >= 2:
                    others.setdefault(parts[0].split("@")[0], "T")
        return reference, others
