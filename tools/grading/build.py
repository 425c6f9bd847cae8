"""Building a student's exercises so that one file that does not compile costs its own chapter
only: every chapter's exercise file is compiled on its own, and a chapter whose file fails is
linked with the reference bodies in its place (RTLAB_STAND_IN), so every other chapter is still
graded, while the failing one scores nothing, with the compiler's first message.

Also what the compiler said about files that did compile (warnings such as "iteration 7 invokes
undefined behavior"): kept per chapter, shown on the scorecard until the file changes.
"""
import re
import subprocess
from pathlib import Path

from .settings import ROOT

# "FAILED: CMakeFiles/rtlab_exercise_03.dir/exercises/ch03_triangles.cpp.o"
FAILED = re.compile(r"^FAILED: .*rtlab_exercise_(\d\d)\.dir/")
# "/lab/exercises/ch03_triangles.cpp:12:5: error: ..." (and warnings, notes)
DIAGNOSTIC = re.compile(r"^(?:.*/)?exercises/(ch(\d\d)_[^/:]*\.cpp):(\d+):(\d+): (error|warning): (.*)$")


def diagnostics(log):
    """{chapter: {"error": first error line, "warnings": [lines]}} from a build's output."""
    out = {}
    for line in log.splitlines():
        m = DIAGNOSTIC.match(line)
        if not m:
            continue
        entry = out.setdefault(m.group(2), {"error": None, "warnings": []})
        text = f"{m.group(1)}:{m.group(3)}:{m.group(4)}: {m.group(5)}: {m.group(6)}"
        if m.group(5) == "error":
            entry["error"] = entry["error"] or text
        elif text not in entry["warnings"]:
            entry["warnings"].append(text)
    return out


def compiled_chapters(log):
    """The chapters whose exercise file this build compiled (so its diagnostics are current)."""
    return set(re.findall(r"Building CXX object CMakeFiles/rtlab_exercise_(\d\d)\.dir/", log))


def compile_exercises(build, chapters, jobs):
    """Compiles the exercise files of `chapters`, each on its own (ninja -k 0). Returns
    (failed: {chapter: first error}, warnings: {chapter: [lines]} for files compiled now)."""
    if not chapters:
        return {}, {}
    targets = [f"rtlab_exercise_{ch}" for ch in chapters]
    result = subprocess.run(["cmake", "--build", str(build), "-j", str(jobs), "--target", *targets, "--", "-k", "0"],
                            capture_output=True, text=True, cwd=ROOT)
    log = result.stdout + result.stderr
    found = diagnostics(log)
    failed = {}
    for ch in {m.group(1) for m in map(FAILED.match, log.splitlines()) if m}:
        failed[ch] = (found.get(ch) or {}).get("error") or "the compiler stopped without an error line (see the build)"
    if result.returncode != 0 and not failed:
        raise RuntimeError("the build failed outside your exercises:\n" + "\n".join(log.splitlines()[-20:]))
    warnings = {ch: (found.get(ch) or {}).get("warnings", []) for ch in compiled_chapters(log) if ch not in failed}
    return failed, warnings
