"""A neutral scene (scenes.py) as a Tachyon .dat file (Tachyon 0.99, Debian's `tachyon`).

Tachyon's camera is left-handed (a point at +x shows on the left of a camera looking down -z), so
the scene is written with every z negated: the mirror image of a mirrored world is the world
again. Its ZOOM sets the image plane's half-height to 0.5 / ZOOM at distance 1 (measured: the
half-width follows the resolution's aspect), so ZOOM = 0.5 / tan(vfov / 2). Its rays go through
pixel corners, not centres; the view direction is turned by half a pixel to make up for it.
RAYDEPTH counts the camera ray, rtlab's max_depth does not: RAYDEPTH = depth + 1 (checked: two
facing mirrors show as many spheres in both). A mirror ray past the limit is not cast by rtlab
(nothing added) but brings back the background in Tachyon: in a corridor of mirrors, Tachyon's
deepest reflections are the background's colour where rtlab's are black.
Shading: colour x (AMBIENT + DIFFUSE x sum of unshadowed lights' n.l) + PHONG highlights (Blinn's
half vector, Tachyon's default) + SPECULAR x what the mirror direction sees: rtlab's Whitted terms
with grey weights. Glass is refused: Tachyon has no refraction."""
import math
import os


def flip(p):
    return (p[0], p[1], -p[2])


def v(p):
    return " ".join(f"{x:.9g}" for x in p)


def read_obj(path):
    """The OBJ's vertices and triangles (fans for polygons), for formats that cannot load OBJ."""
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                verts.append(tuple(float(x) for x in parts[1:4]))
            elif parts[0] == "f":
                idx = [int(p.split("/")[0]) for p in parts[1:]]
                idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
                faces += [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]
    return verts, faces


def camera_basis(cam):
    eye, target, up = cam["eye"], cam["target"], cam["up"]
    w = [e - t for e, t in zip(eye, target)]
    n = math.sqrt(sum(x * x for x in w))
    w = [x / n for x in w]
    u = [up[1] * w[2] - up[2] * w[1], up[2] * w[0] - up[0] * w[2], up[0] * w[1] - up[1] * w[0]]
    n = math.sqrt(sum(x * x for x in u))
    u = [x / n for x in u]
    vv = [w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]]
    return u, vv, w


def tachyon_scene(scene, width, height):
    cam = scene["camera"]
    half = math.tan(math.radians(cam["vfov"]) / 2)
    u, vv, w = camera_basis(cam)
    pixel = 2 * half / height  # one pixel at distance 1
    # Half a pixel down and, as Tachyon's own right is the negated-z world's left, half a pixel
    # left in rtlab's frame: measured, a sphere's centre then lands on the same pixel in both.
    d = [-wi - 0.5 * pixel * ui - 0.5 * pixel * vi for wi, ui, vi in zip(w, u, vv)]
    lines = ["BEGIN_SCENE", f"RESOLUTION {width} {height}", "CAMERA",
             f"  ZOOM {0.5 / half:.9g}", "  ASPECTRATIO 1.0", "  ANTIALIASING 0",
             f"  RAYDEPTH {scene['depth'] + 1}",
             f"  CENTER {v(flip(cam['eye']))}", f"  VIEWDIR {v(flip(d))}", f"  UPDIR {v(flip(vv))}",
             "END_CAMERA", f"BACKGROUND {v(scene['background'])}"]
    for l in scene["lights"]:
        lines.append(f"LIGHT CENTER {v(flip(l['position']))} RAD 0 COLOR {v(l['color'])}")
    for name, m in scene["materials"].items():
        if m["glass"]:
            raise ValueError(f"tachyon: material '{name}' is glass, and Tachyon cannot refract")
        phong = f" PHONG PLASTIC {m['highlight']:.9g} PHONG_SIZE {m['exponent']:.9g}" if m["highlight"] else ""
        lines.append(f"TEXDEF {name} AMBIENT {scene['ambient']:.9g} DIFFUSE 1 SPECULAR {m['mirror']:.9g} "
                     f"OPACITY 1{phong} COLOR {v(m['diffuse'])} TEXFUNC 0")
    for c, r, m in scene["spheres"]:
        lines.append(f"SPHERE CENTER {v(flip(c))} RAD {r:.9g} {m}")
    for tri, m in scene["triangles"]:
        lines.append(f"TRI V0 {v(flip(tri[0]))} V1 {v(flip(tri[1]))} V2 {v(flip(tri[2]))} {m}")
    for path, m in scene["meshes"]:
        verts, faces = read_obj(os.path.abspath(path))
        for a, b, c in faces:
            lines.append(f"TRI V0 {v(flip(verts[a]))} V1 {v(flip(verts[b]))} V2 {v(flip(verts[c]))} {m}")
    lines.append("END_SCENE")
    return "\n".join(lines) + "\n"
