"""The lab's settings stated once in tools/settings.cmake (the chapters, the golden and
statistical tests' arguments and tolerances), read by asking that file, as every script does."""
import functools
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent


@functools.lru_cache(maxsize=None)
def _read(names):
    out = subprocess.run(["cmake", "-DGET=" + ";".join(names), "-P", str(ROOT / "tools" / "settings.cmake")],
                         check=True, capture_output=True, text=True).stdout
    return tuple(tuple(line.split()) for line in out.splitlines())


def settings(*names):
    """Each named setting as a list of words, in the order asked."""
    return [list(words) for words in _read(tuple(names))]


def setting(name):
    return settings(name)[0]
