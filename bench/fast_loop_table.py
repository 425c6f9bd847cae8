"""Book §B.6's and §B.1's tables from bench/fast_loop.sh's output (./lab bench fast-loop).

    python3 bench/fast_loop_table.py OUTPUT LOOP.md [TEST.md]

Each row of fast_loop.sh's table ("LABEL  SECONDS s  TARGET") becomes a row of a Markdown
table, with the machine the loop ran on: the student's loop in LOOP.md (§B.6), `./lab test`'s
rows and its phases in TEST.md (§B.1, what CI runs; when the loop ran it). The times are what
one run on a shared machine measured: a row far from its target is worth running again before
it is believed.
"""

import datetime
import re
import sys


def code_span(label):
    """'./lab grade 08 after ...' -> '`./lab grade 08` after ...': the command in code."""
    m = re.match(r'^(\./lab \w+(?: (?:\d+|--\S+|"[^"]*"))*)(.*)$', label)
    return f"`{m.group(1)}`{m.group(2)}"


def phase_table(starts, rows):
    """Where `./lab test`'s time went, phase by phase: each phase lasts until the next begins,
    the last until the whole run ends."""
    if not starts:
        return []
    caches = list(starts)
    durations = {}
    for cache in caches:
        total = next((s for label, (s, _) in rows.items() if label.startswith("./lab test") and cache in label), None)
        phases = starts[cache]
        for i, (name, begun) in enumerate(phases):
            end = phases[i + 1][1] if i + 1 < len(phases) else total
            durations.setdefault(name, {})[cache] = None if end is None else end - begun
    out = ["", f"`./lab test`, phase by phase ({' and '.join(c + ' compiler cache' for c in caches)}):", "",
           "| phase | " + " | ".join(caches) + " |", "|---|" + "---:|" * len(caches)]
    for name, by in durations.items():
        cells = ["" if by.get(c) is None else f"{by[c] // 60:.0f}m{by[c] % 60:02.0f}s" for c in caches]
        out.append(f"| {name} | " + " | ".join(cells) + " |")
    return out


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: fast_loop_table.py OUTPUT LOOP.md [TEST.md]")
    machine, rows, starts = None, {}, {}
    with open(sys.argv[1]) as f:
        for line in f:
            m = re.match(r"^fast loop, (\d+) cores, (.*), in \S+\s*$", line)
            if m:
                machine = f"{m.group(2)}, {m.group(1)} cores"
                continue
            m = re.match(r"^phase (\S+) (\d+) (\d+) (.*?)\s*$", line)  # a phase of ./lab test began
            if m:
                starts.setdefault(m.group(1), []).append((m.group(4), int(m.group(2)) * 60 + int(m.group(3))))
                continue
            m = re.match(r"^(\./lab .*?)\s+([\d.]+) s   (.*?)\s*$", line)
            if m:
                rows.setdefault(m.group(1), (float(m.group(2)), m.group(3)))
    if machine is None or not rows:
        sys.exit(f"fast_loop_table.py: {sys.argv[1]} is not bench/fast_loop.sh's output")
    heading = (f"_Measured by `./lab bench fast-loop` (`bench/fast_loop.sh`) on {datetime.date.today().isoformat()}, "
               f"{machine}, one run._")

    def table(labels):
        out = [heading, "", "| what | time | target |", "|---|---:|---|"]
        for label in labels:
            seconds, target = rows[label]
            shown = f"{seconds:,.1f} s" + (f" ({seconds / 60:.1f} min)" if seconds >= 600 else "")
            target = "" if target == "-" else target.replace("<=", "≤")
            out.append(f"| {code_span(label)} | {shown} | {target} |")
        return out

    tests = [label for label in rows if label.startswith("./lab test")]
    files = {sys.argv[2]: table([label for label in rows if label not in tests])}
    if tests and len(sys.argv) == 4:
        files[sys.argv[3]] = table(tests) + phase_table(starts, rows)
    for path, out in files.items():
        with open(path, "w") as f:
            f.write("\n".join(out) + "\n")
        print("\n".join(out))

main()
