"""The tables of book §2.6, §3.5 and §6.4, for Real = double and float side by side
(./lab bench precision).

    python3 bench/precision_tables.py DOUBLE_BIN_DIR FLOAT_BIN_DIR OUT_DIR

Runs bench_sphere_accuracy, bench_watertight and bench_acne from both builds and writes, into
OUT_DIR (book/measured/):

  ch02-accuracy.md         §2.6: the sphere tests' worst errors and false misses, and the table
  ch02-area.md             §2.6: the pixels the analytic area test's sphere covers
  ch03-leaks.md            §3.5: leaks of the Cramer and watertight tests, 500,000 rays a mesh
  ch03-watertight-time.md  §3.5: what the watertight test costs, as a ratio (dated)
  ch06-acne.md             §6.4: the acne table
  ch06-acne-float.md       §6.4: what the float columns add up to

Every count is exact for a given build (the same on every machine of the same instruction set).
The relations the prose relies on (no false miss of the stable form, the textbook form far
worse, the watertight test leaking nothing, no offset leaking, the robust offset clean) are
checked here, and a run that breaks one fails (exit 1) instead of writing a sentence the prose
would contradict. Times are quoted only as ratios measured in the same run.
"""

import math
import os
import sys

import measured
from measured import n, need, run, tex, write

LEAK_RAYS = 500000
TIME_RAYS = 200000
TIME_ROUNDS = 5


def accuracy(bin_dir):
    values = {}
    for line in run(os.path.join(bin_dir, "bench_sphere_accuracy")).splitlines():
        key, value = line.split()
        values[key] = value if key == "real" else float(value)
    return values


def about(x):
    """A worst error of thousands of epsilons, to two significant figures."""
    digits = max(0, int(math.floor(math.log10(x))) - 1)
    return int(round(x, -digits))


def ch02(bins, out_dir):
    d, f = accuracy(bins[0]), accuracy(bins[1])
    need(d["real"] == "double" and f["real"] == "float", "the two builds are double and float")
    for a in (d, f):
        need(a["stress_rays"] == 20000 and a["both_rays"] == 5000, "the tests' 20,000 and 5,000 rays all hit")
        need(a["stress_stable_misses"] == 0 and a["stable_misses"] == 0, "the stable form has no false misses")
        need(a["stress_stable_eps"] <= 64, "the stable form is within the test's 64 epsilons")
        need(a["textbook_eps"] > 100 * max(a["stable_eps"], 1), "the textbook form is far worse than the stable one")
    need(d["textbook_misses"] == 0 and f["textbook_misses"] > 0, "only float's textbook form misses")
    # §2.3's estimate eps D / (2 R s) at s = sqrt(1 - 0.99^2): the same order as double's worst.
    estimate = 1e4 / (2 * math.sqrt(1 - 0.99 ** 2))
    need(estimate / 10 < d["textbook_eps"] < estimate * 10, "the textbook error is of the order of §2.3's estimate")
    e = lambda x: f"{x:.1f} ε"
    write(out_dir, "ch02-accuracy.md",
          [f"In `double` the stable form's worst error over the 20,000 rays is ${d['stress_stable_eps']:.1f}\\,\\epsilon$, "
           f"with no false misses. On the 5,000 rays the textbook form's worst error is about "
           f"${tex(about(d['textbook_eps']))}\\,\\epsilon$, and the stable form's is ${d['stable_eps']:.1f}\\,\\epsilon$. "
           f"§2.3's estimate $\\epsilon D/(2Rs)$, with $s = \\sqrt{{1 - 0.99^2}} \\approx 0.14$, gives about "
           f"$3.5\\times10^4\\,\\epsilon$ for one rounding per large term, which is the same order.",
           "",
           f"The same measurements in a build with `Real=float` (the `float` preset) give the second row. In float "
           f"the textbook form does worse than lose digits: on {n(int(f['textbook_misses']))} of the 5,000 rays its "
           f"discriminant comes out negative and the ray misses a sphere it points straight at.",
           "",
           "| `Real` | stable, 0.999 of silhouette (20,000 rays) | textbook, 0.99 (5,000 rays) | stable, 0.99 (5,000 rays) "
           "| textbook false misses |",
           "|---|---|---|---|---|"] +
          [f"| `{a['real']}` | {e(a['stress_stable_eps'])} | ≈ {n(about(a['textbook_eps']))} ε | "
           f"{e(a['stable_eps'])} | {n(int(a['textbook_misses']))} |" for a in (d, f)] +
          ["", "_Measured by `./lab bench precision` (`bench_sphere_accuracy`, the tests' own rays, in the release "
               "and float builds)._"])
    need(abs(d["area_covered"] - d["area_disk"]) < min(d["area_perimeter"], 0.01 * d["area_disk"]),
         "the covered pixels are within a perimeter and 1 % of the disk's area")
    write(out_dir, "ch02-area.md",
          [f"In the double build the sphere covers {n(int(d['area_covered']))} pixels, against "
           f"$\\pi R^2 / (0.01)^2 = {tex(round(d['area_disk'], 1))}$."])


def leaks(bin_dir, rays):
    """{mesh: (cramer leaks, cramer ns, watertight leaks, watertight ns)} and the header."""
    rows = {}
    for line in run(os.path.join(bin_dir, "bench_watertight"), str(rays)).splitlines()[2:]:
        name, cramer, watertight = (part.strip() for part in line.split("|"))
        c, w = cramer.split(), watertight.split()
        rows[name] = (int(c[0]), float(c[1]), int(w[0]), float(w[1]))
    return rows


def ch03(bins, out_dir, stamp):
    ico, cube, far = "icosphere/3 (1280 tris)", "cube 8x8 (768 tris)", "icosphere/3 at 2^20"
    table = ["| `Real` | icosphere, Cramer | icosphere, watertight | cube, Cramer | cube, watertight |",
             "|---|---|---|---|---|"]
    for real, b in zip(("double", "float"), bins):
        r = leaks(b, LEAK_RAYS)
        # The far icosphere is §3.5's third row, in double only: in float its unit-sized
        # triangles at 2^20, where floats are 0.125 apart, are not the mesh they were.
        for mesh in (ico, cube, far) if real == "double" else (ico, cube):
            need(r[mesh][2] == 0, f"the watertight test lets nothing through ({real}, {mesh})")
            need(r[mesh][0] > 0, f"the Cramer test leaks ({real}, {mesh})")
        if real == "float":
            need(r[far][2] > 0, "in float the watertight test lets rays through at 2^20")
        need(r[ico][0] > LEAK_RAYS / 10, "more than one ray in ten gets through the Cramer test on the icosphere")
        pct = lambda k: f"{n(k)} ({100 * k / LEAK_RAYS:.1f}%)"
        table.append(f"| `{real}` | {pct(r[ico][0])} | 0 | {pct(r[cube][0])} | 0 |")
    write(out_dir, "ch03-leaks.md", table)

    # The cost: each form's fastest of TIME_ROUNDS runs, per mesh, as a ratio (the double build).
    best = {}
    for _ in range(TIME_ROUNDS):
        for mesh, (_, cns, _, wns) in leaks(bins[0], TIME_RAYS).items():
            c, w = best.get(mesh, (math.inf, math.inf))
            best[mesh] = (min(c, cns), min(w, wns))
    ratios = [w / c for c, w in best.values()]
    need(max(ratios) < 2, "the watertight test costs less than twice the Cramer test")
    write(out_dir, "ch03-watertight-time.md",
          [f"Per ray, the watertight test took {min(ratios):.2f} to {max(ratios):.2f} times as long as the Cramer "
           f"test on the three meshes (in double, {n(TIME_RAYS)} rays, each form's fastest of {TIME_ROUNDS} runs, "
           "on a machine other programs share: only the ratio is quoted)."], stamp)


def acne(bin_dir):
    """[(exponent, lit, normal acne, normal leaks, course acne, course leaks, robust acne, robust leaks)]"""
    rows = []
    for line in run(os.path.join(bin_dir, "bench_acne")).splitlines():
        if line.startswith("| 10^"):
            cells = [c.strip() for c in line.strip("|").split("|")]
            rows.append([int(cells[0][3:])] + [int(c) for c in cells[1:]])
    need([r[0] for r in rows] == list(range(6)), "bench_acne measures the scales 10^0 to 10^5")
    return rows


def ch06(bins, out_dir):
    d, f = acne(bins[0]), acne(bins[1])
    lit = d[0][1]
    need(all(r[1] == lit for r in d + f), "the same lit pixels at every scale, in both types")
    need(all(r[3] == r[5] == r[7] == 0 for r in d + f), "no method leaks at any scale, in either type")
    need(all(r[6] == 0 for r in d + f), "the robust offset makes no acne")
    need(sum(r[2] + r[4] for r in d) == 1 and d[0][2] == 1, "double's only acne is one normal pixel at 10^0")
    need(max(r[2] for r in f[:3]) <= 1 and f[3][2] > 1000, "float's normal works up to 10^2 and breaks at 10^3")
    need(f[1][4] > f[1][2], "course fails sooner than normal")
    need(all(5 < f[k + 1][4] / f[k][4] < 15 for k in (1, 2)), "course's acne grows about tenfold a decade to 10^3")
    need(f[4][4] / f[3][4] < 5 and f[5][4] / f[4][4] < 5, "and then more slowly")
    table = ["| scale | float: `normal` | float: `course` | float: `robust` | double: `normal` | double: `course` "
             "| double: `robust` |", "|---|---|---|---|---|---|---|"]
    for a, b in zip(f, d):
        table.append(f"| $10^{a[0]}$ | {n(a[2])} | {n(a[4])} | {n(a[6])} | {n(b[2])} | {n(b[4])} | {n(b[6])} |")
    write(out_dir, "ch06-acne.md",
          [f"There are {n(lit)} lit pixels at every scale. **No method leaks at any scale, in either type.** "
           "The acne:", ""] + table)
    pct = lambda k: f"{100 * k / lit:.0f}%"
    write(out_dir, "ch06-acne-float.md",
          [f"In float, `normal` puts {pct(f[4][2])} of the lit pixels in their own shadow at $10^4$ and "
           f"{pct(f[5][2])} at $10^5$. `course` gets {pct(f[5][4])} of them wrong at $10^5$."])


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: precision_tables.py DOUBLE_BIN_DIR FLOAT_BIN_DIR OUT_DIR")
    bins, out_dir = sys.argv[1:3], sys.argv[3]
    stamp = measured.stamp("precision")
    os.makedirs(out_dir, exist_ok=True)
    ch02(bins, out_dir)
    ch03(bins, out_dir, stamp)
    ch06(bins, out_dir)


main()
