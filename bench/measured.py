"""What the generators of book/measured/ share (bench/*.py, run by ./lab bench): the line that
dates a measurement, the check that stops a run the prose would contradict, the book's number
formats, the file written, and the programs' output read back.

A generator imports it as `import measured`: Python puts the script's own folder, bench/,
first on its path. Every helper writes what its copies in each script wrote, byte for byte, so
that moving a script onto it changes no file of book/measured/.
"""

import datetime
import json
import os
import resource
import struct
import subprocess
import sys
import tempfile


def cpu():
    """The processor's name, as /proc/cpuinfo gives it."""
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    return "unknown processor"


def stamp(command):
    """The first line of a dated file: the `./lab bench` command, the day and the machine (a time,
    or a program's whole output with its time in it, is true of one machine on one day)."""
    return (f"_Measured by `./lab bench {command}` on {datetime.date.today().isoformat()}, {cpu()}, "
            f"{os.cpu_count()} cores._")


def need(condition, what):
    """Stops the run (exit 1) when a fact the book's prose relies on no longer holds, instead of
    writing a sentence the prose would contradict. `what` is the fact."""
    if not condition:
        sys.exit(f"{os.path.basename(sys.argv[0])}: the book's prose no longer holds: {what}")


def n(x):
    """A count as the book's text writes it: 1,280."""
    return f"{x:,}"


def tex(x):
    """A count inside $...$, where LaTeX would space a bare comma: 1{,}280."""
    return n(x).replace(",", "{,}")


def write(out_dir, name, lines, stamp=None):
    """Writes OUT_DIR/NAME and shows it. Exact counts need no date (stamp None); a time does."""
    with open(os.path.join(out_dir, name), "w") as f:
        f.write("\n".join(([stamp, ""] if stamp else []) + lines).rstrip() + "\n")
    print(f"== {name}\n" + "\n".join(lines))


def run(binary, *args):
    """A program's standard output; a failing run stops the script."""
    return subprocess.run([binary, *args], check=True, capture_output=True, text=True).stdout


def last_line(binary, *args):
    """The last line a program prints: the JSON of --pick and --stats comes after any progress."""
    return run(binary, *args).strip().splitlines()[-1]


def stats(binary, scene, *args, image=None):
    """A render's --stats: the parsed JSON, with the processor time the render took added as
    "cpu_seconds" (user and system, which another program's load disturbs far less than the
    time on the clock), and the line as printed. The image goes to `image`, or nowhere."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with tempfile.TemporaryDirectory() as tmp:
        line = last_line(binary, "--scene", scene, *args, "--stats", "-o", image or os.path.join(tmp, "x.png"))
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    st = json.loads(line)
    st["cpu_seconds"] = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return st, line


def read_pfm(path):
    """A colour PFM's width, height and values (r, g, b of each pixel), in file order: the bottom
    row first."""
    with open(path, "rb") as f:
        kind, size, scale, data = f.read().split(b"\n", 3)
    need(kind == b"PF", f"{path} is a colour PFM")
    w, h = map(int, size.split())
    return w, h, struct.unpack(("<" if float(scale) < 0 else ">") + f"{w * h * 3}f", data[:w * h * 12])
