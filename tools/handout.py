#!/usr/bin/env python3
"""./lab handout DIR [--chapters 01-08]: the students' repository, made from the instructor's lab.

DIR gets what a student uses and no answer in any form they can read as source:
- exercises/ as generated stubs, for the released chapters (RTLAB_RELEASED in its
  tools/settings.cmake); tools/blanks/ (the solution files with every body a stub), from which
  its ./lab exercises regenerates them and its book takes its excerpts;
- the reference bodies compiled, one object per chapter and processor (tools/reference/x86_64,
  and tools/reference/aarch64 when Debian's cross compiler is installed), without link-time
  bitcode, -march=native, debug information, source paths or local names, so every chapter
  renders and grades as in the lab (tools/reference.cmake);
- the library, the chapters' programs and scenes, the released chapters' unit tests, every
  chapter's golden images, the grader, the book's sources (its students' edition only) and the pictures of the
  lab's steps a handout cannot run (book/supplied/), and a README for students.
Left out: solutions/, bench/, the fairness, planted and fuzzing tests, the lab's own tests, CI.
A DIR that is a git checkout keeps its .git: a later handout of more chapters is a new commit
the students merge (book §B.8), and their ./lab exercises keeps every body they wrote.

Last, the handout is checked (check()): no file holds the text of a reference body, and the
compiled objects hold no debug section, no source path and no local name.
"""
import argparse
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from grading.classbuild import ClassBuild  # noqa: E402
from grading.classroom import chapters_arg  # noqa: E402
from grading.settings import ROOT, setting  # noqa: E402

# What a handout holds, as paths of the lab (folders whole), and what is left out of them.
INCLUDE = ["CMakeLists.txt", "CMakePresets.json", "LICENSE", "lab", ".clang-format", ".gitignore", ".gitattributes",
           ".devcontainer", "common",
           "chapters", "book", "tools/CMakeLists.txt", "tools/settings.cmake", "tools/ccache.cmake",
           "tools/reference.cmake", "tools/aarch64-linux-gnu.cmake", "tools/golden_coverage.cmake", "tools/grade",
           "tools/grade_report.py", "tools/grading", "tools/diff.cpp", "tools/stat.cpp", "tools/ztest.hpp",
           "tools/gen_exercises.cpp", "tools/book.cpp", "tools/limits.cpp", "tools/figures", "tools/explore",
           "tests/CMakeLists.txt", "tests/doctest_main.cpp", "tests/verdict.hpp", "tests/verdict.cpp",
           "tests/support.hpp", "tests/support"]
LEAVE_OUT = re.compile(r"(^|/)(__pycache__|\.pytest_cache)(/|$)|\.pyc$")
# A reference body counts as in a file when this share of its runs of WINDOW tokens is there.
WINDOW, SHARE = 12, 0.5
# Where the lab's own code shares most of a body's text for a reason of its own, said here.
KNOWN = {("11.2", "common/accel/grid.cpp"):
         "Grid::walk_unchecked, the walk without the check that is the exercise: the mistake the book shows"}


def run(argv, **kw):
    result = subprocess.run([str(a) for a in argv], capture_output=True, text=True, **kw)
    if result.returncode != 0:
        raise SystemExit(f"handout: {' '.join(map(str, argv[:3]))} ... failed:\n{result.stderr[-2000:]}")
    return result.stdout


def reference_objects(build, out):
    """tools/reference/ARCH/chNN.o for every chapter of the lab; the compiler in BUILT_WITH."""
    chapters = setting("RTLAB_CHAPTERS")
    commands = {}
    import json
    for entry in json.loads((build.dir / "compile_commands.json").read_text()):
        m = re.search(r"/solutions/ch(\d\d)_[^/]*\.cpp$", entry["file"])
        if m:
            commands[m.group(1)] = entry
    arches = {"x86_64": ("c++", "strip", [])}
    if shutil.which("aarch64-linux-gnu-g++"):
        # The cross compiler's own C library and C++ headers first; then the host's header-only
        # packages (glm, nlohmann, ...), which are the same on every processor.
        arches["aarch64"] = ("aarch64-linux-gnu-g++", "aarch64-linux-gnu-strip", ["-idirafter", "/usr/include"])
    for arch, (compiler, strip, extra) in arches.items():
        folder = out / "tools" / "reference" / arch
        folder.mkdir(parents=True)
        for ch in chapters:
            argv = __import__("shlex").split(commands[ch]["command"])
            cut = [a for i, a in enumerate(argv) if a != "-o" and (i == 0 or argv[i - 1] != "-o")]
            cut[0] = compiler
            obj = folder / f"ch{ch}.o"
            run([*build.launcher(), *cut, *extra, "-g0", f"-ffile-prefix-map={ROOT}=.", "-o", obj],
                cwd=commands[ch]["directory"])
            # No debug section, no local symbol, no compiler note: the globals the linker needs.
            run([strip, "--strip-unneeded", "--remove-section=.comment", obj])
    version = run(["c++", "-dumpfullversion"]).strip()
    (out / "tools" / "reference" / "BUILT_WITH").write_text(
        f"GNU {version} (Debian's g++; objects of x86-64 without -march, aarch64 when present)\n")
    return list(arches)


def copy_tree(out):
    for rel in INCLUDE:
        source = ROOT / rel
        if not source.exists():
            continue
        target = out / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        if source.is_dir():
            shutil.copytree(source, target, ignore=lambda d, names: [n for n in names if LEAVE_OUT.search(n)])
        else:
            shutil.copy2(source, target)


def main(argv):
    released_all = setting("RTLAB_RELEASED")
    parser = argparse.ArgumentParser(prog="./lab handout", description=__doc__.split("\n\n")[0])
    parser.add_argument("dir", type=Path)
    parser.add_argument("--chapters", default=" ".join(released_all))
    args = parser.parse_args(argv)
    released = chapters_arg(args.chapters, released_all, "handout")
    out = args.dir.resolve()
    # Anywhere but among the lab's own files (its build/ is scratch the lab's git ignores).
    if (out == ROOT or ROOT in out.parents) and (ROOT / "build") not in out.parents:
        raise SystemExit("handout: make it outside the lab or under its build/ (it becomes the students' repository)")
    if out.exists() and any(p.name != ".git" for p in out.iterdir()) and not (out / "tools" / "blanks").is_dir():
        raise SystemExit(f"handout: {out} holds files that are not an earlier handout: give an empty folder")

    # The lab's own pictures of what a handout cannot run, and its tools (./lab run is quick when
    # nothing changed: it redoes no step).
    print("handout: ./lab run (the pictures of the steps a handout cannot run)", flush=True)
    subprocess.run([str(ROOT / "lab"), "run"], check=True, stdout=subprocess.DEVNULL)
    build = ClassBuild(setting("RTLAB_CHAPTERS"), 2)
    build.configure()
    run(["cmake", "--build", build.dir, "--target", "rtlab-genex", "rtlab-book"])
    genex = build.dir / "bin" / "rtlab-genex"

    if out.exists():
        for p in out.iterdir():
            if p.name != ".git":
                shutil.rmtree(p) if p.is_dir() and not p.is_symlink() else p.unlink()
    out.mkdir(parents=True, exist_ok=True)
    copy_tree(out)
    arches = reference_objects(build, out)
    # tools/blanks: the solution files, every body a stub; exercises/ made from them.
    (out / "tools" / "blanks").mkdir(parents=True)
    for source in sorted((ROOT / "solutions").glob("ch*.cpp")):
        run([genex, "--blank", source, out / "tools" / "blanks" / source.name])
    run([genex, out / "tools" / "blanks", out / "exercises", "--chapters", " ".join(released)])
    # The released chapters' unit tests; every chapter's golden images (the book pictures the
    # scenes of chapters not yet released by them; a picture of a right answer is no answer).
    for ch in released:
        shutil.copy2(ROOT / "tests" / f"test_ch{ch}.cpp", out / "tests")
    shutil.copytree(ROOT / "tests" / "golden", out / "tests" / "golden")
    settings = (out / "tools" / "settings.cmake").read_text()
    settings, n = re.subn(r"set\(RTLAB_RELEASED [^)]*\)", f"set(RTLAB_RELEASED {' '.join(released)})", settings)
    assert n == 1, "tools/settings.cmake has no RTLAB_RELEASED line"
    (out / "tools" / "settings.cmake").write_text(settings)
    # The pictures of the steps a handout cannot run, as the lab made them.
    for line in (ROOT / "book" / "pictures.txt").read_text().splitlines():
        parts = line.split()
        if len(parts) == 2 and not line.startswith("#") and parts[0] in ("ch15-fence", "acne-double", "acne-float"):
            target = out / "book" / "supplied" / parts[1]
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / "out" / parts[1], target)
    readme = (ROOT / "tools" / "handout" / "README.md").read_text()
    readme = readme.replace("{CHAPTERS}", ", ".join(released)).replace("{ARCHES}", " and ".join(arches))
    (out / "README.md").write_text(readme)
    problems = check(out)
    if problems:
        print("\n".join(problems), file=sys.stderr)
        raise SystemExit(f"handout: {out} would give answers away (above): nothing is wrong with the lab's "
                         "files' text alone, so look at what was copied")
    files = sum(1 for p in out.rglob("*") if p.is_file() and ".git" not in p.parts)
    print(f"handout: {out}: {files} files, chapters {' '.join(released)} released, reference bodies compiled "
          f"for {', '.join(arches)}; no answer in its text (checked)")


TOKEN = re.compile(r"[A-Za-z_]\w*|\d+\.?\d*(?:[eE][-+]?\d+)?|==|!=|<=|>=|&&|\|\||->|::|\S")


def tokens(text):
    text = re.sub(r"//[^\n]*|/\*.*?\*/", " ", text, flags=re.S)
    return TOKEN.findall(text)


def windows(seq):
    return {tuple(seq[i:i + WINDOW]) for i in range(len(seq) - WINDOW + 1)}


def bodies():
    out = {}
    for source in sorted((ROOT / "solutions").glob("ch*.cpp")):
        for m in re.finditer(r"// @exercise (\S+) \|[^\n]*\n(.*?)\n\s*// @end", source.read_text(), re.S):
            out[m.group(1)] = windows(tokens(m.group(2)))
    return out


def check(folder, known=KNOWN):
    """What in a handout gives an answer away: one line each (empty: nothing)."""
    folder = Path(folder)
    problems = []
    if (folder / "solutions").exists():
        problems.append("solutions/ is there")
    answers = bodies()
    for path in sorted(p for p in folder.rglob("*") if p.is_file() and ".git" not in p.relative_to(folder).parts):
        rel = path.relative_to(folder).as_posix()
        data = path.read_bytes()
        if path.suffix == ".o":
            sections = run(["readelf", "-S", "-W", path])
            if ".debug" in sections:
                problems.append(f"{rel}: has debug information")
            if str(ROOT).encode() in data or b"solutions/" in data:
                problems.append(f"{rel}: names a source path")
            # Local symbols but the assembler's own (.LC0, a constant's label; $x and $d, AArch64's
            # marks of code and data): a static function's or an anonymous namespace's name.
            local = [line for line in run(["nm", path]).splitlines() if re.match(r"^\S*\s+[tdbr]\s", line)
                     and not re.match(r"^(\.L|\$[adtx](\.|$))", line.split()[-1])]
            if local:
                problems.append(f"{rel}: keeps local names ({local[0].split()[-1]} ...)")
            continue
        if b"\0" in data[:8192]:
            continue  # a picture
        seen = windows(tokens(data.decode("utf-8", "replace")))
        for number, grams in answers.items():
            if len(grams) >= 8 and len(grams & seen) >= SHARE * len(grams) and (number, rel) not in known:
                problems.append(f"{rel}: holds {len(grams & seen) / len(grams):.0%} of the text of exercise "
                                f"{number}'s reference body")
    return problems


if __name__ == "__main__":
    main(sys.argv[1:])
