"""The counts chapters 15 and 16 quote from --stats, and what an area light costs in time
(./lab bench counts).

    python3 bench/stats_counts.py BIN_DIR OUT_DIR

Renders the scenes §15.4 and §16.5 discuss with --stats (and picks §16.1's pixel) and writes,
into OUT_DIR (book/measured/), the trimmed --stats excerpts and the sentences that quote them:

  ch15-penumbra-stats.md   penumbra at 64x48: the excerpt and what its counts add up to
  ch15-point-light.md      penumbra with a point light at the light's centre
  ch15-fence-stats.md      fence, where every camera ray makes a light term
  ch15-area-light-time.md  penumbra at 400x300 on one thread, area light against point light
  ch16-row-stats.md        row at 64x48: the excerpt and what its counts add up to
  ch16-pick.md             the pinhole ray --pick traces in row (§16.1)
  ch02-stats-example.md    what --stats prints for chapter 2's first scene (§0.4)

Every count is exact (the same on every machine, until the code or the scene changes). The
relations the chapters' prose relies on (two light numbers per light term, one shadow ray at
most per light term, the area light casting more shadow rays than the point light, no lens
or time numbers where nothing needs them) are checked here, and a run that breaks one fails
(exit 1) instead of writing a sentence the prose would contradict. Times are processor time,
best of five, quoted only as a ratio measured in the same run, the two renders alternating.
"""

import json
import os
import sys
import tempfile

import measured
from measured import n, need, stats, tex, write

ROUNDS = 5


def compact(d, keys):
    return "{" + ",".join(f'"{k}":{json.dumps(d[k])}' for k in keys) + "}"


def excerpt(command, st, shading):
    dims = ["glossy", "lens", "light", "other", "pixel", "time"]
    rays = ["camera", "reflection", "refraction", "shadow", "total"]
    lines = ["```text", f"$ {command}",
             f'{{... "random_numbers":{compact(st["random_numbers"], dims)},',
             f' "rays":{compact(st["rays"], rays)}, ...']
    if shading:
        lines.append(f' "shading":{compact(st["shading"], ["light_terms", "specular_terms"])}, "spp":{st["spp"]}, ...}}')
    else:
        lines[-1] += "}"
    return lines + ["```"]


def point_light_scene(path, tmp):
    """The scene with its parallelogram light replaced by a point light at the light's centre."""
    with open(path) as f:
        scene = json.load(f)
    light = scene["lights"][0]
    need(light["type"] == "parallelogram", f"{path}'s light is a parallelogram")
    centre = [c + (a + b) / 2 for c, a, b in zip(light["corner"], light["edge_a"], light["edge_b"])]
    scene["lights"] = [{"type": "point", "position": centre, "color": light["color"]}]
    out = os.path.join(tmp, "penumbra-point.json")
    with open(out, "w") as f:
        json.dump(scene, f)
    return out, centre


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: stats_counts.py BIN_DIR OUT_DIR")
    bin_dir, out_dir = sys.argv[1:]
    ch15, ch16 = os.path.join(bin_dir, "ch15"), os.path.join(bin_dir, "ch16")
    stamp = measured.stamp("counts")
    small = ["--width", "64", "--height", "48"]
    os.makedirs(out_dir, exist_ok=True)
    penumbra_file = "chapters/ch15_soft_shadows/scenes/penumbra.json"

    # §15.4: penumbra's counts.
    p, _ = stats(ch15, "penumbra", *small)
    cam, terms = p["rays"]["camera"], p["shading"]["light_terms"]
    light, shadow = p["random_numbers"]["light"], p["rays"]["shadow"]
    need(cam == 64 * 48 * p["spp"], "one camera ray per sample")
    need(p["random_numbers"]["pixel"] == 2 * cam, "two film numbers per camera ray")
    need(light == 2 * terms, "two light numbers per light term")
    need(shadow <= terms, "at most one shadow ray per light term")
    need(p["random_numbers"]["lens"] == 0 and p["random_numbers"]["time"] == 0, "no lens or time numbers")
    write(out_dir, "ch15-penumbra-stats.md",
          excerpt("build/release/bin/ch15 --scene penumbra --width 64 --height 48 --stats -o /tmp/p.png", p, True) +
          ["", f"There are $64 \\times 48 \\times {p['spp']} = {tex(cam)}$ camera rays, and each "
           f"takes two numbers for its film position. {n(terms)} of them hit something and shade it with the one "
           f"light, and each of those draws exactly two numbers in the light dimension, one point of the light's "
           f"square: {n(light)}. The shadow rays are one per light term, less the {n(terms - shadow)} whose light "
           f"point lay behind the surface (§6.2)."])

    # §15.4: the same with a point light, and fence.
    with tempfile.TemporaryDirectory() as tmp:
        point_file, centre = point_light_scene(penumbra_file, tmp)
        q, _ = stats(ch15, point_file, *small)
        need(q["shading"]["light_terms"] == terms, "the point light has the area light's light terms")
        need(q["random_numbers"]["light"] == 0, "a point light draws no light number")
        need(q["rays"]["shadow"] < shadow, "the area light casts more shadow rays than the point light")
        f, _ = stats(ch15, "fence", *small)
        fcam, fterms = f["rays"]["camera"], f["shading"]["light_terms"]
        need(fterms == fcam and f["rays"]["shadow"] == fcam, "in fence every camera ray makes a light term")
        write(out_dir, "ch15-point-light.md",
              [f"With the light replaced by a point light at its centre, the light terms are the same, {n(terms)}, "
               f"the light dimension draws nothing, and there are {n(q['rays']['shadow'])} shadow rays. The area "
               f"light casts {n(shadow - q['rays']['shadow'])} more."])
        write(out_dir, "ch15-fence-stats.md",
              [f"In `fence` every camera ray hits the floor or a slat and every point faces the light: {n(fterms)} "
               f"light terms, {n(f['random_numbers']['light'])} numbers and {n(f['rays']['shadow'])} shadow rays."])

        # §15.4: the time, as a ratio (absolute times move with the machine's load).
        # The two alternate, round after round, so that both see the same load.
        one = ["--threads", "1"]
        runs = [(stats(ch15, "penumbra", *one)[0], stats(ch15, point_file, *one)[0]) for _ in range(ROUNDS)]
        a = min(r[0]["cpu_seconds"] for r in runs)
        b = min(r[1]["cpu_seconds"] for r in runs)
        shape = runs[0][0]
        write(out_dir, "ch15-area-light-time.md",
              [f"At {shape['width']} × {shape['height']}, {shape['spp']} samples per pixel, on one thread, in "
               f"the {shape['real']} build, `penumbra` took {a / b:.2f} times as long with its area light as with "
               f"the point light (processor time of the whole run, best of {ROUNDS}, the two alternating, on a "
               f"machine other programs share: only the ratio is quoted)."], stamp)

    # §0.4: what --stats prints, whole.
    with tempfile.TemporaryDirectory() as tmp:
        line = measured.last_line(os.path.join(bin_dir, "ch02"), "--stats", "-o", os.path.join(tmp, "s.png"))
    json.loads(line)
    write(out_dir, "ch02-stats-example.md", ["```sh", "$ build/release/bin/ch02 --stats -o /tmp/s.png", line, "```"],
          stamp)

    # §16.1: the pinhole ray --pick traces through a pixel of row.
    pick = json.loads(measured.run(ch16, "--scene", "row", "--pick", "228,157"))
    need(pick["surface"] == "ball 3", "row's pixel (228, 157) sees the third ball")
    write(out_dir, "ch16-pick.md",
          [f"In `row`, `--pick 228,157` finds the third ball at $t = {pick['t']:.2f}$, its front surface's depth "
           f"(here $d = 1$)."])

    # §16.5: row's counts.
    r, _ = stats(ch16, "row", *small)
    rcam = r["rays"]["camera"]
    need(r["random_numbers"]["lens"] == 2 * rcam and r["random_numbers"]["pixel"] == 2 * rcam,
         "two film and two lens numbers per camera ray")
    need(r["random_numbers"]["light"] == 0 and r["random_numbers"]["time"] == 0, "no light or time numbers")
    write(out_dir, "ch16-row-stats.md",
          excerpt("build/release/bin/ch16 --scene row --width 64 --height 48 --stats -o /tmp/r.png", r, False) +
          ["", f"Each of the {n(rcam)} camera rays draws two numbers for its film position and two for its place "
           f"on the lens."])


main()
