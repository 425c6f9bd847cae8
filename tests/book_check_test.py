#!/usr/bin/env python3
"""rtlab-book fails on what would break the book silently, naming the file, line and problem.

  book_check_test.py ROOT BOOK_TOOL WORK_DIR

Each case is a small fake book (in WORK_DIR) with one defect: a heading glued to the line
above it, a link to a missing page or anchor, a bare § that names no section, a § that
quotes another section's title, a picture with no source, and, in a normal build, a picture
that is not there to copy. Each must exit 1 with one line naming the file, line and problem.
The same fake book without the defect, and the real book in ROOT, must pass --check. Also:
"course §9.5" in any case, §N.M.K, and a § in code are not linked. Book §B.7.
Closing line: "N passed, N failed".
"""
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from checks import check, finish  # noqa: E402

root, tool, work = (pathlib.Path(a) for a in sys.argv[1:4])

INDEX = "---\ntitle: \"Fake\"\n---\n\nThe contents.\n\n## Chapters\n\n- [1 One](01-one.html)\n"
GOOD = """---
title: "1 One"
---

Some text.

## 1.1 First things

See §1.2 "Second things", [the start](01-one.html#sec-1-1), [odd](#a-heading-of-its-own) and
[it](#sec-1-2). Course §9.5 is the course's; so is course
§9.6, and its §2.4.6 is another text's. In code, `§7.7` is code.

![A golden picture.](../ch01/scene.png)

### A heading of its own

## 1.2 Second things

The end.
"""


def make(name, chapter, golden=True, pictures=""):
    book = work / name
    shutil.rmtree(book, ignore_errors=True)
    (book / "book").mkdir(parents=True)
    (book / "book/index.md").write_text(INDEX)
    (book / "book/01-one.md").write_text(chapter)
    (book / "book/book.css").write_text("")
    (book / "book/pictures.txt").write_text("# step picture\n" + pictures)
    if golden:
        (book / "tests/golden/ch01").mkdir(parents=True)
        (book / "tests/golden/ch01/scene.png").write_bytes(b"not really a png")
    return book


def run(book, *args):
    r = subprocess.run([str(tool), "--root", str(book), "--out", str(book / "out/book"), *args],
                       capture_output=True, text=True)
    return r.returncode, r.stderr.strip().splitlines()


def line_of(text, needle):
    return text.splitlines().index(needle) + 1


# The fake book without a defect passes, and its links are made as the rules say.
good = make("good", GOOD)
code, lines = run(good, "--check")
check(code == 0 and not lines, f"the good fake book must pass --check, got {code}: {lines}")
code, lines = run(good, "--markdown-only")
md = (good / "out/book/md/01-one.md").read_text()
check("[§1.2](01-one.html#sec-1-2) \"Second things\"" in md, "§1.2 is linked to its section")
check("Course §9.5 is" in md and "course\n§9.6," in md, "course §, in any case and across a line, is not linked")
check("its §2.4.6 is" in md, "§N.M.K is not linked")
check("`§7.7`" in md, "a § in code is not linked")

SEE = next(i + 1 for i, l in enumerate(GOOD.splitlines()) if l.startswith("See §1.2"))
PICTURE = line_of(GOOD, "![A golden picture.](../ch01/scene.png)")
# Each defect: (case, text, the line it is on, words the message must hold).
glued = GOOD.replace("Some text.\n\n## 1.1", "Some text.\n## 1.1")
cases = [
    ("glued heading", glued, line_of(glued, "## 1.1 First things"), "heading glued"),
    ("missing anchor", GOOD.replace("#sec-1-1)", "#sec-1-9)"), SEE, "01-one.html has no anchor #sec-1-9"),
    ("missing page", GOOD.replace("(01-one.html#sec-1-1)", "(02-two.html#sec-2-1)"), SEE, "no page 02-two.html"),
    ("missing same-page anchor", GOOD.replace("(#a-heading-of-its-own)", "(#nowhere)"), SEE, "no anchor #nowhere"),
    ("section that is not there", GOOD.replace("The end.", "As §1.7 says."), line_of(GOOD, "The end."),
     "§1.7 names no section"),
    ("wrong title", GOOD.replace('"Second things"', '"First things"'), SEE,
     'quotes the title "First things" but its title is "Second things"'),
    ("picture without a source", GOOD.replace("ch01/scene.png", "ch01/unmade.png"), PICTURE,
     "picture ch01/unmade.png has no source"),
]
for case, text, number, words in cases:
    book = make(case.replace(" ", "-"), text)
    code, lines = run(book, "--check")
    check(code == 1, f"{case}: --check must exit 1, got {code}")
    hits = [l for l in lines if l.startswith(f"book/01-one.md:{number}: ") and words in l]
    check(len(hits) == 1 and len(lines) == 1, f"{case}: expected one line 'book/01-one.md:{number}: ...{words}...', "
          f"got {lines}")

# A picture a ./lab run step makes (book/pictures.txt) has a source, and so does a chapter's
# noisy scene (its statistical reference): --check passes, but a normal build without the
# renders fails, one line per missing picture, before pandoc runs.
made = GOOD.replace("![A golden picture.](../ch01/scene.png)",
                    "![Made by a step.](../ch01/made.png) ![Noisy.](../ch01/noisy.png) ![Twice.](../ch01/made.png)")
book = make("run-pictures", made, pictures="some-step ch01/made.png\n")
(book / "tests/golden/ch01/noisy.mean.pfm").write_bytes(b"PF")
code, lines = run(book, "--check")
check(code == 0 and not lines, f"pictures from book/pictures.txt and a noisy scene pass --check, got {code}: {lines}")
code, lines = run(book, "--edition", "student")
check(code == 1, f"a normal build with pictures missing must exit 1, got {code}")
check(sorted(lines) == [f"book/01-one.md:{PICTURE}: no picture ch01/made.png (./lab run makes it: run it first)",
                        f"book/01-one.md:{PICTURE}: no picture ch01/noisy.png (./lab run makes it: run it first)"],
      f"one line per missing picture, got {lines}")
check(not (book / "out/book/01-one.html").exists(), "nothing is built when a picture is missing")

# The real book passes.
code, lines = run(root, "--check")
check(code == 0 and not lines, f"the book in {root} must pass --check, got {code}: {lines[:5]}")
finish("book_check_test")
