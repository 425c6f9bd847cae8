"""The chapters' scenes under each search structure, measured with --stats (./lab bench scenes).

    python3 bench/scene_stats.py BIN_DIR OUT_DIR

Renders each scene the book discusses with each structure it compares, at the default
400x300, and writes one Markdown table per scene into OUT_DIR (book/measured/), which the
chapter includes, with a few sentences computed from the table. The counts (nodes, bytes,
boxes and primitives tested per ray) are exact: the same on every machine and every run, until
the code changes. Times are on one thread, best of three, and quoted only as ratios to
`fast` measured in the same run: on a shared machine the absolute times move, the ratios
less.
"""

import filecmp
import os
import sys
import tempfile

import measured

# (chapter binary, scene, structures in the order of the table, whether all must give the same
# image: not for a scene shaded by cost, whose colours are the work each structure does).
SCENES = [
    ("ch12", "city", ["bvh-sah", "bsp-midpoint", "bsp", "fast"], True),
    ("ch12", "sticks", ["none", "bvh-sah", "grid", "bsp", "bsp-midpoint", "fast"], True),
    ("ch12", "stadium", ["bvh-sah", "grid", "bsp-midpoint", "bsp", "fast"], False),
]
ROUNDS = 3


def render(binary, scene, accel, image):
    best = None
    for _ in range(ROUNDS):
        stats, _ = measured.stats(binary, scene, "--accel", accel, "--threads", "1", image=image)
        if best is None or stats["seconds"] < best["seconds"]:
            best = stats
    return best


def table(chapter, scene, results):
    fast = results["fast"]["seconds"]
    lines = [f"`{chapter} --scene {scene} --stats`, 400×300, one thread, best of {ROUNDS}; nodes per ray counts "
             "every box or node visited (cells for the grid), primitives per ray every primitive tested.", "",
             "| `--accel` | nodes | depth | bytes | nodes per ray | primitives per ray | time / `fast` |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for accel, st in results.items():
        a = st["accel"] or {}
        nodes = a.get("nodes", 0)
        label = f"{nodes:,} (cells)" if accel == "grid" else f"{nodes:,}"
        depth = a.get("depth", 0) if accel not in ("none", "grid") else "–"
        lines.append(f"| `{accel}` | {label} | {depth} | {a.get('bytes', 0):,} | "
                     f"{st['search']['nodes_per_ray']:.1f} | {st['search']['primitives_per_ray']:.1f} | "
                     f"{st['seconds'] / fast:.2f} |")
    return lines


def notes(scene, results, same):
    r = {k: (v["search"]["nodes_per_ray"], v["search"]["primitives_per_ray"], v["accel"] or {}) for k, v in
         results.items()}
    out = []
    if same is not None:
        out.append(f"All {len(results)} give the same image, bit for bit." if same else
                   f"The {len(results)} images are not all the same, bit for bit.")
    if "bsp" in r and "bvh-sah" in r and "fast" in r:
        p = r["bsp"][1] / r["bvh-sah"][1]
        b = r["bsp"][2].get("bytes", 0) / max(1, r["bvh-sah"][2].get("bytes", 0))
        out.append(f"The SAH tree (`bsp`) tests {p:.1f} times as many primitives per ray as the BVH built by the "
                   f"same heuristic (`bvh-sah`), in {b:.1f} times the memory, and "
                   f"{r['bsp'][1] / r['fast'][1]:.1f} times as many as `fast`.")
    others = [k for k in ("bsp-midpoint", "grid") if k in r]
    if "bsp" in r and others:
        fewer = [k for k in others if r["bsp"][1] < r[k][1]]
        more = [k for k in others if k not in fewer]
        parts = []
        if fewer:
            parts.append("fewer than " + " and ".join(f"`{k}`" for k in fewer))
        if more:
            parts.append("at least as many as " + " and ".join(f"`{k}`" for k in more))
        out.append("It tests " + ", but ".join(parts) + ".")
    return " ".join(out)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: scene_stats.py BIN_DIR OUT_DIR")
    bin_dir, out_dir = sys.argv[1:]
    stamp = measured.stamp("scenes")
    with tempfile.TemporaryDirectory() as tmp:
        for chapter, scene, accels, must_match in SCENES:
            results, images = {}, []
            for accel in accels:
                image = os.path.join(tmp, f"{scene}-{accel}.png")
                print(f"{chapter} {scene} {accel}", file=sys.stderr)
                results[accel] = render(os.path.join(bin_dir, chapter), scene, accel, image)
                images.append(image)
            same = all(filecmp.cmp(images[0], i, shallow=False) for i in images[1:]) if must_match else None
            measured.write(out_dir, f"{chapter}-{scene}.md",
                           table(chapter, scene, results) + ["", notes(scene, results, same)], stamp)


main()
