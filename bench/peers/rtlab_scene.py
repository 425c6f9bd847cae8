"""A neutral scene (scenes.py) as an rtlab scene file (book Appendix A), shaded "whitted"."""
import json
import os


def rtlab_scene(scene):
    mats = {}
    for name, m in scene["materials"].items():
        if m["glass"]:
            mats[name] = {"ior": m["glass"]}  # clear: no diffuse colour, Schlick's R and 1 - R
            continue
        out = {"diffuse": m["diffuse"]}
        if m["highlight"]:
            out["specular"] = [m["highlight"]] * 3
            out["exponent"] = m["exponent"]
        if m["mirror"]:
            out["mirror"] = [m["mirror"]] * 3
        mats[name] = out
    cam = scene["camera"]
    surfaces = [{"type": "sphere", "center": list(c), "radius": r, "material": m} for c, r, m in scene["spheres"]]
    surfaces += [{"type": "triangle", "vertices": [list(p) for p in v], "material": m} for v, m in scene["triangles"]]
    surfaces += [{"type": "mesh", "file": os.path.abspath(f), "material": m} for f, m in scene["meshes"]]
    return json.dumps({
        "description": scene["description"] + " (bench/peers)",
        "camera": {"eye": list(cam["eye"]), "target": list(cam["target"]), "up": list(cam["up"]), "fov": cam["vfov"]},
        "shading": "whitted", "max_depth": scene["depth"],
        "background": list(scene["background"]), "ambient": [scene["ambient"]] * 3,
        "materials": mats,
        "lights": [{"type": "point", "position": list(l["position"]), "color": list(l["color"])} for l in scene["lights"]],
        "surfaces": surfaces,
    }, indent=1)
