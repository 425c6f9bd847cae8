"""What the time-against-error table says, scene by scene (./lab bench time-error).

    python3 bench/time_error_summary.py TABLE OUT_DIR

TABLE is bench_time_error's printed output (book/measured/time-error.md holds it). Writes
time-error-SCENE.md for every scene, one paragraph the chapter of that scene includes
(book §14.5, §15.6, §16.5, §17.6, §18.5), and time-error-all.md, the range over all scenes.
Every number in them is read or computed from the table, so a new run cannot leave a
sentence behind. RMSE and rays do not depend on the machine; times do, and the sentences
quote them side by side with a ratio.
"""

import math
import re
import sys


def load(path):
    scenes = {}  # name -> {"rows": {pattern: [(spp, seconds, rays, rmse)]}, "slopes": {...}, "equal": ...}
    current = None
    with open(path) as f:
        for line in f:
            m = re.match(r"^(\S+) \((\d+)x(\d+), (\w+) filter;", line)
            if m:
                current = scenes.setdefault(m.group(1), {"rows": {}, "slopes": {}, "equal": None})
                continue
            if current is None:
                continue
            m = re.match(r"^\s+(random|jittered)\s+(\d+)\s+([\d.]+)\s+(\d+)\s+([\d.]+)\s+[\d.]+\s*$", line)
            if m:
                current["rows"].setdefault(m.group(1), []).append(
                    (int(m.group(2)), float(m.group(3)), int(m.group(4)), m.group(5)))
                continue
            m = re.match(r"^\s+(random|jittered)\s+RMSE ~ spp\^(-?[\d.]+), ~ time\^(-?[\d.]+)\s*$", line)
            if m:
                current["slopes"][m.group(1)] = (m.group(2), m.group(3))
                continue
            m = re.match(r"^\s+at random's RMSE at (\d+) spp \(([\d.]+)\): random ([\d.]+) s, jittered ([\d.]+) s: "
                         r"([\d.]+)x less time\s*$", line)
            if m:
                current["equal"] = m.groups()
    if not scenes:
        sys.exit(f"time_error_summary.py: no scenes in {path}")
    return scenes


def minus(s):
    return s.replace("-", "−")


def samples_to_reach(rows, target):
    """Where jittering's RMSE, interpolated on log-log axes between the spp measured, reaches target:
    (lower spp, upper spp, interpolated spp), or None when it never gets there."""
    pts = [(spp, float(rmse)) for spp, _, _, rmse in rows]
    for (s0, e0), (s1, e1) in zip(pts, pts[1:]):
        if e0 >= target >= e1:
            t = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return s0, s1, math.exp(math.log(s0) + t * (math.log(s1) - math.log(s0)))
    return None


def paragraph(name, sc):
    rnd, jit = sc["rows"]["random"], sc["rows"]["jittered"]
    (rs, rt), (js, jt) = sc["slopes"]["random"], sc["slopes"]["jittered"]
    top_r, top_j = rnd[-1], jit[-1]
    out = [f"On `{name}` (measured by `./lab bench time-error`), random sampling's RMSE falls as "
           f"$N^{{{rs}}}$ and jittering's as $N^{{{js}}}$ (against time: {minus(rt)} and {minus(jt)}). "
           f"At {top_r[0]:,} samples per pixel jittering's RMSE is {top_j[3]} against {top_r[3]}, with "
           + (f"the same {top_r[2]:,} rays" if top_r[2] == top_j[2] else f"{top_j[2]:,} rays against {top_r[2]:,}")
           + "."]
    if sc["equal"]:
        spp, target, t_r, t_j, ratio = sc["equal"]
        out.append(f"Random sampling reaches its {int(spp):,}-sample error ({target}) in {t_r} s, jittering in "
                   f"{t_j} s: **{ratio} times less time**.")
        reach = samples_to_reach(jit, float(target))
        if reach:
            lo, hi, at = reach
            out.append(f"Counted in samples, which the machine's load does not touch, jittering gets there between "
                       f"{lo:,} and {hi:,} samples (about {at:,.0f} on log–log axes, {int(spp) / at:.1f} times fewer).")
    return " ".join(out)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: time_error_summary.py TABLE OUT_DIR")
    scenes = load(sys.argv[1])
    ratios, fewer = [], []
    for name, sc in scenes.items():
        if "random" not in sc["rows"] or "jittered" not in sc["rows"] or len(sc["slopes"]) < 2:
            sys.exit(f"time_error_summary.py: scene {name} lacks a pattern's rows or slopes")
        with open(f"{sys.argv[2]}/time-error-{name}.md", "w") as f:
            f.write(paragraph(name, sc) + "\n")
        if sc["equal"]:
            ratios.append(float(sc["equal"][4]))
            reach = samples_to_reach(sc["rows"]["jittered"], float(sc["equal"][1]))
            if reach:
                fewer.append(int(sc["equal"][0]) / reach[2])
    with open(f"{sys.argv[2]}/time-error-all.md", "w") as f:
        f.write(f"Over the {len(scenes)} scenes of the table, jittering reaches random sampling's error in "
                f"{min(ratios):.1f} to {max(ratios):.1f} times less time"
                + (f", and with {min(fewer):.1f} to {max(fewer):.1f} times fewer samples." if fewer else ".") + "\n")


main()
