"""The neutral scenes of `./lab bench peers` (bench/peers/peers.py): each is a plain dict that
rtlab_scene.py, tachyon_scene.py and povray_scene.py turn into each renderer's own file, so the
three renderers are handed the same geometry, camera, lights and materials.

A scene holds:
  camera     eye, target, up (right-handed, y up, as rtlab's files) and vfov in degrees
  background a colour; ambient a grey level a (every surface adds a times its diffuse colour)
  depth      how many reflections deep a pixel may go (rtlab's max_depth)
  min_weight a secondary ray that would carry less than this share of its pixel is not cast:
             rtlab's min_reach (its default, 1/1024), POV-Ray's adc_bailout (whose own default,
             1/255, cuts glass's trees short: a Fresnel reflection of 4 % off a sphere seen
             through another is 0.0016 of its pixel); Tachyon has no such cut
  materials  name -> diffuse colour, highlight (grey weight, Blinn exponent), mirror (grey
             weight) or glass (index of refraction; clear, no diffuse colour)
  lights     point lights: position, colour (no fall-off)
  spheres    (centre, radius, material); triangles ((a, b, c), material); meshes (OBJ file,
             material): flat shaded, as the OBJ gives no vertex normals
Grey weights, not colours, for the highlight and the mirror: Tachyon takes a single number for
each, so the three can only agree on grey ones."""
import math
import random

MIN_WEIGHT = 1 / 1024  # rtlab's min_reach (render/scene.hpp), which rtlab_scene.py leaves at its default


def material(diffuse=(0, 0, 0), highlight=0.0, exponent=32.0, mirror=0.0, glass=None):
    return {"diffuse": list(diffuse), "highlight": highlight, "exponent": exponent, "mirror": mirror, "glass": glass}


def rtiow(seed, glass=True):
    """The cover of Ray Tracing in One Weekend (book 1's final scene), drawn from Python's own
    seeded generator so every run and every renderer gets the same spheres: a 22 x 22 grid of
    small spheres jittered in their cells, 80% diffuse, 15% metal, 5% glass, three large ones and
    a ground sphere of radius 1000. The book lights it by its sky alone (path tracing); a Whitted
    renderer needs lights, so it gets two point lights and a sky-blue background. Metal is a
    grey mirror over a dark tint of its colour, with a highlight; with glass=False every glass
    sphere becomes a clear mirror (Tachyon cannot refract)."""
    rnd = random.Random(seed)
    glass_mat = material(glass=1.5) if glass else material(mirror=0.9)
    mats = {"ground": material((0.5, 0.5, 0.5)), "glass": glass_mat}
    spheres = [((0, -1000, 0), 1000, "ground")]
    for a in range(-11, 11):
        for b in range(-11, 11):
            choose = rnd.random()
            centre = (a + 0.9 * rnd.random(), 0.2, b + 0.9 * rnd.random())
            if math.dist(centre, (4, 0.2, 0)) <= 0.9:
                continue
            name = f"m{len(mats)}"
            if choose < 0.8:
                mats[name] = material([rnd.random() * rnd.random() for _ in range(3)])
            elif choose < 0.95:
                albedo = [0.5 + 0.5 * rnd.random() for _ in range(3)]
                mats[name] = material([0.2 * c for c in albedo], highlight=0.5, exponent=50, mirror=0.7)
            else:
                name = "glass"
            spheres.append((centre, 0.2, name))
    mats["big_diffuse"] = material((0.4, 0.2, 0.1))
    mats["big_metal"] = material((0.14, 0.12, 0.1), highlight=0.5, exponent=50, mirror=0.8)
    spheres += [((0, 1, 0), 1.0, "glass"), ((-4, 1, 0), 1.0, "big_diffuse"), ((4, 1, 0), 1.0, "big_metal")]
    used = {s[2] for s in spheres}
    return {
        "description": f"RTIOW book 1's cover, seed {seed}, {'with glass' if glass else 'glass made mirrors'}",
        "camera": {"eye": (13, 2, 3), "target": (0, 0, 0), "up": (0, 1, 0), "vfov": 20},
        "background": (0.5, 0.7, 1.0), "ambient": 0.1, "depth": 5, "min_weight": MIN_WEIGHT,
        "materials": {k: v for k, v in mats.items() if k in used},
        "lights": [{"position": (10, 15, 8), "color": (0.7, 0.7, 0.7)},
                   {"position": (-8, 12, 10), "color": (0.4, 0.4, 0.4)}],
        "spheres": spheres, "triangles": [], "meshes": [],
    }


def obj_bounds(path):
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                p = [float(x) for x in line.split()[1:4]]
                lo = [min(a, b) for a, b in zip(lo, p)]
                hi = [max(a, b) for a, b in zip(hi, p)]
    return lo, hi


def bunny(obj):
    """The Stanford bunny on a mirror floor (two triangles just under its lowest vertex), one
    point light: every camera ray that meets the floor casts a reflection ray back up at the
    bunny, and every hit a shadow ray through the 69,451 triangles."""
    lo, hi = obj_bounds(obj)
    y, s = lo[1] - 1e-4, 0.6
    a, b, c, d = (-s, y, -s), (s, y, -s), (s, y, s), (-s, y, s)
    return {
        "description": "the Stanford bunny on a mirror floor",
        "camera": {"eye": (-0.05, 0.16, 0.36), "target": (-0.017, 0.095, 0), "up": (0, 1, 0), "vfov": 35},
        "background": (0.3, 0.35, 0.45), "ambient": 0.1, "depth": 5, "min_weight": MIN_WEIGHT,
        "materials": {"clay": material((0.75, 0.7, 0.65), highlight=0.3, exponent=40),
                      "floor": material((0.1, 0.1, 0.12), mirror=0.8)},
        "lights": [{"position": (0.3, 0.5, 0.4), "color": (1, 1, 1)}],
        "spheres": [], "triangles": [((a, b, c), "floor"), ((a, c, d), "floor")],
        "meshes": [(obj, "clay")],
    }


def many_lights(count=32):
    """A 10 x 10 grid of diffuse spheres with highlights on a grey ground sphere, lit by `count`
    coloured point lights on a ring above them: every hit casts `count` shadow rays, so this
    scene measures the shadow test and the light loop, not recursion (no mirrors)."""
    mats = {"ground": material((0.6, 0.6, 0.6))}
    spheres = [((0, -1000, 0), 1000, "ground")]
    for i in range(10):
        for j in range(10):
            name = f"s{(i + j) % 3}"
            spheres.append(((i - 4.5, 0.35, j - 4.5), 0.35, name))
    mats["s0"] = material((0.8, 0.3, 0.2), highlight=0.4, exponent=40)
    mats["s1"] = material((0.2, 0.7, 0.3), highlight=0.4, exponent=40)
    mats["s2"] = material((0.2, 0.3, 0.8), highlight=0.4, exponent=40)
    lights = []
    for k in range(count):
        angle = 2 * math.pi * k / count
        hue = [0.5 + 0.5 * math.cos(angle + p) for p in (0, 2.1, 4.2)]
        lights.append({"position": (8 * math.cos(angle), 4 + (k % 3), 8 * math.sin(angle)),
                       "color": [2.0 / count * h for h in hue]})
    return {
        "description": f"100 spheres under {count} point lights",
        "camera": {"eye": (0, 9, 12), "target": (0, 0, 0), "up": (0, 1, 0), "vfov": 45},
        "background": (0.05, 0.05, 0.08), "ambient": 0.05, "depth": 5, "min_weight": MIN_WEIGHT,
        "materials": mats, "lights": lights, "spheres": spheres, "triangles": [], "meshes": [],
    }


def all_scenes(bunny_obj, seed=1):
    """name -> scene, in the table's order; the bunny only when its OBJ is there."""
    scenes = {"rtiow-glass": rtiow(seed, glass=True), "rtiow-mirrors": rtiow(seed, glass=False)}
    if bunny_obj:
        scenes["bunny-mirror"] = bunny(bunny_obj)
    scenes["lights-32"] = many_lights(32)
    return scenes
