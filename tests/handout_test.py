#!/usr/bin/env python3
"""The students' handout (./lab handout, book §B.8), made from this lab and used as a class would:

    handout_test.py ROOT WORK

1. `./lab handout` of chapter 01 into a git checkout (the class's template), cloned as a
   student's repository; no reference body's text in any file, nothing of solutions/, and the
   handout's own check catches a body planted in it;
2. in the student's clone, the README's two commands: `./lab run` (every chapter renders, the
   students' book builds) and `./lab grade`: the stubs pass nothing, the reference bodies
   pasted in pass everything;
3. a second release (chapters 01-02) into the same template: the student pulls it and runs
   `./lab exercises`; every line they wrote stays, and chapter 02 is there, as stubs.
"""
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tools"))
from checks import check, finish  # noqa: E402
from exercise_text import exercise_text, file_name  # noqa: E402
import handout  # noqa: E402

root, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
template, student = work / "template", work / "student"


def sh(argv, cwd, **kw):
    r = subprocess.run([str(a) for a in argv], cwd=cwd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        print(f"$ {' '.join(map(str, argv))} (in {cwd}) -> {r.returncode}\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}")
    return r


def git(cwd, *argv):
    return sh(["git", "-c", "user.name=rtlab", "-c", "user.email=rtlab@example.org", *argv], cwd)


# 1. The first release.
template.mkdir()
git(template, "init", "-q")
made = sh([root / "lab", "handout", template, "--chapters", "01"], root)
check(made.returncode == 0, "./lab handout of chapter 01")
git(template, "add", "-A")
git(template, "commit", "-qm", "chapter 01")
git(work, "clone", "-q", template, student)
check(not (student / "solutions").exists(), "no solutions/ in the handout")
check(sorted(p.name for p in (student / "exercises").glob("*.cpp")) == [file_name(root, "01")],
      "exercises/ holds the released chapter's file only")
check((student / "tools" / "reference" / "x86_64" / "ch18.o").exists(), "every chapter's reference, compiled")
check(not handout.check(student), f"no answer in the handout: {handout.check(student)[:3]}")
planted = work / "planted"
shutil.copytree(student, planted, ignore=shutil.ignore_patterns(".git"))
shutil.copy2(root / "solutions" / file_name(root, "02"), planted / "common" / "hidden.cpp")
found = handout.check(planted)
check(any("hidden.cpp" in line and "2." in line for line in found), f"the check catches a planted body: {found[:3]}")

# 2. The student's two commands.
ran = sh([student / "lab", "run"], student, timeout=3600)
check(ran.returncode == 0, "./lab run in the handout")
check((student / "out" / "book" / "index.html").exists(), "the students' book is built")
check(not (student / "out" / "book-instructor").exists(), "no instructor edition in the handout")
renders = sorted(p.parent.name for p in (student / "out").glob("ch*/*.png"))
check(len(set(renders)) == 18, f"every chapter rendered: {sorted(set(renders))}")
stubs = sh([student / "lab", "grade", "--expect", "none"], student, timeout=3600)
check(stubs.returncode == 0, f"the stubs pass nothing:\n{stubs.stdout[-1500:]}")
(student / "exercises" / file_name(root, "01")).write_text(exercise_text(root, "01", mark="mine"))
full = sh([student / "lab", "grade", "--expect", "all"], student, timeout=3600)
check(full.returncode == 0, f"the reference bodies pasted in pass everything:\n{full.stdout[-1500:]}")
git(student, "commit", "-qam", "my chapter 01")

# 3. The second release, merged by the student.
again = sh([root / "lab", "handout", template, "--chapters", "01-02"], root)
check(again.returncode == 0, "./lab handout of chapters 01-02 into the same template")
git(template, "add", "-A")
git(template, "commit", "-qm", "chapters 01-02")
pulled = git(student, "pull", "-q", "--no-rebase", "--no-edit")
check(pulled.returncode == 0, "the student pulls the second release")
regen = sh([student / "lab", "exercises"], student, timeout=3600)
check(regen.returncode == 0, "./lab exercises in the handout")
mine = (student / "exercises" / file_name(root, "01")).read_text()
check(mine.count("// mine") == len(re.findall(r"// @exercise ", mine)) > 0, "every body the student wrote is kept")
check((student / "exercises" / file_name(root, "02")).read_text() ==
      (root / "exercises" / file_name(root, "02")).read_text(), "chapter 02 arrives as stubs")
finish("handout")
