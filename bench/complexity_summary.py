"""What the complexity sweep says, written from its own output (./lab bench complexity).

    python3 bench/complexity_summary.py TEXT OUT_DIR

TEXT is bench_complexity's printed output, the table the book shows (book/measured/complexity.md
holds it): the sentences are computed from the rows and slopes as printed, so that they say
exactly what a reader checking them against the table finds, ties included. Writes three Markdown lists, one per
chapter, that the book includes after the table (book §10.7, §11.5, §12.6):
complexity-bvh.md, complexity-grid.md and complexity-bsp.md. Every number and every
comparison in them ("the quickest at 14 of 16 sizes") is computed here, so a new run cannot
leave a sentence behind. Times are one run's on a shared machine: the sentences compare
structures measured side by side and quote ratios, and the counts per ray are exact.
"""

import math
import re
import sys

from measured import n

COURSE_BVHS = ["bvh-sort", "bvh-midpoint", "bvh-sah"]
BVH_BUILDS = COURSE_BVHS + ["fast"]
INPUTS = ["terrain", "soup", "stadium"]


def load(text_path):
    rows = {}  # (input, structure) -> [row] by size
    slopes = {}  # (input, structure) -> (query, build)
    keys = ("build_s", "ns_per_ray", "nodes_per_ray", "primitives_per_ray", "bytes_per_primitive")
    with open(text_path) as f:
        for line in f:
            m = re.match(r"^(\w+)\s+(\d+)\s+(\S+)((?:\s+[\d.]+){5})\s*$", line)
            if m:
                r = dict(zip(keys, map(float, m.group(4).split())))
                r.update(input=m.group(1), triangles=int(m.group(2)), structure=m.group(3))
                rows.setdefault((m.group(1), m.group(3)), []).append(r)
                continue
            m = re.match(r"^\s+(\w+)\s+(\S+)\s+query\s+(-?[\d.]+)\s+build\s+(-?[\d.]+)\s*$", line)
            if m:
                slopes[(m.group(1), m.group(2))] = (float(m.group(3)), float(m.group(4)))
    if not rows or not slopes:
        sys.exit(f"complexity_summary.py: no rows or no slopes in {text_path}")
    return rows, slopes


def span(values, digits=2):
    lo, hi = (f"{v:,.{digits}f}" for v in (min(values), max(values)))
    return lo if lo == hi else f"{lo}–{hi}"


def code(name):
    return f"`{name}`"


def listing(names):
    names = list(names)
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


class Sweep:
    def __init__(self, rows, slopes):
        self.rows, self.slopes = rows, slopes

    def sizes(self, inp):
        return sorted({r["triangles"] for (i, _), rs in self.rows.items() if i == inp for r in rs})

    def at(self, inp, structure, triangles):
        for r in self.rows.get((inp, structure), []):
            if r["triangles"] == triangles:
                return r
        return None

    def query(self, inp, s):
        return self.slopes[(inp, s)][0]

    def build(self, inp, s):
        return self.slopes[(inp, s)][1]

    def best(self, inp, triangles, structures, key):
        """The structures with the lowest key (as printed, so ties count) among those measured."""
        present = [(self.at(inp, s, triangles)[key], s) for s in structures if self.at(inp, s, triangles)]
        low = min(present)[0] if present else None
        return {s for v, s in present if v == low}

    def wins(self, structure, structures, key, inputs=INPUTS):
        """(sizes where structure has the lowest key, all sizes, the others as 'input N')."""
        won, total, lost = 0, 0, []
        for inp in inputs:
            for t in self.sizes(inp):
                if not self.at(inp, structure, t):
                    continue
                total += 1
                if structure in self.best(inp, t, structures, key):
                    won += 1
                else:
                    lost.append(f"{inp} {n(t)}")
        return won, total, lost

    def largest(self, inp, structure):
        return max(self.rows[(inp, structure)], key=lambda r: r["triangles"])


def nlogn_slope(sizes):
    """The least-squares log-log slope of N log N over these sizes: what the course predicts."""
    xs = [math.log10(t) for t in sizes]
    ys = [math.log10(t * math.log(t)) for t in sizes]
    m = len(xs)
    sx, sy = sum(xs), sum(ys)
    sxx, sxy = sum(x * x for x in xs), sum(x * y for x, y in zip(xs, ys))
    return (m * sxy - sx * sy) / (m * sxx - sx * sx)


def bvh(s):
    out = []
    none_q = [s.query(i, "none") for i in INPUTS]
    line = (f"- **Brute force** (`none`) has query slopes of {span(none_q)}: every triangle, every ray")
    if min(none_q) < 0.95:
        line += " (below 1 where a fixed cost per ray still shows at the smallest sizes)"
    if max(none_q) > 1.05:
        line += (". A slope above 1 is not the algorithm's: the machine, shared, was busier while the larger "
                 "sizes ran, and only ratios measured side by side are safe from that")
    out.append(line + ".")

    builds = [s.build(i, b) for i in INPUTS for b in BVH_BUILDS]
    sizes = s.sizes("terrain")
    steepest = {i: max(BVH_BUILDS, key=lambda b: s.build(i, b)) for i in INPUTS}
    won, total, lost = s.wins("bvh-midpoint", COURSE_BVHS, "build_s")
    line = (f"- **Building** a BVH (the course's three and `fast`) has slopes of {span(builds)}. "
            f"Over {n(sizes[0])}–{n(sizes[-1])} triangles $N \\log N$ itself has a log–log slope of "
            f"{nlogn_slope(sizes):.2f}, so that is what the course predicts. The steepest BVH build is "
            + listing(f"{code(b)} on the {i}s" for i, b in steepest.items()) + ". "
            f"The midpoint build is the quickest of the course's three (or tied at the table's precision) "
            f"at {won} of {total} sizes")
    out.append(line + (f" (not at {listing(lost)})." if lost else "."))

    trees = {i: [s.query(i, b) for b in BVH_BUILDS] for i in INPUTS}
    line = ("- **Queries** of the BVHs are far from brute force but not flat: slopes "
            + listing(f"{span(v)} on {i}s" for i, v in trees.items()) + ".")
    first, last = s.sizes("terrain")[0], s.sizes("terrain")[-1]
    a, b = s.at("terrain", "bvh-sah", first), s.at("terrain", "bvh-sah", last)
    line += (f" The boxes tested per ray grow roughly like $\\log N$: `bvh-sah` on terrains tests "
             f"{a['nodes_per_ray']:.1f} boxes per ray at {n(first)} triangles and {b['nodes_per_ray']:.1f} at "
             f"{n(last)}, {b['nodes_per_ray'] / a['nodes_per_ray']:.1f} times as many, while $\\log_2 N$ grows "
             f"{math.log2(last) / math.log2(first):.1f} times. Its time per ray grows "
             f"{b['ns_per_ray'] / a['ns_per_ray']:.1f} times.")
    out.append(line)

    big = s.sizes("soup")[-2:]
    ratios = [s.at("soup", c, t)["primitives_per_ray"] / s.at("soup", "fast", t)["primitives_per_ray"]
              for t in big for c in COURSE_BVHS if s.at("soup", c, t) and s.at("soup", "fast", t)]
    terr = [s.at("terrain", "fast", t)["primitives_per_ray"] for t in s.sizes("terrain") if s.at("terrain", "fast", t)]
    terr_sah = [s.at("terrain", "bvh-sah", t)["primitives_per_ray"] for t in s.sizes("terrain")
                if s.at("terrain", "bvh-sah", t)]
    won, total, lost = s.wins("fast", [k for (i, k) in s.rows if i == "terrain"], "ns_per_ray")
    line = (f"- **Order matters.** On the soups of {listing(n(t) for t in big)} triangles the course's trees, "
            f"searched left child first, test {span(ratios, 1)} times as many primitives per ray as `fast`, "
            f"which opens the nearer child first. On the terrains `fast` tests more "
            f"({span(terr, 1)} per ray against `bvh-sah`'s {span(terr_sah, 1)}): it counts every triangle of each "
            f"block it opens. Its time per ray is the lowest of all structures at {won} of {total} sizes")
    out.append(line + (f" (not at {listing(lost)})." if lost else "."))

    won, total, lost = s.wins("bvh-sah", COURSE_BVHS, "ns_per_ray")
    line = f"- **Among the course's trees**, `bvh-sah` is the quickest to search at {won} of {total} sizes"
    out.append(line + (f" (not at {listing(lost)})." if lost else "."))
    return out


def grid(s):
    out = []
    every = sorted({k for (_, k) in s.rows if k != "none"})
    won, total, lost = s.wins("grid", every, "build_s")
    builds = [s.build(i, "grid") for i in INPUTS]
    line = (f"- **Building** the grid is the quickest of all the structures (or tied at the table's "
            f"precision) at {won} of {total} sizes"
            + (f" (not at {listing(lost)})" if lost else "")
            + f". Its slopes are {span(builds)}.")
    out.append(line)

    trees = [s.query("terrain", b) for b in COURSE_BVHS]
    inside = all(min(s.at("terrain", b, t)["ns_per_ray"] for b in COURSE_BVHS) * 0.5
                 <= s.at("terrain", "grid", t)["ns_per_ray"]
                 <= max(s.at("terrain", b, t)["ns_per_ray"] for b in COURSE_BVHS) * 1.5
                 for t in s.sizes("terrain") if s.at("terrain", "grid", t))
    line = (f"- **Evenly spread scenes.** On terrains the grid's query slope is {s.query('terrain', 'grid'):.2f}, "
            f"against {span(trees)} for the course's BVHs, and its time per ray "
            + ("stays within half to one and a half times theirs at every size." if inside
               else "leaves their range at some sizes."))
    beats = [t for t in s.sizes("soup") if s.at("soup", "grid", t)
             and s.at("soup", "grid", t)["ns_per_ray"] < min(s.at("soup", b, t)["ns_per_ray"] for b in COURSE_BVHS)]
    if beats:
        fewer = all(s.at("soup", "grid", t)["nodes_per_ray"] < min(s.at("soup", b, t)["nodes_per_ray"]
                                                                   for b in COURSE_BVHS) for t in beats)
        line += (f" On soups it is quicker than every course BVH at {listing(n(t) for t in beats)} triangles"
                 + (", visiting fewer cells per ray than they open boxes." if fewer else "."))
    else:
        line += " On soups it is quicker than none of the course's BVHs."
    out.append(line)

    big = s.largest("stadium", "grid")
    worst = max(s.at("stadium", b, big["triangles"])["ns_per_ray"] for b in COURSE_BVHS)
    out.append(f"- **The stadium.** The grid's query slope is {s.query('stadium', 'grid'):.2f}, against "
               f"{s.query('stadium', 'none'):.2f} for brute force. At {n(big['triangles'])} triangles it tests "
               f"{big['primitives_per_ray']:,.0f} triangles per ray and takes {big['ns_per_ray'] / worst:.0f} times "
               f"as long per ray as the slowest course BVH. That is the breakdown of §11.4, measured.")
    return out


def bsp(s):
    out = []
    every = sorted({k for (_, k) in s.rows if k != "none"})
    slowest = {i: max(every, key=lambda k: s.largest(i, k)["build_s"]) for i in INPUTS}
    ratio = {i: s.largest(i, "bsp")["build_s"] / s.largest(i, "bvh-sah")["build_s"] for i in INPUTS}
    out.append(f"- **Building.** Log–log slopes of {span([s.build(i, 'bsp-midpoint') for i in INPUTS])} for the "
               f"midpoint build and {span([s.build(i, 'bsp') for i in INPUTS])} for the SAH build. At the largest "
               f"size of each input the SAH build takes "
               + listing(f"{r:.1f} times (on the {i}s)" for i, r in ratio.items())
               + " as long as the BVH's SAH build. The slowest build there is "
               + listing(f"{code(k)} on the {i}s" for i, k in slowest.items()) + ".")

    t = s.largest("terrain", "bsp")["triangles"]
    row = {k: s.at("terrain", k, t) for k in ("bsp-midpoint", "bsp", "bvh-sah", "fast")}
    out.append(f"- **Terrains.** Query slopes {s.query('terrain', 'bsp-midpoint'):.2f} (midpoint) and "
               f"{s.query('terrain', 'bsp'):.2f} (SAH), against {span([s.query('terrain', b) for b in COURSE_BVHS])} "
               f"for the course's BVHs. At {n(t)} triangles a ray takes "
               f"{row['bsp-midpoint']['ns_per_ray'] / row['bvh-sah']['ns_per_ray']:.1f} times as long with the "
               f"midpoint tree as with `bvh-sah`, {row['bsp']['ns_per_ray'] / row['bvh-sah']['ns_per_ray']:.1f} times "
               f"with the SAH tree, and `fast` {row['fast']['ns_per_ray'] / row['bvh-sah']['ns_per_ray']:.1f} times; "
               f"the SAH tree tests {row['bsp']['primitives_per_ray']:.1f} primitives per ray, `bvh-sah` "
               f"{row['bvh-sah']['primitives_per_ray']:.1f}.")

    t = s.largest("soup", "bsp")["triangles"]
    course = ["bvh-sort", "bvh-midpoint", "bvh-sah", "grid", "bsp-midpoint", "bsp"]
    ranked = sorted(course, key=lambda k: s.at("soup", k, t)["ns_per_ray"])
    place = ranked.index("bsp") + 1
    quicker = ranked[:place - 1]
    r = s.at("soup", "bsp", t)
    out.append(f"- **Soups.** The SAH tree's query slope is {s.query('soup', 'bsp'):.2f}, the midpoint tree's "
               f"{s.query('soup', 'bsp-midpoint'):.2f}. At {n(t)} triangles the SAH tree tests "
               f"{r['primitives_per_ray']:.1f} primitives per ray and is "
               + ("the quickest of the course's structures" if place == 1 else
                  f"number {place} of the course's six structures by time per ray, after "
                  + listing(code(k) for k in quicker))
               + f"; `fast` takes {s.at('soup', 'fast', t)['ns_per_ray'] / r['ns_per_ray']:.2f} of its time.")

    mid = s.rows[("stadium", "bsp-midpoint")]
    big = [x for x in mid if x["triangles"] >= 10000]
    out.append(f"- **The stadium.** The SAH tree's query slope is {s.query('stadium', 'bsp'):.2f}, the midpoint "
               f"tree's {s.query('stadium', 'bsp-midpoint'):.2f}: from {n(big[0]['triangles'])} triangles on, "
               f"the midpoint tree tests {span([x['primitives_per_ray'] for x in big], 0)} triangles per ray, the "
               f"SAH tree {span([s.at('stadium', 'bsp', x['triangles'])['primitives_per_ray'] for x in big], 1)}.")
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: complexity_summary.py TEXT OUT_DIR")
    rows, slopes = load(sys.argv[1])
    s = Sweep(rows, slopes)
    for name, lines in (("bvh", bvh(s)), ("grid", grid(s)), ("bsp", bsp(s))):
        with open(f"{sys.argv[2]}/complexity-{name}.md", "w") as f:
            f.write("\n".join(lines) + "\n")


main()
