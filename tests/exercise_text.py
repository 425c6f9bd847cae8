"""Exercise files as a test or a benchmark writes them for a made-up student: the handed-out file
of a chapter with the reference's bodies in some regions, other bodies in others, and stubs left
where the student has not written yet."""
import re
from pathlib import Path


def region(text, opener):
    """The span of the lines between the line matching `opener` and its // @end."""
    m = re.search(r"(^[ \t]*" + opener + r"[^\n]*\n)(.*?)(^[ \t]*// @end[ \t]*$)", text, re.S | re.M)
    if not m:
        raise SystemExit(f"no region '{opener}'")
    return m.start(2), m.end(2)


def put(text, opener, body):
    a, b = region(text, opener)
    return text[:a] + body + text[b:]


def file_name(root, ch):
    return next((Path(root) / "solutions").glob(f"ch{ch}_*.cpp")).name


def exercise_text(root, ch, bodies=None, helpers=None, stubs=(), mark=""):
    """Chapter CH's exercise file with the reference's bodies, except `bodies` (number -> text)
    and the exercises in `stubs`, left as handed out; `mark`, a comment line put at the top of
    every body written (so that two students' files differ)."""
    root = Path(root)
    name = file_name(root, ch)
    reference = (root / "solutions" / name).read_text()
    text = (root / "exercises" / name).read_text()
    for m in re.finditer(r"^[ \t]*// @exercise (\S+) \|", reference, re.M):
        number = m.group(1)
        if number in stubs:
            continue
        opener = r"// @exercise " + re.escape(number) + r" \|"
        a, b = region(reference, opener)
        body = (bodies or {}).get(number, reference[a:b])
        text = put(text, opener, (f"    // {mark}\n" if mark else "") + body)
    if helpers:
        text = put(text, r"// @helpers", helpers)
    return text
