"""A student's submission, taken as an attacker would hand it in: only the exercise files are
read, from a folder, a git checkout, a .zip or a .tar.gz, never following a link, never writing
outside the grader's staging folder, never reading more than the limits below; then only their
exercise regions (bodies and @helpers) are put into the instructor's own copy of each file, by
the exercise generator's own parser (rtlab-genex --transplant).

Whatever is wrong with an entry (an archive entry with ../ or an absolute path, a link, a file of
a gigabyte, an archive that inflates without end, a missing or renamed file, markers that do
not balance, a binary file) becomes a reason for a chapter's 0, never a crash of the class run.
"""
import re
import stat
import subprocess
import tarfile
import zipfile
from pathlib import Path, PurePosixPath

LARGEST_FILE = 1 << 20  # an exercise file
LARGEST_INFLATED = 256 << 20  # all an archive may inflate to before it is refused
FILE_RE = re.compile(r"^exercises/(ch(\d\d)_[A-Za-z0-9_]+\.cpp)$")


class Refused(Exception):
    """The whole submission cannot be read: every chapter gets 0 with this reason."""


def display_name(entry):
    """The student's name, from the entry's name (an archive's without its extension)."""
    name = entry.name
    for ext in (".tar.gz", ".tgz", ".zip"):
        if name.endswith(ext):
            return name[: -len(ext)]
    return name


def exercise_path(name, wanted):
    """The exercise file a member path names (at the top, or under one folder, as a hosting
    site's archive has it): 'ch02_spheres.cpp', or None."""
    parts = PurePosixPath(name).parts
    if not parts or name.startswith("/") or ".." in parts:
        return None
    for start in (0, 1):
        rest = "/".join(parts[start:])
        m = FILE_RE.match(rest)
        if m and m.group(1) in wanted:
            return m.group(1)
    return None


def from_folder(folder, wanted, into):
    """Copies the wanted files of a folder (a git checkout is one), following no link."""
    found = {}
    top = [folder] + [p for p in sorted(folder.iterdir()) if p.is_dir() and not p.is_symlink()][:64]
    for base in top:
        exercises = base / "exercises"
        if exercises.is_symlink() or not exercises.is_dir():
            continue
        for name in wanted:
            path = exercises / name
            if name in found:
                continue
            try:
                info = path.lstat()
            except OSError:
                continue
            if stat.S_ISLNK(info.st_mode):
                found[name] = f"exercises/{name} is a symbolic link"
            elif not stat.S_ISREG(info.st_mode):
                found[name] = f"exercises/{name} is not a plain file"
            elif info.st_size > LARGEST_FILE:
                found[name] = f"exercises/{name} is larger than 1 MiB"
            else:
                with open(path, "rb") as f:
                    (into / name).write_bytes(f.read(LARGEST_FILE + 1)[:LARGEST_FILE])
                found[name] = None
    return found


def from_zip(path, wanted, into):
    found, inflated = {}, 0
    try:
        with zipfile.ZipFile(path) as z:
            members = z.infolist()
            if len(members) > 100_000:
                raise Refused(f"the archive has {len(members):,} entries")
            for info in members:
                name = exercise_path(info.filename, wanted)
                if not name or name in found:
                    continue
                mode = info.external_attr >> 16
                if stat.S_ISLNK(mode):
                    found[name] = f"exercises/{name} is a symbolic link"
                elif info.file_size > LARGEST_FILE:
                    found[name] = f"exercises/{name} is larger than 1 MiB"
                else:
                    with z.open(info) as member:
                        data = member.read(LARGEST_FILE + 1)  # the header's size may lie
                    inflated += len(data)
                    if len(data) > LARGEST_FILE:
                        found[name] = f"exercises/{name} is larger than 1 MiB"
                    else:
                        (into / name).write_bytes(data)
                        found[name] = None
                if inflated > LARGEST_INFLATED:
                    raise Refused("the archive inflates past 256 MiB")
    except (zipfile.BadZipFile, zipfile.LargeZipFile, OSError, EOFError, RuntimeError, NotImplementedError) as e:
        raise Refused(f"not a readable .zip ({str(e)[:80]})")
    return found


def from_tar(path, wanted, into):
    found, inflated = {}, 0
    try:
        with tarfile.open(path, "r:*") as t:
            for member in t:  # streamed: one member at a time
                inflated += member.size if member.isfile() else 0
                if inflated > LARGEST_INFLATED:
                    raise Refused("the archive inflates past 256 MiB")
                name = exercise_path(member.name, wanted)
                if not name or name in found:
                    continue
                if member.issym() or member.islnk():
                    found[name] = f"exercises/{name} is a link"
                elif not member.isfile():
                    found[name] = f"exercises/{name} is not a plain file"
                elif member.size > LARGEST_FILE:
                    found[name] = f"exercises/{name} is larger than 1 MiB"
                else:
                    (into / name).write_bytes(t.extractfile(member).read(LARGEST_FILE))
                    found[name] = None
    except (tarfile.TarError, OSError, EOFError) as e:
        raise Refused(f"not a readable .tar.gz ({str(e)[:80]})")
    return found


def collect(entry, wanted, into):
    """{file name: None (copied into `into`) or the reason it could not be}; raises Refused."""
    into.mkdir(parents=True, exist_ok=True)
    if entry.is_symlink():
        raise Refused("the entry is a symbolic link")
    if entry.is_dir():
        return from_folder(entry, wanted, into)
    if entry.name.endswith(".zip"):
        return from_zip(entry, wanted, into)
    if entry.name.endswith((".tar.gz", ".tgz")):
        return from_tar(entry, wanted, into)
    raise Refused("not a folder, a .zip or a .tar.gz")


def text_problem(path):
    """Why a student's file is not a C++ text the generator can read, or None."""
    data = path.read_bytes()
    if b"\0" in data:
        return "is not a text file"
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return "is not UTF-8 text (a binary file?)"
    if "// @exercise" not in text:
        return "has no exercise regions (were the // @exercise lines removed or renamed?)"
    return None


def transplant(genex, solution, student_file, out):
    """The instructor's copy of the file with the student's regions; None, or the reason."""
    problem = text_problem(student_file)
    if problem:
        return f"exercises/{student_file.name} {problem}"
    try:
        result = subprocess.run([str(genex), "--transplant", str(solution), str(student_file), str(out)],
                                capture_output=True, text=True, timeout=30)
    except subprocess.TimeoutExpired:
        return f"exercises/{student_file.name}: its regions could not be read in 30 s"
    if result.returncode != 0:
        why = (result.stderr.strip().splitlines() or ["the generator failed"])[-1]
        return why.removeprefix("rtlab-genex: ")
    return None
