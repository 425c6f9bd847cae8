#!/usr/bin/env python3
"""./lab bench peers: rtlab against the two Whitted ray tracers in Debian, Tachyon 0.99 and
POV-Ray 3.7, on the same scenes (bench/peers/scenes.py, written out for each by
rtlab_scene.py, tachyon_scene.py and povray_scene.py): same resolution, one sample per pixel
(at the pixel's centre), the same recursion depth, shadows.

  bench/peers/peers.py BIN_DIR [--runs N] [--size WxH] [--bunny OBJ] [--out DIR]

First each renderer renders each scene once into a linear image, and the images are compared
with rtlab's (images.py). Then the timed renders: RUNS rounds, and in each round every scene,
on 1 and 2 threads, every renderer in turn (the order turning each round), each one process
writing the PNG a user would get. Render time is each renderer's own report of its pixel loop:
rtlab's --stats "seconds", Tachyon's "Ray Tracing Time", POV-Ray's "Trace Time"; process time is
the whole process's wall time (reading the scene, building, rendering, writing the PNG). The
table gives medians over the rounds and each peer's time over rtlab's (above 1: rtlab is faster)."""
import argparse
import os
import re
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import images  # noqa: E402
from povray_scene import povray_scene  # noqa: E402
from rtlab_scene import rtlab_scene  # noqa: E402
from scenes import all_scenes  # noqa: E402
from tachyon_scene import tachyon_scene  # noqa: E402

RENDERERS = ("rtlab", "tachyon", "povray")


def command(renderer, args, base, threads, image, compare=False):
    """The command line that renders scene BASE.* into IMAGE, and how its output names its render time."""
    w, h = args.width, args.height
    if renderer == "rtlab":
        return [f"{args.bin}/ch10", "--scene", base + ".json", "--width", str(w), "--height", str(h), "--spp", "1",
                "--threads", str(threads), "--stats", "-o", image]
    if renderer == "tachyon":
        return ["tachyon", base + ".dat", "-numthreads", str(threads), "-format", "PPM48" if compare else "PNG",
                "-o", image]
    return ["povray", "-D", f"+I{base}.pov", f"+O{image}", f"+W{w}", f"+H{h}", "-A", f"+WT{threads}",
            "+FP16", "File_Gamma=1.0"] if compare else \
        ["povray", "-D", f"+I{base}.pov", f"+O{image}", f"+W{w}", f"+H{h}", "-A", f"+WT{threads}",
         "+FN8", "File_Gamma=sRGB"]


def render_seconds(renderer, text):
    pattern = {"rtlab": r'"seconds":([0-9.e+-]+)', "tachyon": r"Ray Tracing Time:\s+([0-9.]+) seconds",
               "povray": r"Trace Time:.*\(([0-9.]+) seconds\)"}[renderer]
    m = re.search(pattern, text)
    if not m:
        raise RuntimeError(f"peers: no render time in {renderer}'s output:\n{text}")
    return float(m.group(1))


def run(cmd):
    start = time.perf_counter()
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.perf_counter() - start
    if p.returncode != 0:
        raise RuntimeError(f"peers: {' '.join(cmd)} failed ({p.returncode}):\n{p.stdout[-2000:]}")
    return p.stdout, wall


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("bin")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--size", default="1280x720")
    ap.add_argument("--bunny", default="")
    ap.add_argument("--out", default="out/bench/peers")
    args = ap.parse_args()
    if not re.fullmatch(r"[1-9][0-9]*x[1-9][0-9]*", args.size) or args.runs < 1:
        print("peers: --size must be WxH and --runs a whole number above 0", file=sys.stderr)
        sys.exit(2)
    args.width, args.height = (int(x) for x in args.size.split("x"))
    if not os.access(f"{args.bin}/ch10", os.X_OK):
        print(f"peers: no chapter program {args.bin}/ch10 (build the release preset)", file=sys.stderr)
        sys.exit(2)
    if args.bunny and not os.path.isfile(args.bunny):
        print(f"peers: no bunny at {args.bunny}: its row is left out", file=sys.stderr)
        args.bunny = ""
    os.makedirs(args.out, exist_ok=True)

    scenes = all_scenes(args.bunny)
    who = {}  # scene -> the renderers that can render it
    for name, scene in scenes.items():
        base = os.path.join(args.out, name)
        open(base + ".json", "w").write(rtlab_scene(scene))
        open(base + ".pov", "w").write(povray_scene(scene, args.width, args.height))
        who[name] = ["rtlab", "povray"]
        if not any(m["glass"] for m in scene["materials"].values()):
            open(base + ".dat", "w").write(tachyon_scene(scene, args.width, args.height))
            who[name].insert(1, "tachyon")

    load = open("/proc/loadavg").read().split()[0]
    print(f"{args.width}x{args.height}, 1 sample per pixel, depth 5, shadows; Tachyon 0.99 and POV-Ray 3.7 (Debian 12)")
    print(f"load average {load} at the start")
    print()
    print("Do the images agree? Each peer's image against rtlab's, as 8-bit sRGB: mean absolute")
    print("difference in codes (0-255) and the share of pixels within 16 codes on every channel.")
    print(f"{'scene':<15} {'peer':<8} {'mean diff':>9} {'agree':>7}")
    ext = {"rtlab": ".pfm", "tachyon": ".ppm", "povray": ".ppm"}
    read = {"rtlab": images.read_pfm, "tachyon": images.read_ppm, "povray": images.read_ppm}
    for name in scenes:
        base = os.path.join(args.out, name)
        pics = {}
        for r in who[name]:
            image = f"{base}-{r}{ext[r]}"
            run(command(r, args, base, 2, image, compare=True))
            pics[r] = read[r](image)
        for r in who[name][1:]:
            mad, agree = images.compare(pics["rtlab"], pics[r])
            print(f"{name:<15} {r:<8} {mad:9.2f} {100 * agree:6.1f}%")
        images.write_png(f"{base}-compare.png", *images.side_by_side([pics[r] for r in who[name]]))

    times = {}  # (scene, threads, renderer) -> ([render s], [process s])
    for k in range(args.runs):
        order = RENDERERS[k % 3:] + RENDERERS[:k % 3]
        for name in scenes:
            base = os.path.join(args.out, name)
            for threads in (1, 2):
                for r in order:
                    if r not in who[name]:
                        continue
                    text, wall = run(command(r, args, base, threads, f"{base}-{r}.png"))
                    t = times.setdefault((name, threads, r), ([], []))
                    t[0].append(render_seconds(r, text))
                    t[1].append(wall)

    print()
    print(f"Medians of {args.runs} rounds, seconds; x = the peer's time / rtlab's (above 1: rtlab is faster).")
    print(f"{'scene':<15} {'thr':>3} | {'render: rtlab':>13} {'tachyon':>8} {'x':>5} {'povray':>7} {'x':>5}"
          f" | {'process: rtlab':>14} {'tachyon':>8} {'x':>5} {'povray':>7} {'x':>5}")
    for name in scenes:
        for threads in (1, 2):
            cells = []
            for which in (0, 1):
                base_t = statistics.median(times[(name, threads, "rtlab")][which])
                cells.append(f"{base_t:{13 + which}.3f}")
                for r in ("tachyon", "povray"):
                    if (name, threads, r) in times:
                        t = statistics.median(times[(name, threads, r)][which])
                        cells.append(f"{t:{8 if r == 'tachyon' else 7}.3f} {t / base_t:5.2f}")
                    else:
                        cells.append(f"{'-':>{8 if r == 'tachyon' else 7}} {'-':>5}")
            print(f"{name:<15} {threads:>3} | {' '.join(cells[0:3])} | {' '.join(cells[3:6])}")

    # The sentences the book reads the table by (§10.10): every row a peer wins.
    print()
    for r in ("tachyon", "povray"):
        lost = []
        for name in scenes:
            for threads in (1, 2):
                if (name, threads, r) not in times:
                    continue
                for which, what in ((0, "render"), (1, "process")):
                    ratio = statistics.median(times[(name, threads, r)][which]) / \
                        statistics.median(times[(name, threads, "rtlab")][which])
                    if ratio < 1:
                        lost.append(f"{name} {what} on {threads} thread{'s' if threads > 1 else ''}"
                                    f" (rtlab takes {1 / ratio:.2f}x {r}'s time)")
        print(f"{r} is faster than rtlab on: " + ("; ".join(lost) if lost else "no row") + ".")


if __name__ == "__main__":
    main()
