"""What a student's compiled exercises may define, checked before anything of theirs is linked.

Their object may define, for the rest of the program to see, only C++ names of namespace rt that
nothing else in the program defines (their exercises among them, and helpers of their own), and
template or inline code (weak definitions) of any C++ name the rest of the program does not
define for good. Never a C name (a `read` or a `write` of their own would be taken in place of
the C library's by the whole program, the harness included), an operator new or delete, any of
doctest's names, or a .preinit_array (code that would run before the harness's own).
"""
import subprocess

STRONG = set("TDBRGSCI")  # nm's letters for a definition the linker takes over any other
WEAK = set("WVu")


def defined(path):
    """{name: kind letter} of the global definitions in an object or archive."""
    out = subprocess.run(["nm", "--defined-only", "--extern-only", "-P", str(path)], capture_output=True,
                         text=True).stdout
    names = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 2 and not parts[0].endswith(":") and len(parts[1]) == 1:
            names[parts[0]] = parts[1]
    return names


def sections(path):
    out = subprocess.run(["readelf", "-S", "-W", str(path)], capture_output=True, text=True).stdout
    return out


def problems(obj, reference, others):
    """Why the student's object may not be linked (a list of lines; empty when it may).
    reference: the names the chapter's reference object defines (the exercises);
    others: {name: kind} defined by everything else the programs link."""
    out = []
    if ".preinit_array" in sections(obj):
        out.append("defines code to run before the program starts (.preinit_array)")
    for name, kind in sorted(defined(obj).items()):
        if name in reference:
            continue
        if kind in WEAK and name.startswith("DW.ref."):  # the compiler's own, for exceptions
            continue
        if not name.startswith("_Z"):
            out.append(f"defines the C name '{name}', which would replace the library's")
        elif name.startswith(("_Znw", "_Zna", "_Zdl", "_Zda")):
            out.append(f"replaces operator new or delete ({name})")
        elif name.startswith(("_ZN7doctest", "_ZNK7doctest", "_ZTVN7doctest")):
            out.append(f"defines a name of the test harness ({name})")
        elif kind in STRONG:
            if not (name.startswith("_ZN2rt") or name.startswith("_ZNK2rt")) or name in others:
                out.append(f"defines {name}, which the library or the harness defines")
        elif kind in WEAK and others.get(name, "W") in STRONG:
            out.append(f"defines {name}, which the library or the harness defines")
    return out[:5]
