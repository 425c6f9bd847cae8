"""A neutral scene (scenes.py) as a POV-Ray 3.7 scene (.pov).

POV-Ray is left-handed: every z is negated, as for Tachyon. Its camera `angle` is the horizontal
field of view. assumed_gamma 1 keeps its arithmetic linear, as rtlab's; max_trace_level counts the
camera ray (depth + 1), and adc_bailout is the scene's min_weight (rtlab's min_reach) in place of
POV-Ray's default 1/255, so both prune a pixel's tree of rays at the same weight. Finish: ambient a, diffuse 1 (brilliance 1: plain n.l), `specular` (Blinn)
with roughness 1 / exponent, `reflection` the mirror's grey weight. Glass: a clear filtering
pigment, ior 1.5, Fresnel reflection with conserve_energy (POV-Ray's exact Fresnel, where rtlab
takes Schlick's approximation). POV-Ray lets light through a transparent object's shadow (filtered,
not refracted); rtlab's glass blocks shadow rays."""
import math
import os

from tachyon_scene import read_obj


def flip(p):
    return (p[0], p[1], -p[2])


def v(p):
    return "<" + ", ".join(f"{x:.9g}" for x in p) + ">"


def povray_scene(scene, width, height):
    cam = scene["camera"]
    hfov = 2 * math.degrees(math.atan(math.tan(math.radians(cam["vfov"]) / 2) * width / height))
    out = ["#version 3.7;",
           f"global_settings {{ assumed_gamma 1.0 max_trace_level {scene['depth'] + 1} "
           f"adc_bailout {scene['min_weight']:.9g} ambient_light rgb 1 }}",
           f"background {{ rgb {v(scene['background'])} }}",
           f"camera {{ perspective location {v(flip(cam['eye']))} sky {v(flip(cam['up']))} up y "
           f"right x*{width}/{height} angle {hfov:.9g} look_at {v(flip(cam['target']))} }}"]
    for l in scene["lights"]:
        out.append(f"light_source {{ {v(flip(l['position']))} color rgb {v(l['color'])} }}")
    for name, m in scene["materials"].items():
        if m["glass"]:
            out.append(f"#declare M_{name} = material {{ texture {{ pigment {{ rgbf <1, 1, 1, 1> }} "
                       "finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy } } "
                       f"interior {{ ior {m['glass']:.9g} }} }}")
            continue
        finish = f"ambient {scene['ambient']:.9g} diffuse 1"
        if m["highlight"]:
            finish += f" specular {m['highlight']:.9g} roughness {1 / m['exponent']:.9g}"
        if m["mirror"]:
            finish += f" reflection {{ {m['mirror']:.9g} }}"
        out.append(f"#declare M_{name} = material {{ texture {{ pigment {{ rgb {v(m['diffuse'])} }} "
                   f"finish {{ {finish} }} }} }}")
    for c, r, m in scene["spheres"]:
        out.append(f"sphere {{ {v(flip(c))}, {r:.9g} material {{ M_{m} }} }}")
    for tri, m in scene["triangles"]:
        out.append(f"triangle {{ {v(flip(tri[0]))}, {v(flip(tri[1]))}, {v(flip(tri[2]))} material {{ M_{m} }} }}")
    for path, m in scene["meshes"]:
        verts, faces = read_obj(os.path.abspath(path))
        out.append(f"mesh2 {{ vertex_vectors {{ {len(verts)},")
        out.append(",\n".join(v(flip(p)) for p in verts))
        out.append(f"}} face_indices {{ {len(faces)},")
        out.append(",\n".join(f"<{a}, {b}, {c}>" for a, b, c in faces))
        out.append(f"}} material {{ M_{m} }} }}")
    return "\n".join(out) + "\n"
