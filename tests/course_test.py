#!/usr/bin/env python3
"""A small class graded by ./lab grade-class, as an instructor would grade it, with the cheats of
tests/adversarial/ and attacks on the unpacking beside honest students (issue 42, book §B.8).

    course_test.py ROOT WORK

Honest students hand in folders, a .zip and a .tar.gz; each file of tests/adversarial/ is a
student whose 2.2 is that body (every other exercise of chapters 01-02 the reference's); other
students attack the unpacking (../ and absolute paths, links out of the folder, an archive that
inflates to 2 GiB, a file of 1 GiB, a name with a newline and markup, a file whose markers do not
balance, a binary file, a renamed file). Then:
- every gradebook cell of the honest students is what their own ./lab grade says (run on a copy
  of the lab), the stubs' are all 0, the reference's all full;
- every cheat scores at most what the honest student whose 2.2 is unfinished scores, chapter by
  chapter, with a reason line about chapter 02; a refused object or submission says why;
- nothing outside the students' scratch folders changed: the lab's tree, /tmp, the home folder;
  no process of a student's user id is left;
- names reach the report as text and the CSV without a formula;
- Gradescope's layout (tools/gradescope/) runs once and writes a results.json that agrees.
The sandbox needs root (a user id and a scratch mount per student). Run by an ordinary user (./lab
test in the container, or in ./lab distro-check), grade-class must refuse without --no-sandbox,
and the class is graded without one: the honest students and the attacks on the unpacking (which
are refused before anything runs), not the cheats, whose code would do what it tries. CI runs as
root and grades them all.
"""
import csv
import gzip
import hashlib
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from checks import check, finish  # noqa: E402
from exercise_text import exercise_text as exercise_text_of  # noqa: E402

SANDBOX = os.geteuid() == 0  # the docstring's last paragraph

root, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
shutil.rmtree(work, ignore_errors=True)
subs = work / "submissions"
subs.mkdir(parents=True)
CHAPTERS = ["01", "02"]
FILES = {ch: next((root / "solutions").glob(f"ch{ch}_*.cpp")).name for ch in CHAPTERS}
MARKUP = '<b onmouseover=alert(1)>\n=HYPERLINK("x")'  # (no "/": a name cannot hold one)


def exercise_text(ch, bodies=None, helpers=None, stubs=()):
    return exercise_text_of(root, ch, bodies, helpers, stubs)


def folder(name, files):
    d = subs / name / "exercises"
    d.mkdir(parents=True)
    for file, text in files.items():
        (d / file).write_bytes(text if isinstance(text, bytes) else text.encode())


def reference_files(**stubs):
    return {FILES[ch]: exercise_text(ch, stubs=stubs.get(ch, ())) for ch in CHAPTERS}


# Honest students.
folder("ref", reference_files())
folder("stubs", {FILES[ch]: (root / "exercises" / FILES[ch]).read_text() for ch in CHAPTERS})
folder("honest-22", reference_files(**{"02": ("2.2",)}))
with zipfile.ZipFile(subs / "zipped.zip", "w") as z:
    for file, text in reference_files().items():
        z.writestr(f"repo-main/exercises/{file}", text)
with tarfile.open(subs / "tarred.tar.gz", "w:gz") as t:
    for file, text in reference_files(**{"01": ("1.4",)}).items():
        info = tarfile.TarInfo(f"exercises/{file}")
        info.size = len(text.encode())
        t.addfile(info, io.BytesIO(text.encode()))
folder(MARKUP, reference_files())

# The cheats: each body of tests/adversarial/ as 2.2.
cheats = []
for path in sorted((root / "tests" / "adversarial").glob("*.cpp")) if SANDBOX else []:
    lines = path.read_text().replace("RTLAB_ROOT", json.dumps(str(root))).splitlines()
    helpers = "\n".join(lines[lines.index("// @helpers") + 1:lines.index("// @body")]) + "\n"
    body = "\n".join(lines[lines.index("// @body") + 1:]) + "\n"
    name = "adv-" + path.stem.replace("_", "-")
    cheats.append(name)
    folder(name, {FILES["01"]: exercise_text("01"), FILES["02"]: exercise_text("02", {"2.2": body}, helpers)})

# Attacks on the unpacking.
with zipfile.ZipFile(subs / "zip-slip.zip", "w") as z:
    z.writestr("../../zip-slip-was-here.cpp", "x")
    z.writestr("/tmp/zip-slip-absolute.cpp", "x")
    z.writestr(f"exercises/../../{FILES['02']}", exercise_text("02"))
    z.writestr(f"exercises/{FILES['01']}", exercise_text("01"))
folder("link-out", {FILES["01"]: exercise_text("01")})
(subs / "link-out" / "exercises" / FILES["02"]).symlink_to(root / "solutions" / FILES["02"])
with tarfile.open(subs / "tar-link.tar.gz", "w:gz") as t:
    info = tarfile.TarInfo(f"exercises/{FILES['02']}")
    info.type, info.linkname = tarfile.SYMTYPE, str(root / "solutions" / FILES["02"])
    t.addfile(info)
# 2 GiB of zeros behind a 64 KiB file: gzip members one after another, as gzip allows.
header = tarfile.TarInfo(f"exercises/{FILES['01']}")
header.size = 2 << 30
block = gzip.compress(b"\0" * (64 << 20), compresslevel=1)
with open(subs / "bomb.tar.gz", "wb") as f:
    f.write(gzip.compress(header.tobuf(), compresslevel=1))
    for _ in range(32):
        f.write(block)
folder("big-file", {FILES["01"]: exercise_text("01")})
with open(subs / "big-file" / "exercises" / FILES["02"], "wb") as f:
    f.truncate(1 << 30)  # sparse: a gigabyte to read, none on the disk
broken = exercise_text("02").replace("    // @end\n", "", 1)
folder("broken", {FILES["01"]: bytes(range(256)) * 8, FILES["02"]: broken})
folder("renamed", {FILES["01"]: exercise_text("01"), FILES["02"].replace(".cpp", "s.cpp"): exercise_text("02")})


def tree_hash(*folders):
    h = hashlib.sha256()
    for d in folders:
        for p in sorted(d.rglob("*")):
            if p.is_file() and "__pycache__" not in p.parts:
                h.update(str(p).encode() + p.read_bytes())
    return h.hexdigest()


watched = [root / d for d in ("solutions", "tests", "tools", "common", "chapters")]
before = tree_hash(*watched)
out = work / "out"
if not SANDBOX:
    refused = subprocess.run([str(root / "tools" / "grade-class"), str(subs), "--out", str(out)], capture_output=True,
                             text=True, timeout=600)
    check(refused.returncode != 0 and "needs root" in refused.stderr and not out.exists(),
          f"as an ordinary user, grade-class refuses to grade without its sandbox: {refused.stderr[-500:]}")
    print("course: the cheats of tests/adversarial/ are graded only as root (their sandbox needs it)")
run = subprocess.run([str(root / "tools" / "grade-class"), str(subs), "--out", str(out), "--chapters", "01-02",
                      "--jobs", "2", "--seconds", "3", *([] if SANDBOX else ["--no-sandbox"])], capture_output=True,
                     text=True, timeout=3600)
print(run.stdout[-3000:], run.stderr[-3000:])
check(run.returncode == 0, f"grade-class ends well: {run.returncode}")
check(tree_hash(*watched) == before, "the lab's tree is as it was")
for stray in ("/tmp/rtlab-adversarial-was-here", "/root/rtlab-adversarial-was-here",
              str(root.parent / "rtlab-adversarial-was-here"), "/tmp/zip-slip-absolute.cpp",
              str(subs.parent / "zip-slip-was-here.cpp")):
    # (lexists: as an ordinary user /root cannot be looked into, and no student could write there)
    check(not os.path.lexists(stray), f"nothing written at {stray}")
# (A zombie is dead already: it holds nothing, and waits only for init to read its status.)
# Read from /proc as ps would (a minimal Debian has no ps): effective user id, state, name.
left = []
for status in Path("/proc").glob("[0-9]*/status"):
    try:
        fields = dict(line.split(":", 1) for line in status.read_text().splitlines() if ":" in line)
    except OSError:
        continue  # it ended meanwhile
    uid, state = int(fields["Uid"].split()[1]), fields["State"].split()[0]
    if 61000 <= uid < 62000 and state != "Z":
        left.append(f"{uid} {status.parent.name} {state} {fields['Name'].strip()}")
check(not left, f"no process of a student's user id is left: {left[:5]}")

rows = {}
with open(out / "gradebook.csv", newline="") as f:
    for row in csv.DictReader(f):
        rows[row["student"]] = row
folder_of = {name: row["folder"] for name, row in rows.items()}


def cells(name):
    r = rows[name]
    return [r[f"ch{ch} {k}"] for ch in CHAPTERS for k in ("units", "golden")]


def fraction(cell):
    a, b = cell.split("/")
    return int(a), int(b)


def card(name):
    return (out / folder_of[name] / "scorecard.txt").read_text()


totals = [fraction(c)[1] for c in cells("ref")]
check(all(fraction(c)[0] == fraction(c)[1] > 0 for c in cells("ref")), f"the reference gets full marks: {cells('ref')}")
check(cells("zipped") == cells("ref"), f"the .zip (under a top folder) grades as the folder: {cells('zipped')}")
check(all(fraction(c)[0] == 0 for c in cells("stubs")), f"the stubs get nothing: {cells('stubs')}")
check([fraction(c)[1] for c in cells("stubs")] == totals, "the denominators are the same for everyone")
honest = [fraction(c)[0] for c in cells("honest-22")]
check(0 < honest[2] < totals[2], f"an unfinished 2.2 passes some of chapter 02's tests, not all: {cells('honest-22')}")

# Every honest student's row is what their own ./lab grade says: the reference, the unfinished
# 2.2 and the unfinished 1.4 (the .tar.gz), graded on a copy of the lab.
single = work / "single"
shutil.copytree(root, single, ignore=shutil.ignore_patterns(".git", "build", "out"), symlinks=True)
for name, files in (("ref", reference_files()), ("honest-22", reference_files(**{"02": ("2.2",)})),
                    ("tarred", reference_files(**{"01": ("1.4",)}))):
    for file, text in files.items():
        (single / "exercises" / file).write_text(text)
    mine = subprocess.run(["tools/grade", "01", "02", "--build", "build/exercises", "--solved", ""], cwd=single,
                          capture_output=True, text=True).stdout
    got = []
    for ch in CHAPTERS:
        m = re.search(rf"^ch{ch} +(\d+) of (\d+) +(\d+) of (\d+)", mine, re.M)
        got += [f"{m[1]}/{m[2]}", f"{m[3]}/{m[4]}"] if m else ["?", "?"]
    check(got == cells(name), f"{name}: the class's row {cells(name)} is its own ./lab grade's {got}")

# The cheats: never more than the honest unfinished 2.2, and a reason about chapter 02.
for name in cheats:
    mine = [fraction(c)[0] for c in cells(name)]
    check(all(m <= h for m, h in zip(mine, honest)), f"{name} scores {cells(name)}, more than an honest "
          f"unfinished 2.2 ({cells('honest-22')})")
    check(re.search(r"^  ch02", card(name), re.M), f"{name}: a reason names chapter 02:\n{card(name)}")
named = {"adv-interpose-read": "the C name 'read'", "adv-preinit": ".preinit_array", "adv-fork-sleepers": "ch02",
         "adv-fake-test-case": "a name of the test harness"}
for name in cheats:
    if name in named:
        check(named[name] in card(name), f"{name}: the scorecard says '{named[name]}':\n{card(name)}")
check(len(cheats) == 0 or set(named) <= set(cheats), f"the cheats named here are in tests/adversarial/: {sorted(named)}")

# The unpacking.
expect = {"zip-slip": ["01"], "link-out": ["01"], "tar-link": [], "bomb": [], "big-file": ["01"], "broken": [],
          "renamed": ["01"]}
for name, good in expect.items():
    for ch in CHAPTERS:
        units, golden = cells(name)[2 * CHAPTERS.index(ch)], cells(name)[2 * CHAPTERS.index(ch) + 1]
        full = units == cells("ref")[2 * CHAPTERS.index(ch)] and golden == cells("ref")[2 * CHAPTERS.index(ch) + 1]
        zero = fraction(units)[0] == 0 and fraction(golden)[0] == 0
        check(full if ch in good else zero, f"{name}: ch{ch} {units} {golden} ({'full' if ch in good else 'zero'} "
              f"expected)\n{card(name)}")
for name, why in (("link-out", "symbolic link"), ("tar-link", "link"), ("bomb", "inflates past"),
                  ("big-file", "larger than 1 MiB"), ("broken", f"{FILES['02']}:"), ("broken", "not a text file"),
                  ("renamed", "is missing")):
    check(why in card(name), f"{name}: the scorecard says '{why}':\n{card(name)}")

# Names: text in the page, no formula in the spreadsheet, a folder name of plain characters.
page = (out / folder_of[MARKUP] / "report.html").read_text()
check("<b onmouseover" not in page and "&lt;b onmouseover=alert(1)&gt;" in page, "a name with markup is text in the report")
check(re.fullmatch(r"[A-Za-z0-9._@-]+", folder_of[MARKUP]), f"its folder name is plain: {folder_of[MARKUP]!r}")
raw = (out / "gradebook.csv").read_text()
check("\n=HYPERLINK" not in raw.replace('"<b onmouseover=alert(1)>\n=HYPERLINK(""x"")"', "") and
      '"<b onmouseover=alert(1)>\n=HYPERLINK(""x"")"' in raw,
      "the name is one quoted CSV cell")

# Gradescope's files, in an /autograder layout of a temporary folder.
grader = work / "autograder"
(grader / "submission" / "exercises").mkdir(parents=True)
for file, text in reference_files(**{"02": ("2.2",)}).items():
    (grader / "submission" / "exercises" / file).write_text(text)
env = dict(os.environ, AUTOGRADER_ROOT=str(grader), RTLAB_LAB=str(root), RTLAB_CHAPTERS="01-02")
setup = subprocess.run(["bash", str(root / "tools" / "gradescope" / "setup.sh")], env=env, capture_output=True,
                       text=True, timeout=3600)
check(setup.returncode == 0, f"setup.sh prepares the image: {setup.stderr[-500:]}")
gs = subprocess.run(["bash", str(root / "tools" / "gradescope" / "run_autograder")], env=env, capture_output=True,
                    text=True, timeout=1800)
print(gs.stdout[-1500:], gs.stderr[-1500:])
results = grader / "results" / "results.json"
check(gs.returncode == 0 and results.exists(), f"run_autograder writes results/results.json ({gs.returncode})")
if results.exists():
    r = json.loads(results.read_text())
    mine = json.loads((out / folder_of["honest-22"] / "results.json").read_text())
    check(abs(r["score"] - mine["score"]) < 1e-6, f"Gradescope's score {r['score']} is the class's {mine['score']}")
    check(all({"name", "score", "max_score", "output", "visibility"} <= set(t) for t in r["tests"]) and
          len(r["tests"]) == sum(totals), f"one test per unit test and golden image: {len(r['tests'])}")
finish("course")
