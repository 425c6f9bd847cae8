"""What float against double measured, in the sentences book §0.9 quotes (./lab bench real-choice).

    python3 bench/real_choice_summary.py TABLE OUT_DIR

TABLE is bench/real_choice.sh's printed output (book/measured/real-choice.md holds it). Writes
three paragraphs §0.9 includes, every number read or computed from the table:

  real-choice-cost.md     the stable form's cost per call, and the textbook form's error and misses
  real-choice-render.md   a whole render in float against double, as a ratio
  real-choice-limits.md   where the stable form fails in float, and its worst error in double

Errors and misses depend on the arithmetic only; times move with the machine's load, and are
quoted as ratios measured in the same run. The chapter's reasoning relies on a few facts
(the textbook form's error in double grows with the distance, no misses in double, float
faster); a table that breaks one stops this script (exit 1) instead of writing a sentence
the prose would contradict.
"""

import math
import re
import sys

from measured import n, need


def load(path):
    tables, current, render = {}, None, None
    with open(path) as f:
        for line in f:
            m = re.match(r"^Real=(\w+), (\d+) rays per distance", line)
            if m:
                current = tables.setdefault(m.group(1), {"rays": int(m.group(2)), "rows": []})
                continue
            m = re.match(r"^\s*([\d.e+-]+) \|\s+([\d.]+)\s+([\d.e+]+)\s+(\d+) \|\s+([\d.]+)\s+([\d.e+]+)\s+(\d+)\s*$", line)
            if m and current is not None:
                d, tn, te, tm, sn, se, sm = m.groups()
                current["rows"].append({"D": float(d), "text_ns": float(tn), "text_err": float(te),
                                        "text_miss": int(tm), "stable_ns": float(sn), "stable_err": float(se),
                                        "stable_miss": int(sm)})
                continue
            m = re.match(r"^== whole renders: (.*) \(seconds, best of (\d+)\)", line)
            if m:
                render = {"what": m.group(1), "rounds": m.group(2)}
                continue
            m = re.match(r"^double ([\d.e+-]+) s, float ([\d.e+-]+) s", line)
            if m and render is not None:
                render["double"], render["float"] = float(m.group(1)), float(m.group(2))

    if set(tables) != {"double", "float"} or not all(t["rows"] for t in tables.values()) or "double" not in (
            render or {}):
        sys.exit(f"real_choice_summary.py: {path} lacks a double table, a float table or the renders")
    return tables, render


def power(d):
    return f"$10^{{{round(math.log10(d))}}}$"


def fastest(rows):
    """The stable form's time per call over the textbook form's, each at its fastest distance:
    the work per call does not depend on the distance, a busy machine only adds to it."""
    return min(r["stable_ns"] for r in rows) / min(r["text_ns"] for r in rows)


def eps(e):
    return f"{e:,.0f}" if e >= 100 else f"{e:.2g}"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: real_choice_summary.py TABLE OUT_DIR")
    tables, render = load(sys.argv[1])
    dbl, flt = tables["double"]["rows"], tables["float"]["rows"]
    rays = tables["float"]["rays"]

    errs = [r["text_err"] for r in dbl]
    need(all(b > a for a, b in zip(errs, errs[1:])), "the textbook form's error in double grows with the distance")
    need(all(r["stable_miss"] == 0 and r["text_miss"] == 0 for r in dbl), "no misses in double")
    missing = [r for r in flt if r["text_miss"] > 0]
    need(missing, "the textbook form misses in float")
    worst = max(flt, key=lambda r: r["text_miss"])
    cost = (f"Per call the stable form took {fastest(dbl):.1f} times as long as the textbook form in double and "
            f"{fastest(flt):.1f} times in float (each form's fastest distance, the time least disturbed by other "
            f"programs on a shared machine). In double the textbook error grows with the distance, to "
            f"{eps(dbl[-1]['text_err'])} epsilons at {power(dbl[-1]['D'])} radii. In float it is "
            f"{eps(flt[1]['text_err'])} epsilons at {power(flt[1]['D'])}, and it starts reporting misses at "
            f"{power(missing[0]['D'])}: {n(missing[0]['text_miss'])} rays there, and "
            f"{n(worst['text_miss'])} of {n(rays)} at {power(worst['D'])}.")

    ratio = render["float"] / render["double"]
    need(ratio < 1, "float renders faster than double")
    speed = (f"The whole render ({render['what']}, best of {render['rounds']}) took {ratio:.2f} times as long in "
             f"float as in double ({render['float']:.3f} s against {render['double']:.3f} s, on a machine other "
             f"programs share: the ratio is what to read).")

    failing = [r for r in flt if r["stable_miss"] > 0]
    need(failing, "the stable form misses in float at some distance")
    parts = [f"{n(r['stable_miss'])} at {power(r['D'])}" for r in failing]
    misses = parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]
    limits = (f"In float the stable form misses too, once the sphere is far enough: {misses} radii (of {n(rays)} "
              f"rays each). In double it stays within {max(r['stable_err'] for r in dbl):.2g} ε all the way to "
              f"{power(dbl[-1]['D'])}, and misses none.")

    for name, text in [("real-choice-cost.md", cost), ("real-choice-render.md", speed),
                       ("real-choice-limits.md", limits)]:
        with open(f"{sys.argv[2]}/{name}", "w") as f:
            f.write(text + "\n")
        print(f"== {name}\n{text}")


main()
