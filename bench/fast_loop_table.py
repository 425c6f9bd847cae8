"""Book §B.6's table from bench/fast_loop.sh's output (./lab bench fast-loop).

    python3 bench/fast_loop_table.py OUTPUT OUT.md

Each row of fast_loop.sh's table ("LABEL  SECONDS s  TARGET") becomes a row of a Markdown
table, with the machine the loop ran on. The times are what one run on a shared machine
measured: a row far from its target is worth running again before it is believed.
"""

import datetime
import re
import sys


def code_span(label):
    """'./lab grade 08 after ...' -> '`./lab grade 08` after ...': the command in code."""
    m = re.match(r'^(\./lab \w+(?: (?:\d+|--\S+|"[^"]*"))*)(.*)$', label)
    return f"`{m.group(1)}`{m.group(2)}"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: fast_loop_table.py OUTPUT OUT.md")
    machine, rows = None, {}
    with open(sys.argv[1]) as f:
        for line in f:
            m = re.match(r"^fast loop, (\d+) cores, (.*), in \S+\s*$", line)
            if m:
                machine = f"{m.group(2)}, {m.group(1)} cores"
                continue
            m = re.match(r"^(\./lab .*?)\s+([\d.]+) s   (.*?)\s*$", line)
            if m:
                rows.setdefault(m.group(1), (float(m.group(2)), m.group(3)))
    if machine is None or not rows:
        sys.exit(f"fast_loop_table.py: {sys.argv[1]} is not bench/fast_loop.sh's output")
    out = [f"_Measured by `./lab bench fast-loop` (`bench/fast_loop.sh`) on {datetime.date.today().isoformat()}, "
           f"{machine}, one run._", "", "| what | time | target |", "|---|---:|---|"]
    for label, (seconds, target) in rows.items():
        what = code_span(label)
        shown = f"{seconds:,.1f} s" + (f" ({seconds / 60:.1f} min)" if seconds >= 600 else "")
        target = "" if target == "-" else target.replace("<=", "≤")
        out.append(f"| {what} | {shown} | {target} |")
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(out) + "\n")
    print("\n".join(out))


main()
