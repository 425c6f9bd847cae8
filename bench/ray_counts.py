"""The ray and random-number counts chapters 2, 5-9, 17 and 18 quote from --stats and --pick
(./lab bench counts).

    python3 bench/ray_counts.py BIN_DIR OUT_DIR

Writes, into OUT_DIR (book/measured/):

  ch02-pick-middle.md    §2.5: what --pick prints for the middle pixel of a 201x151 image
  ch02-pick-default.md   §2.5: the t of --pick 200,150 at the default 400x300
  ch06-pick.md           §6.7: --pick of a floor pixel in both shadows, trimmed and rounded
  ch13-lens-stripes.md   §13.8: the lens's stripes in pixels, in its middle and beside it
  ch05-skipping-*.md     §5.7: spheres and skipping, whole (dated), and the terms both evaluate
  ch07-depth-*.md        §7.3: mirrors' rays at each --depth, and what they add up to
  ch07-tinted-*.md       §7.7: tinted-sphere's --stats (dated), and its reflection rays
  ch08-*.md              §8.7: glass-sphere's --stats (dated), its rays, glass-block's and tir's
  ch09-instances-*.md    §9.5: instances' --stats (dated), and the bytes sharing saves
  ch06-shadows-stats.md  §6.7: what --stats prints for shadows, whole (it has a time: dated)
  ch06-shadow-rays.md    §6.7: what its counts add up to, and conic's and acne's
  ch17-grazing-stats.md  §17.3: the glossy reflections tried in grazing, and those lost
  ch17-plates-rays.md    §17.5: plates' rays, the same with every plate sharp
  ch17-plates-numbers.md §17.5: plates' random numbers, and the reflections that drew them
  ch18-swept-box.md      §18.1: the search's nodes and primitives per ray, balls moving and still
  ch18-time-numbers.md   §18.2: one time number per camera ray, none when nothing moves

Every count is exact. The relations the prose relies on are checked, and a run that breaks one
fails (exit 1) instead of writing a sentence the prose would contradict.
"""

import json
import os
import sys
import tempfile

import measured
from measured import n, need, stats, tex, write


def without(path, key, tmp):
    """A copy of the scene file with KEY removed from every surface (and glossy materials)."""
    with open(path) as f:
        scene = json.load(f)
    removed = 0
    materials = scene.get("materials", {})
    for part in scene.get("surfaces", []) + list(materials.values() if isinstance(materials, dict) else materials):
        if isinstance(part, dict) and key in part:
            del part[key]
            removed += 1
    need(removed > 0, f"{path} has a '{key}' key to remove")
    out = os.path.join(tmp, f"no-{key}-" + os.path.basename(path))
    with open(out, "w") as f:
        json.dump(scene, f)
    return out


def ch02(bin_dir, out_dir):
    command = ["--scene", "sphere", "--width", "201", "--height", "151", "--pick", "100,75"]
    line = measured.last_line(os.path.join(bin_dir, "ch02"), *command)
    middle = json.loads(line)
    need(middle["hit"] and middle["t"] == 2 and middle["normal"] == [0, 0, 1],
         "the middle pixel's ray meets the sphere at t = 2 exactly, facing the eye")
    write(out_dir, "ch02-pick-middle.md", ["```sh", "$ build/release/bin/ch02 " + " ".join(command), line, "```"])
    pick = json.loads(measured.last_line(os.path.join(bin_dir, "ch02"), "--scene", "sphere", "--pick", "200,150"))
    need(pick["hit"] and 2 < pick["t"] < 2.001, "the pixel beside the centre sees the sphere at a t a little over 2")
    write(out_dir, "ch02-pick-default.md",
          [f"At the default 400×300 there is no middle pixel. `--pick 200,150` is the pixel just right of and "
           f"below the centre, and its $t$ is a little over 2 ({pick['t']:.8g})."])


def transcript(command, line):
    return ["```text", "$ build/release/bin/" + command, line, "```"]


def ch05(bin_dir, out_dir, stamp):
    ch05 = os.path.join(bin_dir, "ch05")
    a, la = stats(ch05, "spheres")
    b, lb = stats(ch05, "skipping")
    need(a["shading"] == b["shading"], "skipping evaluates the terms spheres does")
    need(b["scene_skipped"]["black_lights"] == 1 and b["scene_skipped"]["unused_materials"] == 2,
         "skipping's black light and two unused materials are skipped")
    with tempfile.TemporaryDirectory() as tmp:
        images = []
        for scene in ("spheres", "skipping"):
            measured.run(ch05, "--scene", scene, "-o", os.path.join(tmp, scene + ".png"))
            with open(os.path.join(tmp, scene + ".png"), "rb") as f:
                images.append(f.read())
    need(images[0] == images[1], "spheres and skipping render the same image, byte for byte")
    t = a["shading"]
    need(t["specular_terms"] < t["light_terms"] / 2, "fewer than half the light terms need a highlight")
    write(out_dir, "ch05-skipping-stats.md",
          transcript("ch05 --scene spheres --stats -o /tmp/a.png", la)[:-1] +
          ["$ build/release/bin/ch05 --scene skipping --stats -o /tmp/b.png", lb, "```"], stamp)
    write(out_dir, "ch05-skipping-terms.md",
          [f"Both evaluate {n(t['light_terms'])} light terms and {n(t['specular_terms'])} highlight terms, and the two "
           "images are identical byte for byte."])


def ch07(bin_dir, out_dir, stamp):
    ch07 = os.path.join(bin_dir, "ch07")
    rows, last = [], None
    for depth in range(0, 13):
        s, _ = stats(ch07, "mirrors", "--depth", str(depth))
        need(s["rays"]["camera"] == 120000, "120,000 camera rays at every depth")
        r = (s["rays"]["reflection"], s["rays"]["shadow"], s["rays"]["total"])
        if last is not None:
            need(r[0] >= last[0], "reflection rays never fall with the depth")
        rows.append((depth, r))
        if last == r:
            break
        last = r
    need(rows[-1][1] == rows[-2][1], "a depth past which nothing changes")
    final = rows[-2][0]  # the first depth of the unchanging counts
    while final > 0 and rows[final - 1][1] == rows[final][1]:
        final -= 1
    one, two = rows[1][1][0], rows[2][1][0]
    need(0.5 < one / 120000 < 0.6, "a little over half the camera rays hit a mirror")
    need(0.4 < (two - one) / one < 0.6, "depth 2 adds about half as many again")
    gains = [rows[k][1][0] - rows[k - 1][1][0] for k in range(2, final + 1)]
    need(all(b < a for a, b in zip(gains, gains[1:])), "each later step adds fewer")
    table = ["| `--depth` | reflection rays | shadow rays | total |", "|---|---|---|---|"]
    for depth, (refl, shadow, total) in rows[:final + 1]:
        if depth in (0, 1, 2, 4, 8) or depth == final:
            label = f"{depth} and more" if depth == final else str(depth)
            table.append(f"| {label} | {n(refl)} | {n(shadow)} | {n(total)} |")
    write(out_dir, "ch07-depth-table.md", table)
    write(out_dir, "ch07-depth-mirror.md",
          [f"A little over half the camera rays ({n(one)}) hit a mirror. Depth 2 adds about half as many again, and "
           "each later step adds fewer, because most reflected rays leave the mirrors. They hit the floor, the wall "
           "or a ball, or fly out over the walls into the sky. Only the rays near the vanishing point go on "
           f"bouncing. Depth {final} adds the last {n(rows[final][1][0] - rows[final - 1][1][0])} reflection rays. "
           f"From there on nothing changes, because no ray in this scene is reflected more than {final} times."])
    s, line = stats(ch07, "tinted-sphere")
    need(s["rays"]["refraction"] == 0 and s["rays"]["total"] == sum(s["rays"][k] for k in
                                                                    ("camera", "reflection", "shadow")),
         "tinted-sphere: no refraction rays, the total the sum of the kinds")
    write(out_dir, "ch07-tinted-stats.md", transcript("ch07 --scene tinted-sphere --stats -o /tmp/t.png", line), stamp)
    write(out_dir, "ch07-tinted-reflections.md",
          [f"The {n(s['rays']['reflection'])} reflection rays are the camera rays that hit the gold ball, one each."])


def ch08(bin_dir, out_dir, stamp):
    ch08 = os.path.join(bin_dir, "ch08")
    s, line = stats(ch08, "glass-sphere")
    refl, refr = s["rays"]["reflection"], s["rays"]["refraction"]
    need(refl < refr, "fewer reflection rays than refraction rays in glass-sphere")
    write(out_dir, "ch08-glass-stats.md", transcript("ch08 --scene glass-sphere --stats -o /tmp/x.png", line), stamp)
    write(out_dir, "ch08-glass-rays.md",
          [f"Every glass hit below the depth limit could cast one ray of each kind, but there are fewer reflection "
           f"rays ({n(refl)}) than refraction rays ({n(refr)})."])
    b, _ = stats(ch08, "glass-block")
    t, _ = stats(ch08, "tir")
    write(out_dir, "ch08-block-tir-rays.md",
          [f"`glass-block` casts {n(b['rays']['reflection'])} reflection rays and {n(b['rays']['refraction'])} "
           f"refraction rays, and `tir` {n(t['rays']['reflection'])} and {n(t['rays']['refraction'])}."])


def ch09(bin_dir, out_dir, stamp):
    s, line = stats(os.path.join(bin_dir, "ch09"), "instances")
    inst = s["instancing"]
    need(inst["instances"] == 25 and s["scene_kept"]["triangles"] == 1280, "25 instances of one 1,280-triangle ball")
    need(inst["shared_bytes"] % 24 == 0, "the bytes 24 more copies would take")
    write(out_dir, "ch09-instances-stats.md", transcript("ch09 --scene instances --stats -o /tmp/y.png", line), stamp)
    one = inst["shared_bytes"] // 24
    write(out_dir, "ch09-instances-bytes.md",
          [f"The ball has 642 vertices and 1,280 triangles. With its vertex normals, in {s['real']} precision, it "
           f"takes {n(one)} bytes, and 24 more copies would take $24 \\times {tex(one)} = {tex(24 * one)}$."])


def ch06(bin_dir, out_dir, stamp):
    ch06 = os.path.join(bin_dir, "ch06")
    s, line = stats(ch06, "shadows")
    write(out_dir, "ch06-shadows-stats.md",
          ["```text", "$ build/release/bin/ch06 --scene shadows --stats -o /tmp/a.png", line, "```"], stamp)
    cam, terms, shadow = s["rays"]["camera"], s["shading"]["light_terms"], s["rays"]["shadow"]
    need(s["scene_kept"]["lights"] == 2, "shadows has two lights")
    need(terms % 2 == 0 and terms // 2 < cam, "two light terms per camera ray that hits, and some see the sky")
    need(shadow < terms, "at most one shadow ray per light term, and some lights behind the surface")
    need(s["rays"]["total"] == cam + shadow, "no rays but camera and shadow rays")
    c, _ = stats(ch06, "conic")
    a, _ = stats(ch06, "acne")
    for name, x in (("conic", c), ("acne", a)):
        need(x["rays"]["shadow"] <= x["shading"]["light_terms"], f"{name}: at most one shadow ray per light term")
    write(out_dir, "ch06-shadow-rays.md",
          [f"There are two lights, and {n(terms)} light terms, so {n(terms // 2)} of the {n(cam)} camera rays hit "
           f"something. The rest see the sky. The integrator cast {n(shadow)} shadow rays, one for each light term "
           f"except {n(terms - shadow)}, where the light was behind the surface (§6.2)."])
    write(out_dir, "ch06-conic-acne-rays.md",
          [f"`conic` casts {n(c['rays']['shadow'])} shadow rays for its {n(c['shading']['light_terms'])} light "
           f"terms, and the built-in `acne` {n(a['rays']['shadow'])} for {n(a['shading']['light_terms'])}."])


def ch06_pick(bin_dir, out_dir):
    """§6.7's --pick of a floor pixel in both shadows, trimmed (the fields the prose reads) and
    rounded, with the facts the prose draws from it checked."""
    command = ["--scene", "shadows", "--pick", "200,178"]
    pick = json.loads(measured.last_line(os.path.join(bin_dir, "ch06"), *command))
    tree = pick["tree"]
    point, sun = tree["children"]
    need(pick["surface"] == "floor" and tree["hit"]["surface"] == "floor", "pixel 200,178 of shadows is on the floor")
    need([c["kind"] for c in tree["children"]] == ["shadow", "shadow"] and point["light"] == 0 and sun["light"] == 1,
         "the pixel casts one shadow ray to each light, the point light first")
    need(point["blocked"] and point["blocker"]["surface"] == "red ball" and sun["blocked"]
         and sun["blocker"]["surface"] == "blue ball" and "triangle" in sun["blocker"],
         "the red ball blocks the point light and a triangle of the blue ball the sun")
    need(point["interval"][1] is not None and sun["interval"][1] is None,
         "the point light's ray ends, the sun's does not")
    need(all(abs(c - d * a) < 1e-6 for c, d, a in zip(pick["color"], (0.8, 0.78, 0.72), (0.12, 0.12, 0.15))),
         "the colour is the floor's diffuse colour (0.8, 0.78, 0.72) times the ambient (0.12, 0.12, 0.15)")
    p, o = pick["point"], point["origin"]
    need(p[1] == 0 and o[1] == 2.0 ** -40 and o[0] == p[0] and o[2] == p[2],
         "the floor point has y = 0 and its shadow rays start 2^-40 above it, x and z unmoved")

    def r(x, digits=3):  # a number as the trimmed transcript rounds it
        return "null" if x is None else f"{x:.{digits}g}"

    def v(xs, digits=3):
        return "[" + ", ".join(r(x, digits) for x in xs) + "]"

    lines = ["```text", "$ build/release/bin/ch06 " + " ".join(command),
             f'{{"color": {v(pick["color"])}, "surface": "floor", "point": {v(p)}, ...',
             f' "tree": {{"kind": "camera", "depth": 0, "hit": {{"surface": "floor", '
             f'"t": {tree["hit"]["t"]:.4f}, ...}},',
             '  "children": [']
    for c, last in ((point, False), (sun, True)):
        end = "" if c["interval"][1] is None else f'{c["interval"][1]:.4f}'
        lines.append(f'   {{"kind": "shadow", "light": {c["light"]}, "blocked": true, '
                     f'"interval": [0, {end or "null"}],')
        if not last:
            lines.append(f'    "origin": [{", ".join(repr(x) for x in c["origin"])}],')
        b = c["blocker"]
        triangle = f', "triangle": {b["triangle"]}' if "triangle" in b else ""
        lines.append(f'    "blocker": {{"surface": "{b["surface"]}", "t": {b["t"]:.4f}{triangle}, ...}},')
        lines.append(f'    "weight": {{"of": "{c["weight"]["of"]}", "value": {v(c["weight"]["value"], 2)}}}, '
                     f'"radiance": {v(c["radiance"])}}}{"]}}" if last else ","}')
    lines.append("```")
    write(out_dir, "ch06-pick.md", lines + [
        "",
        f"The point light's ray ends at the light, {point['interval'][1]:.2f} away, and the sun's ray has no end "
        "(`null`)."])


def ch13_lens(bin_dir, out_dir):
    """§13.8's magnifying glass: the stripes' widths in pixels along the row through the lens's
    centre (the image's middle row: the camera looks at it), in the middle and beside the lens."""
    with tempfile.TemporaryDirectory() as tmp:
        image = os.path.join(tmp, "lens.pfm")
        measured.run(os.path.join(bin_dir, "ch13"), "--scene", "lens", "-o", image)
        w, h, values = measured.read_pfm(image)
    # Rows of (r, g, b), top row first (PFM stores the bottom row first).
    rows = [[values[3 * (y * w + x):3 * (y * w + x) + 3] for x in range(w)] for y in range(h)][::-1]
    blue = [r[2] > r[0] + 0.1 for r in rows[h // 2]]  # the wall's blue stripes against its cream ones
    runs, start = [], 0  # (first pixel, width) of each stripe
    for x in range(1, w + 1):
        if x == w or blue[x] != blue[start]:
            runs.append((start, x - start))
            start = x
    middle = next(width for first, width in runs if first <= w // 2 < first + width)
    beside = sorted({width for _, width in runs[1:6] + runs[-6:-1]})  # whole stripes at both ends, off the lens
    need(len(beside) <= 2 and beside[-1] - beside[0] <= 1,
         "the stripes beside the lens are all one width, give or take a pixel")
    need(1.6 < middle / (sum(beside) / len(beside)) < 2.2,
         "the stripes through the middle look about 1.9 times as wide")
    write(out_dir, "ch13-lens-stripes.md",
          [f"The stripes through the middle of the lens should look about 1.9 times as wide as those beside it, and "
           f"at {w} × {h} they are {middle} pixels wide against {' or '.join(map(str, beside))}."])


def ch17(bin_dir, out_dir):
    ch17 = os.path.join(bin_dir, "ch17")
    g, _ = stats(ch17, "grazing")
    glossy, refl = g["random_numbers"]["glossy"], g["rays"]["reflection"]
    need((g["width"], g["height"]) == (400, 300), "grazing renders at 400 x 300")
    need(glossy % 2 == 0 and refl < glossy // 2, "two numbers per glossy reflection, and some lost below the floor")
    tried = glossy // 2
    write(out_dir, "ch17-grazing-stats.md",
          [f"Over the whole {g['width']} × {g['height']} picture, `--stats` counts {n(glossy)} glossy numbers, that "
           f"is {n(tried)} glossy reflections tried, and {n(refl)} reflection rays. So {n(tried - refl)} of them "
           f"({100 * (tried - refl) / tried:.1f} %) pointed below the floor and cast nothing."])

    plates = "chapters/ch17_glossy_reflection/scenes/plates.json"
    p, _ = stats(ch17, "plates")
    with tempfile.TemporaryDirectory() as tmp:
        q, _ = stats(ch17, without(plates, "glossy", tmp))
    need((p["width"], p["height"], p["spp"]) == (400, 300, 16), "plates renders at 400 x 300, 16 samples per pixel")
    need(p["rays"] == q["rays"], "the glossy plates cast exactly the rays the sharp ones cast")
    need(q["random_numbers"]["glossy"] == 0, "sharp plates draw no glossy number")
    need(p["random_numbers"]["pixel"] == 2 * p["rays"]["camera"], "two film numbers per camera ray")
    pg, pr = p["random_numbers"]["glossy"], p["rays"]["reflection"]
    need(pg % 2 == 0 and pg // 2 < pr, "two numbers per glossy reflection; the sharp plate's reflections draw none")
    rays = ["camera", "reflection", "refraction", "shadow", "total"]
    dims = ["glossy", "lens", "light", "other", "pixel", "time"]
    compact = lambda d, keys: "{" + ",".join(f'"{k}":{json.dumps(d[k])}' for k in keys) + "}"
    write(out_dir, "ch17-plates-rays.md", ["```text", f'"rays":{compact(p["rays"], rays)}', "```"])
    write(out_dir, "ch17-plates-numbers.md",
          ["```text", f'"random_numbers":{compact(p["random_numbers"], dims)}', "```", "",
           "`random_numbers` counts the numbers each dimension drew for samples: two per camera ray for the pixel, "
           f"and two per glossy reflection. The satin and brushed plates took {n(pg // 2)} of the {n(pr)} "
           "reflections. The sharp plate drew nothing."])


def ch18(bin_dir, out_dir):
    ch18 = os.path.join(bin_dir, "ch18")
    balls = "chapters/ch18_motion_blur/scenes/balls.json"
    m, _ = stats(ch18, "balls")
    with tempfile.TemporaryDirectory() as tmp:
        s, _ = stats(ch18, without(balls, "moves_to", tmp))
    ms, ss = m["search"], s["search"]
    need(ms["nodes_per_ray"] >= ss["nodes_per_ray"] and ms["primitives_per_ray"] > ss["primitives_per_ray"],
         "the swept boxes make the search test more primitives per ray, and no fewer boxes")
    more = ms["primitives_per_ray"] / ss["primitives_per_ray"] - 1
    if ms["nodes_per_ray"] > ss["nodes_per_ray"]:
        sentence = (f"With `--stats`, the search visits {ms['nodes_per_ray']:.2f} nodes and tests "
                    f"{ms['primitives_per_ray']:.3f} primitives per ray in `balls`, against {ss['nodes_per_ray']:.2f} and "
                    f"{ss['primitives_per_ray']:.3f} in the still copy. That is {100 * more:.0f} % more primitive tests per "
                    "ray, for two balls that move 1 and 2 units.")
    else:
        # A scene of a few spheres is one wide node: every ray tests its eight boxes, swept or not.
        need(m["accel"]["nodes"] == 1 and s["accel"]["nodes"] == 1, "the same boxes per ray only when one node holds all")
        sentence = (f"With `--stats`, the search tests {ms['primitives_per_ray']:.3f} primitives per ray in `balls`, "
                    f"against {ss['primitives_per_ray']:.3f} in the still copy: {100 * more:.0f} % more, for two balls "
                    f"that move 1 and 2 units. The boxes it tests are {ms['nodes_per_ray']:.0f} per ray in both: the "
                    f"{m['accel']['primitives']} surfaces fit under one node of eight boxes (§10.5), so what the larger "
                    "boxes cost shows in the spheres tested, not in the boxes.")
    write(out_dir, "ch18-swept-box.md", [sentence])
    need(m["random_numbers"]["time"] == m["rays"]["camera"], "one time number per camera ray in balls")
    need(s["random_numbers"]["time"] == 0, "no time number when nothing moves")
    write(out_dir, "ch18-time-numbers.md",
          [f"`random_numbers.time` is 0 for every scene without `moves_to`, and for `balls` at {m['width']} × "
           f"{m['height']} with {m['spp']} samples per pixel it is {n(m['random_numbers']['time'])}, one number per "
           "camera ray."])


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: ray_counts.py BIN_DIR OUT_DIR")
    bin_dir, out_dir = sys.argv[1:]
    stamp = measured.stamp("counts")
    os.makedirs(out_dir, exist_ok=True)
    ch02(bin_dir, out_dir)
    ch05(bin_dir, out_dir, stamp)
    ch07(bin_dir, out_dir, stamp)
    ch08(bin_dir, out_dir, stamp)
    ch09(bin_dir, out_dir, stamp)
    ch06(bin_dir, out_dir, stamp)
    ch06_pick(bin_dir, out_dir)
    ch13_lens(bin_dir, out_dir)
    ch17(bin_dir, out_dir)
    ch18(bin_dir, out_dir)


main()
