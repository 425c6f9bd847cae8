#!/usr/bin/env python3
"""The bad-input catalogue: malformed scene files, OBJ files, images and command lines.

  bad_input_test.py ROOT BIN_DIR WORK_DIR

Each case runs a program of BIN_DIR and states the exit code and the words its one-line
message must contain. For every failing case the test also checks that stderr is exactly
one line and that nothing was written: the output directory holds no image and no
temporary afterwards. Then: a scene whose file name is not UTF-8 picks and prints its
statistics, and SIGINT or SIGTERM at any moment of a render leaves either a whole image
(the run had finished) or nothing. Prints one line per failure and a closing count; exit 1
on any failure.
"""
import copy
import json
import math
import os
import pathlib
import signal
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from checks import check, finish  # noqa: E402

root, bin_dir, work = (pathlib.Path(a) for a in sys.argv[1:4])
work = work.resolve()
out = work / "out"
inputs = work / "inputs"
for d in (out, inputs):
    d.mkdir(parents=True, exist_ok=True)




def leftovers():
    return sorted(p.name for p in out.iterdir())


def run(name, argv, code, words, timeout=60):
    """Runs argv; checks the exit code, one line of stderr naming `words`, nothing written."""
    for p in out.iterdir():
        p.unlink()
    try:
        r = subprocess.run([str(a) for a in argv], capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        check(False, f"{name}: no answer within {timeout} s")
        return
    err = r.stderr.decode("utf-8", "replace").strip()
    if r.returncode != code:
        check(False, f"{name}: exit {r.returncode}, expected {code}: {err!r}")
        return
    if code != 0:
        check(err != "" and "\n" not in err, f"{name}: expected one line on stderr, got {err!r}")
        missing = [w for w in words if w not in err]
        check(not missing, f"{name}: message {err!r} lacks {missing}")
        check(not leftovers(), f"{name}: a failed run wrote {leftovers()}")
    return r


# --- scene files -----------------------------------------------------------------------

BASE = {
    "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
    "materials": {"m": {"diffuse": [0.5, 0.5, 0.5]}},
    "lights": [{"type": "point", "position": [0, 5, 5]}],
    "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
}
DELETE = object()


def patched(patch):
    doc = copy.deepcopy(BASE)
    for pointer, value in patch.items():
        *path, last = pointer.strip("/").split("/")
        node = doc
        for part in path:
            node = node[int(part)] if isinstance(node, list) else node[part]
        key = int(last) if isinstance(node, list) else last
        if value is DELETE:
            del node[key]
        else:
            node[key] = value
    return json.dumps(doc, indent=1)


def chapter(args):
    return [bin_dir / "ch05"] + args + ["--width", "8", "--height", "6", "-o", out / "image.png"]


def scene_text(name, text, words, code=2, files=None):
    path = inputs / f"{name}.json"
    path.write_bytes(text.encode() if isinstance(text, str) else text)
    for file_name, content in (files or {}).items():
        (inputs / file_name).write_text(content)
    run(f"scene {name}", chapter(["--scene", path]), code, [path.name] + words)


def scene(name, patch, *words):
    scene_text(name, patched(patch), list(words))


def surface(name, value, *words):
    scene(name, {"/surfaces/0": value}, *words)


S = "/surfaces/0"
scene("radius_negative", {S + "/radius": -1}, S + "/radius", "length must be in 1e-6..1e8, not -1")
scene("radius_zero", {S + "/radius": 0}, S + "/radius", "length must be in")
scene("radius_huge", {S + "/radius": 1e39}, "length must be in", "not 1e39")
scene("radius_tiny", {S + "/radius": 1e-7}, "length must be in")
scene("radius_string", {S + "/radius": "1"}, S + "/radius", "must be a number")
scene("radius_bool", {S + "/radius": True}, "must be a number")
scene("radius_null", {S + "/radius": None}, "must be a number")
scene("radius_missing", {S + "/radius": DELETE}, S, "missing key 'radius'")
scene("center_far", {S + "/center": [1e9, 0, 0]}, S + "/center/0", "coordinate must be in -1e8..1e8")
scene("center_very_far", {S + "/center": [-1e200, 0, 0]}, "coordinate must be in")
scene("center_two", {S + "/center": [0, 0]}, S + "/center", "must be an array of 3 numbers")
scene("center_four", {S + "/center": [0, 0, 0, 0]}, "must be an array of 3 numbers")
scene("center_text", {S + "/center": "origin"}, "must be an array of 3 numbers")
scene("center_string_item", {S + "/center": ["0", 0, 0]}, S + "/center/0", "must be a number")
scene("center_missing", {S + "/center": DELETE}, "missing key 'center'")
scene("type_missing", {S + "/type": DELETE}, "missing key 'type'")
scene("type_unknown", {S + "/type": "cone"}, "unknown surface type \"cone\"")
scene("type_number", {S + "/type": 5}, S + "/type", "must be a string")
scene("surface_unknown_key", {S + "/colour": [1, 0, 0]}, "unknown key 'colour'")
scene("surface_name_number", {S + "/name": 5}, S + "/name", "must be a string")
scene("material_unknown_name", {S + "/material": "gold"}, "no material named \"gold\"")
scene("material_not_string", {S + "/material": 3}, "must be a string")
# Chapters 06-09: recursion depth, offsets, dielectrics, mirrors, transforms, instances.
M = "/materials/m"
scene("ior_zero", {M + "/ior": 0}, M + "/ior", "index of refraction must be in 0.01..100, not 0")
scene("ior_negative", {M + "/ior": -1.5}, M + "/ior", "index of refraction must be in")
scene("ior_text", {M + "/ior": "glass"}, M + "/ior", "must be a number")
scene("attenuation_opaque", {M + "/attenuation": [0.5, 0.5, 0.5]}, "only a dielectric")
scene("attenuation_above_one", {M + "/ior": 1.5, M + "/attenuation": [1.5, 1, 1]}, "reflectance must be in 0..1")
scene("mirror_above_one", {M + "/mirror": [2, 0, 0]}, M + "/mirror/0", "reflectance must be in 0..1, not 2")
scene("mirror_on_dielectric", {M + "/ior": 1.5, M + "/mirror": [1, 1, 1]}, "a dielectric reflects by Schlick")
scene("checker_without_size", {M + "/checker": [0, 0, 0]}, "'checker' and 'checker_size' go together")
scene("max_depth_negative", {"/max_depth": -1}, "/max_depth", "recursion depth must be in 0..64, not -1")
scene("max_depth_past_limit", {"/max_depth": 65}, "recursion depth must be in 0..64, not 65")
scene("max_depth_fraction", {"/max_depth": 2.5}, "/max_depth", "must be a whole number")
scene("offset_unknown", {"/offset": {"method": "magic"}}, "/offset/method", "unknown offset method \"magic\"")
scene("offset_epsilon_negative", {"/offset": {"method": "course", "epsilon": -1}}, "/offset/epsilon", "length")
scene("offset_unknown_key", {"/offset": {"eps": 1}}, "unknown key 'eps'")
# Chapter 10: the search structure.
scene("accel_unknown", {"/accel": "kd-tree"}, "/accel", "unknown accel \"kd-tree\"")
scene("accel_not_text", {"/accel": 3}, "/accel")
scene("transform_too_flat", {S + "/transform": [{"scale": [1, 1e-7, 1]}]}, "nearly singular transform")
scene("transform_singular", {S + "/transform": [{"scale": [1, 0, 1]}]}, S + "/transform", "singular transform")
scene("transform_scale_zero", {S + "/transform": [{"scale": 0}]}, "singular transform")
scene("transform_flattening_rotation_pair",
      {S + "/transform": [{"scale": [1, 1e-14, 1]}, {"rotate": [1, 1, 0], "degrees": 30}]}, "singular transform")
scene("transform_not_array", {S + "/transform": {"scale": 2}}, S + "/transform", "must be an array of objects")
scene("transform_step_not_object", {S + "/transform": [2]}, S + "/transform/0", "must be an object")
scene("transform_two_kinds", {S + "/transform": [{"scale": 2, "translate": [0, 0, 0]}]}, "exactly one of")
scene("transform_no_kind", {S + "/transform": [{}]}, "exactly one of")
scene("transform_step_unknown_key", {S + "/transform": [{"scale": 2, "skew": 1}]}, S + "/transform/0/skew",
      "unknown key 'skew'")
scene("transform_rotate_no_degrees", {S + "/transform": [{"rotate": [0, 1, 0]}]}, "'rotate' and 'degrees' go together")
scene("transform_rotate_zero_axis", {S + "/transform": [{"rotate": [0, 0, 0], "degrees": 10}]}, "must not be zero")
scene("transform_degrees_huge", {S + "/transform": [{"rotate": [0, 1, 0], "degrees": 1e9}]}, "angle must be in")
scene("transform_scale_far", {S + "/transform": [{"scale": [1e9, 1, 1]}]}, "coordinate must be in")
scene("instance_unknown_shape", {S: {"type": "instance", "shape": "teapot"}}, "no shape named \"teapot\"")
scene("instance_inside_shapes", {"/shapes": {"a": {"type": "instance", "shape": "a"}}}, "/shapes/a/type",
      "cannot be one there")
scene("instance_shape_missing", {S: {"type": "instance"}}, "missing key 'shape'")
# A shape of /shapes has no material, name or transform: its instances give them.
scene("shapes_entry_material", {"/shapes": {"a": {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}}},
      "/shapes/a/material", "unknown key 'material'")
scene("instance_unknown_key", {S: {"type": "instance", "shape": "a", "smooth": True},
                                "/shapes": {"a": {"type": "sphere", "center": [0, 0, 0], "radius": 1}}},
      S + "/smooth", "unknown key 'smooth'")
scene("shapes_bad_entry", {"/shapes": {"a": {"type": "sphere", "center": [0, 0, 0], "radius": -1}}},
      "/shapes/a/radius", "length must be in")
scene("smooth_sphere", {S + "/smooth": True}, S + "/smooth", "only meshes have vertex normals")
scene("smooth_false_sphere", {S + "/smooth": False}, S + "/smooth", "only meshes have vertex normals")
scene("mirror_black_on_dielectric", {M + "/ior": 1.5, M + "/mirror": [0, 0, 0]}, "a dielectric reflects by Schlick")
scene("transform_moves_too_far", {S + "/radius": 1e7, S + "/transform": [{"scale": 100}]}, S + "/transform",
      "coordinate must be in")
scene("smooth_text", {S: {"type": "icosphere", "center": [0, 0, 0], "radius": 1, "smooth": "yes"}}, S + "/smooth",
      "must be true or false")
scene("shading_unknown_lists_whitted", {"/shading": "raytrace"}, "unknown shading", "whitted")
scene("materials_array", {"/materials": []}, "/materials", "must be an object")
scene("material_not_object", {"/materials/m": 1}, "/materials/m", "must be an object")
scene("diffuse_over_one", {"/materials/m/diffuse": [1.5, 0, 0]}, "/materials/m/diffuse/0", "reflectance must be in 0..1")
scene("diffuse_negative", {"/materials/m/diffuse": [0, -0.1, 0]}, "/materials/m/diffuse/1", "reflectance")
scene("diffuse_huge", {"/materials/m/diffuse": [0, 0, 1e39]}, "reflectance")
scene("specular_two", {"/materials/m/specular": [1, 1]}, "must be an array of 3 numbers")
scene("exponent_zero", {"/materials/m/exponent": 0}, "Phong exponent must be in")
scene("exponent_huge", {"/materials/m/exponent": 1e7}, "Phong exponent")
scene("exponent_negative", {"/materials/m/exponent": -5}, "Phong exponent")
scene("material_unknown_key", {"/materials/m/shininess": 3}, "unknown key 'shininess'")
# Chapter 13: CSG objects and boxes.
BALL = {"type": "sphere", "center": [0, 0, 0], "radius": 1}
CSG = {"type": "csg", "op": "difference", "operands": [BALL, {"type": "box", "min": [0, 0, 0], "max": [2, 2, 2]}]}
scene("csg_ok_but_op_unknown", {S: dict(CSG, op="subtract")}, S + "/op", "unknown CSG operation \"subtract\"")
scene("csg_one_operand", {S: dict(CSG, operands=[BALL])}, S + "/operands", "CSG operands must be in 2..1024, not 1")
scene("csg_operands_object", {S: dict(CSG, operands=BALL)}, S + "/operands", "must be an array of objects")
scene("csg_too_many_operands", {S: dict(CSG, operands=[BALL] * 1025)}, "CSG operands must be in 2..1024, not 1025")
scene("csg_operand_triangle", {S: dict(CSG, operands=[BALL, {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}])},
      S + "/operands/1", "a CSG operand must be a closed solid: a triangle has no inside")
scene("csg_operand_terrain", {S: dict(CSG, operands=[BALL, {"type": "terrain", "center": [0, 0, 0], "size": 2, "height": 0.1, "cells": 4}])},
      S + "/operands/1", "the mesh is not closed")
# A closed tetrahedron wound clockwise seen from outside: closed, but inside out.
INSIDE_OUT = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n"
scene_text("csg_operand_inside_out", patched({S: dict(CSG, operands=[BALL, {"type": "mesh", "file": "inside_out.obj"}])}),
           [S + "/operands/1", "the mesh is inside out"], files={"inside_out.obj": INSIDE_OUT})
scene("csg_operand_bad_sphere", {S: dict(CSG, operands=[BALL, dict(BALL, radius=-1)])}, S + "/operands/1/radius", "length")
scene("csg_operand_unknown_key", {S: dict(CSG, operands=[BALL, dict(BALL, colour=1)])}, "unknown key 'colour'")
scene("csg_operand_unknown_material", {S: dict(CSG, operands=[BALL, dict(BALL, material="gold")])},
      S + "/operands/1/material", "no material named \"gold\"")
scene("csg_operand_unknown_shape", {S: dict(CSG, operands=[BALL, {"type": "instance", "shape": "x"}])}, "no shape named \"x\"")
scene("csg_in_shapes_names_shape", {"/shapes": {"a": BALL, "b": dict(CSG, operands=[BALL, {"type": "instance", "shape": "a"}])}},
      "/shapes/b/operands/1/type", "cannot name another shape")
scene("csg_intersection_empty", {S: dict(CSG, op="intersection", operands=[BALL, dict(BALL, center=[5, 0, 0])])}, S,
      "the intersection is empty")
scene("csg_thin_negative", {S: dict(CSG, thin=-1)}, S + "/thin", "CSG thin must be in 0..1e8, not -1")
scene("csg_thin_text", {S: dict(CSG, thin="small")}, S + "/thin", "must be a number")
scene("box_flat", {S: {"type": "box", "min": [0, 0, 0], "max": [1, 0, 1]}}, "box: min must be below max")
scene("box_far", {S: {"type": "box", "min": [0, 0, 0], "max": [1, 1e9, 1]}}, S + "/max/1", "coordinate must be in")
# Chapter 14: antialiasing.
scene("aa_pattern_unknown", {"/antialiasing": {"pattern": "halton"}}, "/antialiasing/pattern", "unknown pattern \"halton\"")
scene("aa_filter_unknown", {"/antialiasing": {"filter": "gauss"}}, "/antialiasing/filter", "unknown filter \"gauss\"")
scene("aa_samples_zero", {"/antialiasing": {"samples": 0}}, "/antialiasing/samples", "samples per pixel must be in 1..65536")
scene("aa_samples_huge", {"/antialiasing": {"samples": 1e9}}, "/antialiasing/samples", "must be a whole number")
scene("aa_samples_not_square", {"/antialiasing": {"pattern": "jittered", "samples": 12}}, "/antialiasing/samples",
      "the jittered pattern takes n x n samples")
scene("aa_unknown_key", {"/antialiasing": {"sampler": "random"}}, "unknown key 'sampler'")
scene("aa_not_object", {"/antialiasing": "jittered"}, "/antialiasing", "must be an object")
# Chapters 15-18: area lights, the thin lens, glossy mirrors, motion and the shutter.
PAR = {"type": "parallelogram", "corner": [-1, 4, -1], "edge_a": [2, 0, 0], "edge_b": [0, 0, 2]}
scene("parallelogram_parallel_edges", {"/lights/0": dict(PAR, edge_b=[4, 0, 0])}, "/lights/0/edge_b",
      "is parallel to edge_a")
scene("parallelogram_zero_edge", {"/lights/0": dict(PAR, edge_a=[0, 0, 0])}, "/lights/0/edge_a", "must not be zero")
scene("parallelogram_far", {"/lights/0": dict(PAR, edge_a=[9e7, 0, 0], corner=[9e7, 0, 0])}, "/lights/0",
      "reaches past the coordinate limits")
scene("parallelogram_missing_edge", {"/lights/0": {"type": "parallelogram", "corner": [0, 4, 0], "edge_a": [1, 0, 0]}},
      "missing key 'edge_b'")
scene("aperture_negative", {"/camera/aperture": -0.1}, "/camera/aperture", "aperture must be in 0..1e8")
scene("aperture_orthographic", {"/camera/projection": "orthographic", "/camera/aperture": 0.2},
      "a lens (aperture > 0) needs a perspective camera")
scene("lens_unknown", {"/camera/aperture": 0.2, "/camera/lens": "hexagon"}, "/camera/lens",
      "unknown lens \"hexagon\" (expected square or disk)")
scene("lens_without_aperture", {"/camera/lens": "disk"}, "/camera/lens", "a lens needs an aperture > 0")
scene("focus_zero", {"/camera/aperture": 0.2, "/camera/focus_distance": 0}, "/camera/focus_distance", "length must be in")
scene("shutter_backwards", {"/camera/shutter": [0.6, 0.2]}, "/camera/shutter", "closes before it opens")
scene("shutter_past_one", {"/camera/shutter": [0, 1.5]}, "/camera/shutter/1", "shutter time must be in 0..1")
scene("shutter_one_number", {"/camera/shutter": 0.5}, "/camera/shutter: must be an array of 2 numbers")
scene("shutter_three_numbers", {"/camera/shutter": [0, 0.5, 1]}, "/camera/shutter: must be an array of 2 numbers")
scene("shutter_text", {"/camera/shutter": ["open", 1]}, "/camera/shutter/0: must be a number")
scene("glossy_without_mirror", {"/materials/m/glossy": 0.2}, "/materials/m/glossy", "only a mirror")
scene("glossy_huge", {"/materials/m/mirror": [1, 1, 1], "/materials/m/glossy": 40}, "/materials/m/glossy",
      "glossy width must be in 0..16")
scene("moves_to_far", {S + "/moves_to": [0, 1e9, 0]}, S + "/moves_to/1", "coordinate must be in")
scene("moves_to_text", {S + "/moves_to": "left"}, S + "/moves_to", "must be an array of 3 numbers")
L = "/lights/0"
scene("light_colour_huge", {L + "/color": [1e39, 1, 1]}, L + "/color/0", "radiance must be in 0..1000000")
scene("light_colour_negative", {L + "/color": [1, -1, 1]}, "radiance")
scene("light_colour_past_limit", {L + "/color": [2e6, 1, 1]}, "radiance")
scene("light_type_unknown", {L + "/type": "spot"}, "unknown light type \"spot\"")
scene("light_position_missing", {L + "/position": DELETE}, "missing key 'position'")
scene("light_position_far", {L + "/position": [0, 1e200, 0]}, L + "/position/1", "coordinate must be in")
scene("directional_zero", {L: {"type": "directional", "direction": [0, 0, 0]}}, L + "/direction", "must not be zero")
scene("directional_huge", {L: {"type": "directional", "direction": [0, -1e200, 0]}}, "coordinate must be in")
scene("light_unknown_key", {L + "/falloff": 2}, "unknown key 'falloff'")
scene("lights_object", {"/lights": {}}, "/lights", "must be an array")
scene("light_number", {"/lights": [5]}, L, "must be an object")
scene("background_huge", {"/background": [1e39, 0, 0]}, "/background/0", "radiance")
scene("background_two", {"/background": [1, 2]}, "/background", "must be an array of 3 numbers")
scene("ambient_negative", {"/ambient": [-1, 0, 0]}, "/ambient/0", "radiance")
scene("ambient_text", {"/ambient": "grey"}, "/ambient", "must be an array of 3 numbers")
C = "/camera"
scene("camera_missing", {C: DELETE}, "missing key 'camera'")
scene("camera_not_object", {C: [0, 0, 5]}, C, "must be an object")
scene("eye_missing", {C + "/eye": DELETE}, "missing key 'eye'")
scene("eye_on_target", {C + "/eye": [0, 0, 0]}, "eye and target are the same point")
scene("up_along_view", {C + "/up": [0, 0, 1]}, "up is parallel to the view direction")
scene("eye_very_far", {C + "/eye": [1e200, 0, 0]}, C + "/eye/0", "coordinate must be in")
scene("fov_zero", {C + "/fov": 0}, C + "/fov", "field of view must be in 0.001..179.9 degrees")
scene("fov_180", {C + "/fov": 180}, "field of view")
scene("fov_negative", {C + "/fov": -10}, "field of view")
scene("projection_unknown", {C + "/projection": "fisheye"}, C + "/projection",
      "unknown projection \"fisheye\" (expected orthographic or perspective)")
scene("window_height_zero", {C + "/projection": "orthographic", C + "/window_height": 0}, "length must be in")
scene("focal_distance_negative", {C + "/focal_distance": -1}, C + "/focal_distance", "length")
scene("camera_unknown_key", {C + "/zoom": 1}, "unknown key 'zoom'")
scene("shading_unknown", {"/shading": "toon"}, "unknown shading \"toon\"")
scene("shading_number", {"/shading": 3}, "/shading", "must be a string")
scene("top_unknown_key", {"/sky": 1}, "/sky", "unknown key 'sky'")
scene("surfaces_missing", {"/surfaces": DELETE}, "missing key 'surfaces'")
scene("surfaces_object", {"/surfaces": {}}, "/surfaces", "must be an array")
scene("surface_number", {"/surfaces": [5]}, S, "must be an object")
scene("description_number", {"/description": 5}, "/description", "must be a string")
surface("triangle_two_vertices", {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0]]},
        "must be an array of 3 points")
surface("triangle_collinear", {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0]]}, "degenerate")
surface("triangle_far_vertex", {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1e9, 0]]},
        S + "/vertices/2/1", "coordinate")
surface("triangle_vertex_not_point", {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], 7]},
        S + "/vertices/2", "must be an array of 3 numbers")
surface("polygon_two_vertices", {"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0]]},
        "polygon vertices must be in 3..100000, not 2")
surface("polygon_collinear", {"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]},
        "no area")
surface("polygon_not_planar", {"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 1]]},
        "off the plane")
surface("polygon_too_many", {"type": "polygon", "vertices": [[i % 7, i % 5, 0] for i in range(100001)]},
        "polygon vertices must be in 3..100000, not 100001")
surface("polygon_repeated_vertex", {"type": "polygon", "vertices": [[0, 0, 0], [0, 0, 0], [1, 0, 0], [0, 1, 0]]},
        "vertices")
surface("icosphere_subdivisions_8", {"type": "icosphere", "center": [0, 0, 0], "radius": 1, "subdivisions": 8},
        "icosphere subdivisions must be in 0..7, not 8")
surface("icosphere_subdivisions_fraction",
        {"type": "icosphere", "center": [0, 0, 0], "radius": 1, "subdivisions": 2.5}, "must be a whole number")
surface("cube_subdivisions_0", {"type": "cube", "center": [0, 0, 0], "size": 1, "subdivisions": 0},
        "cube subdivisions must be in 1..256, not 0")
surface("cube_subdivisions_257", {"type": "cube", "center": [0, 0, 0], "size": 1, "subdivisions": 257},
        "cube subdivisions")
surface("cube_size_negative", {"type": "cube", "center": [0, 0, 0], "size": -2}, S + "/size", "length")
surface("terrain_cells_0", {"type": "terrain", "center": [0, 0, 0], "size": 4, "height": 1, "cells": 0},
        "terrain cells must be in 1..2048, not 0")
surface("terrain_cells_5000", {"type": "terrain", "center": [0, 0, 0], "size": 4, "height": 1, "cells": 5000},
        "terrain cells")
surface("terrain_height_huge", {"type": "terrain", "center": [0, 0, 0], "size": 4, "height": 1e9},
        S + "/height", "coordinate")
surface("soup_count_0", {"type": "soup", "center": [0, 0, 0], "size": 1, "scale": 0.1, "count": 0},
        "soup triangles must be in 1..1000000, not 0")
surface("soup_count_past_limit", {"type": "soup", "center": [0, 0, 0], "size": 1, "scale": 0.1, "count": 1000001},
        "soup triangles")
surface("soup_seed_negative", {"type": "soup", "center": [0, 0, 0], "size": 1, "scale": 0.1, "count": 5, "seed": -1},
        "soup seed must be in 0..2147483647, not -1")
surface("soup_scale_zero", {"type": "soup", "center": [0, 0, 0], "size": 1, "scale": 0, "count": 5}, "length")


def renders(name, patch):
    """Values at the edges of their ranges: accepted, rendered, and every sample finite."""
    path = inputs / f"{name}.json"
    path.write_text(patched(patch))
    r = run(f"edge {name}", chapter(["--scene", path, "--stats"]), 0, [])
    if r is not None:
        stats = json.loads(r.stdout)
        check(stats["nonfinite_samples"] == 0, f"edge {name}: {stats['nonfinite_samples']} samples not finite")


renders("directional_tiny", {L: {"type": "directional", "direction": [0, -1e-30, 0]}})
renders("directional_largest", {L: {"type": "directional", "direction": [1e8, -1e8, 1e8]}})
renders("up_tiny", {C + "/up": [0, 1e-30, 0]})
renders("eye_close_to_target", {C + "/eye": [0, 0, 1e-30], C + "/target": [0, 0, 0]})
renders("everything_far", {C + "/eye": [1e8, 1e8, 1e8], C + "/target": [-1e8, -1e8, -1e8], S + "/center": [0, 0, 0],
                           S + "/radius": 1e8, L + "/position": [-1e8, 1e8, 1e8]})
renders("radiance_largest", {L + "/color": [1e6, 1e6, 1e6], "/background": [1e6, 0, 0], "/ambient": [1e6, 1e6, 1e6],
                             "/materials/m/diffuse": [1, 1, 1], "/materials/m/specular": [1, 1, 1]})
renders("light_inside_sphere_surface", {L + "/position": [0, 0, 1]})
renders("radius_smallest", {S + "/radius": 1e-6})
renders("exponent_extremes", {"/materials/m/exponent": 1e6, "/materials/m/specular": [1, 1, 1]})
W = {"/shading": "whitted", "/max_depth": 64}
renders("ior_smallest", {**W, M + "/ior": 0.01})
renders("ior_largest", {**W, M + "/ior": 100, M + "/attenuation": [0, 0, 0]})
renders("mirror_sphere_depth_64", {**W, M + "/mirror": [1, 1, 1], L + "/position": [0, 0, 0]})
renders("transform_nearly_flat", {**W, S + "/transform": [{"scale": [1, 1e-5, 1]}, {"rotate": [1, 1, 0], "degrees": 30}]})
renders("transform_mirror", {**W, S + "/transform": [{"scale": [-1, 1, 1]}]})
renders("offset_course_tiny", {**W, "/offset": {"method": "course", "epsilon": 1e-6}})
for kind in ["none", "bvh-sort", "bvh-midpoint", "bvh-sah", "grid", "bsp-midpoint", "bsp", "fast"]:
    renders("accel_" + kind.replace("-", "_"), {**W, "/accel": kind})

good = patched({})
scene_text("empty", "", ["not valid JSON"])
scene_text("trailing_comma", good[:-2] + ",\n}", ["not valid JSON"])
scene_text("truncated", good[: len(good) // 2], ["not valid JSON"])
scene_text("comment", "// a scene\n" + good, ["1:1", "not valid JSON"])
scene_text("top_level_array", "[" + good + "]", ["/: must be an object"])
scene_text("nul_byte", good.replace('"m"', '"\0"', 1), ["not valid JSON"])
scene_text("invalid_utf8", good.encode().replace(b'"m"', b'"\xe9"', 1), ["not valid JSON"])
scene_text("nested_100000", '{"description": ' + "[" * 100000 + "]" * 100000 + "}",
           ["/description/0/0", "JSON nesting depth must be in 1..32"])
scene_text("nested_33", '{"description": ' + "[" * 32 + "]" * 32 + "}", ["JSON nesting depth must be in 1..32, not 33"])
scene_text("radius_1e400", good.replace('"radius": 1', '"radius": 1e400'),
           [S + "/radius", "number 1e400 is too large to hold"])
scene_text("center_minus_1e400", good.replace('"center": [\n    0', '"center": [\n    -1e400'),
           [S + "/center/0", "too large to hold"])
scene_text("fov_1e400", good.replace('"target"', '"fov": 1e400, "target"'), [C + "/fov", "too large to hold"])
scene_text("file_too_large", good + " " * (17 << 20), ["scene file size must be in 0..16777216 bytes, not"])

# The work a scene may ask of the search structures and of CSG (limits.hpp), refused when
# the scene is read or its structure built, before any rendering: 10^4 balls in one place
# would list each in every cell of a grid (800 MB); 32 instances of a 1024-ball CSG shape
# under one CSG would test 32768 balls a ray. The largest CSG allowed loads and renders.
doc = copy.deepcopy(BASE)
doc["surfaces"] = [dict(BALL, material="m") for _ in range(10000)]
(inputs / "grid_pile.json").write_text(json.dumps(doc))
start = time.monotonic()
run("grid_pile", [bin_dir / "ch11", "--scene", inputs / "grid_pile.json", "--accel", "grid", "--width", "8", "--height",
                  "6", "-o", out / "image.png"], 2, ["grid entries must be in 0..67108864", "--accel fast"])
check(time.monotonic() - start < 10, f"grid_pile: refused after {time.monotonic() - start:.1f} s")
BALLS = {"type": "csg", "op": "union", "operands": [dict(BALL, center=[k / 1024, 0, 0]) for k in range(1024)]}
for copies, code, words in ((16, 0, []), (32, 2, ["/surfaces/0", "CSG leaves must be in 2..16384"])):
    doc = copy.deepcopy(BASE)
    doc["shapes"] = {"balls": BALLS}
    doc["surfaces"] = [{"type": "csg", "op": "union", "material": "m", "operands": [
        {"type": "instance", "shape": "balls", "transform": [{"translate": [0, k, 0]}]} for k in range(copies)]}]
    scene_text(f"csg_leaves_{copies}", json.dumps(doc), words, code)

# --- meshes (OBJ files, through a scene) -----------------------------------------------------


def mesh(name, obj, words, patch=None, code=2):
    doc = copy.deepcopy(BASE)
    doc["surfaces"] = [{"type": "mesh", "file": f"{name}.obj", **(patch or {})}]
    scene_text(f"mesh_{name}", json.dumps(doc), words, code, files={f"{name}.obj": obj} if obj is not None else None)


TRI = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
mesh("missing", None, ["/surfaces/0/file", "missing.obj: no such file"])
(inputs / "folder.obj").mkdir(exist_ok=True)
mesh("folder", None, ["folder.obj: is a directory"])
doc = copy.deepcopy(BASE)
doc["surfaces"] = [{"type": "mesh", "file": "/dev/zero"}]
scene_text("mesh_device", json.dumps(doc), ["/dev/zero: is not a regular file"])
mesh("index_huge", TRI + "f 1 2 99999999999\n", ["index_huge.obj:4", "vertex index 99999999999, but the file has 3"])
mesh("index_past_1e12", TRI + "f 1 2 99999999999999999999\n", ["vertex index past 10^12"])
mesh("index_zero", TRI + "f 0 1 2\n", ["index_zero.obj:4", "vertex index 0"])
mesh("index_before_first", TRI + "f -1 -2 -4\n", ["vertex index -4 reaches before the first vertex"])
mesh("face_two_corners", TRI + "f 1 2\n", ["face_two_corners.obj:4", "OBJ face corners must be in 3..255, not 2"])
mesh("face_garbage", TRI + "f a b c\n", ["face corner 'a' has no vertex index"])
mesh("no_faces", TRI, ["no triangles in the file"])
mesh("empty", "", ["no triangles in the file"])
mesh("vertex_huge", "v 1e400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ["vertex_huge.obj:1", "'1e400' is not a finite number"])
mesh("vertex_1e39", "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ["vertex 1", "coordinate must be in"])
# tinyobjloader reads a coordinate that is not a number as 0: each is refused at its line.
for bad in ("nan", "-inf", "abc", "0x1p3", "1e", "1.2.3"):
    mesh(f"vertex_{bad}", TRI + f"v {bad} 0 0\nf 1 2 4\n", [f"vertex_{bad}.obj:4", f"vertex coordinate '{bad}' is not a finite number"])
mesh("vertex_two_coordinates", "v 0 0\n" + TRI + "f 2 3 4\n", ["vertex_two_coordinates.obj:1", "vertex has 2 coordinates, not 3"])
mesh("normal_nan", TRI + "vn nan 0 1\nf 1//1 2//1 3//1\n", ["normal_nan.obj:4", "vertex normal coordinate 'nan' is not a finite number"])
mesh("all_degenerate", TRI + "v 2 0 0\nf 1 2 4\n", ["every triangle is degenerate"])
mesh("scaled_past_limit", TRI + "f 1 2 3\n", ["vertex 2", "coordinate must be in"],
     {"scale": 1e8, "translate": [1e8, 0, 0]})
mesh("translate_far", TRI + "f 1 2 3\n", ["/surfaces/0/translate/0", "coordinate"], {"translate": [1e9, 0, 0]})
mesh("scale_zero", TRI + "f 1 2 3\n", ["/surfaces/0/scale", "length"], {"scale": 0})

# tinyobjloader counts a face's corners in a byte: 255 corners load (fanned, in linear time),
# 20,000 are refused at once rather than wrapped round.
for big, code, words in ((255, 0, []), (20000, 2, ["OBJ face corners must be in 3..255, not 20000"])):
    ring = "".join(f"v {math.cos(2 * math.pi * k / big)} {math.sin(2 * math.pi * k / big)} 0\n" for k in range(big))
    mesh(f"face_{big}_corners", ring + "f " + " ".join(str(k + 1) for k in range(big)) + "\n", words, code=code)

# --- images (rtlab-diff) --------------------------------------------------------------------

golden = root / "tests/golden/ch01/gradient.png"
if not golden.exists():
    golden = sorted((root / "tests/golden").glob("*/*.png"))[0]
png = golden.read_bytes()


def image(name, data, words, other=golden):
    path = inputs / name
    if isinstance(data, bytes):
        path.write_bytes(data)
    run(f"image {name}", [bin_dir / "rtlab-diff", other, path, "--heatmap", out / "heat.png"], 2, [name] + words)


def pfm(w, h, floats, scale="-1.0"):
    import struct
    return f"PF\n{w} {h}\n{scale}\n".encode() + struct.pack(f"<{len(floats)}f", *floats)


image("missing.png", None, ["no such file"])
(inputs / "folder.png").mkdir(exist_ok=True)
image("folder.png", None, ["is a directory"])
image("text.png", b"this is not a PNG", ["not a PNG file"])
image("truncated.png", png[:100], ["cannot read image"])
image("empty.png", b"", ["not a PNG file"])
# A valid PNG signature and header claiming 100000 x 100000 pixels: refused before decoding.
import struct
import zlib
ihdr = struct.pack(">IIBBBBB", 100000, 100000, 8, 2, 0, 0, 0)
chunk = struct.pack(">I", len(ihdr)) + b"IHDR" + ihdr + struct.pack(">I", zlib.crc32(b"IHDR" + ihdr))
image("huge.png", b"\x89PNG\r\n\x1a\n" + chunk, ["image width and height must be in 1..16384 pixels, not 100000"])
ihdr = struct.pack(">IIBBBBB", 8192, 8192, 8, 2, 0, 0, 0)
chunk = struct.pack(">I", len(ihdr)) + b"IHDR" + ihdr + struct.pack(">I", zlib.crc32(b"IHDR" + ihdr))
image("many_pixels.png", b"\x89PNG\r\n\x1a\n" + chunk, ["image size must be in 1..33554432 pixels, not 67108864"])
image("short.pfm", pfm(2, 2, [0.5] * 3), ["holds 12 bytes of pixels, not 48 for 2x2"])
image("long.pfm", pfm(1, 1, [0.5] * 6), ["holds 24 bytes of pixels, not 12 for 1x1"])
image("nan.pfm", pfm(1, 1, [0.5, float("nan"), 0.5]), ["pixel 0,0 is not finite"])
image("inf.pfm", pfm(1, 1, [float("inf"), 0, 0]), ["pixel 0,0 is not finite"])
image("big_endian.pfm", pfm(1, 1, [0.5] * 3, scale="1.0"), ["not a little-endian colour PFM"])
image("grey.pfm", b"Pf\n1 1\n-1.0\n" + b"\0" * 4, ["not a PNG file"])
image("zero_width.pfm", pfm(0, 1, []), ["image width and height must be in 1..16384 pixels, not 0"])
image("huge.pfm", b"PF\n20000 20000\n-1.0\n", ["image width and height must be in 1..16384 pixels, not 20000"])
image("width_text.pfm", b"PF\nwide 1\n-1.0\n\0\0\0\0", ["not a little-endian colour PFM"])
small = inputs / "small.pfm"
small.write_bytes(pfm(1, 1, [0.5] * 3))
image("size_differs.pfm", pfm(2, 1, [0.5] * 6), ["sizes differ"], other=small)
run("diff heatmap extension", [bin_dir / "rtlab-diff", golden, golden, "--heatmap", out / "heat.jpg"], 2,
    ["--heatmap", "must end in .png"])
run("diff threshold nan", [bin_dir / "rtlab-diff", golden, golden, "--threshold", "nan"], 2, ["--threshold"])
run("diff max-rmse nan", [bin_dir / "rtlab-diff", golden, golden, "--max-rmse", "nan"], 2, ["--max-rmse"])
run("diff radius 9", [bin_dir / "rtlab-diff", golden, golden, "--radius", "9"], 2, ["--radius"])
run("diff one image", [bin_dir / "rtlab-diff", golden], 2, ["B"])

# --- command lines --------------------------------------------------------------------------------


def cli(name, args, words, code=2):
    run(f"cli {name}", [bin_dir / "ch02"] + args, code, words)


o = ["-o", out / "image.png"]
cli("width_text", ["--width", "abc"] + o, ["--width", "must be a whole number, not 'abc'"])
cli("width_zero", ["--width", "0"] + o, ["--width"])
cli("width_past_limit", ["--width", "16385"] + o, ["--width"])
cli("width_float", ["--width", "12.5"] + o, ["--width", "whole number"])
cli("height_negative", ["--height", "-1"] + o, ["--height"])
cli("spp_zero", ["--spp", "0"] + o, ["--spp"])
cli("spp_past_limit", ["--spp", "65537"] + o, ["--spp"])
cli("too_many_pixels", ["--width", "16384", "--height", "16384"] + o,
    ["image size must be in 1..33554432 pixels, not 268435456"])
cli("too_many_samples", ["--width", "8192", "--height", "4096", "--spp", "65536"] + o,
    ["samples per image must be in 1..4294967296 width x height x spp, not 2199023255552"])
cli("threads_past_limit", ["--threads", "2000"] + o, ["--threads"])
cli("threads_text", ["--threads", "many"] + o, ["--threads"])
cli("seed_text", ["--seed", "abc"] + o, ["--seed"])
cli("seed_negative", ["--seed", "-1"] + o, ["--seed"])
cli("unknown_option", ["--frobnicate"] + o, ["frobnicate"])
cli("extra_argument", ["extra"] + o, ["extra"])
cli("unknown_scene", ["--scene", "nope"] + o, ["unknown scene 'nope'"])
cli("scene_file_missing", ["--scene", inputs / "none.json"] + o, ["none.json: no such file"])
(inputs / "folder.json").mkdir(exist_ok=True)
cli("scene_file_folder", ["--scene", inputs / "folder.json"] + o, ["folder.json: is a directory"])
cli("output_empty", ["-o", ""], ["--output: must not be empty"])
cli("output_jpg", ["-o", out / "x.jpg"], ["must end in .png or .pfm"])
cli("output_bare_extension", ["-o", out / ".png"], ["must end in .png or .pfm"])
cli("pick_one_number", ["--pick", "7"] + o, ["--pick"])
cli("pick_outside", ["--width", "20", "--height", "20", "--pick", "20,3"] + o, ["--pick", "outside the 20x20 image"])
cli("pick_negative", ["--pick", "-1,0"] + o, ["--pick"])
cli("pick_text", ["--pick", "a,b"] + o, ["--pick"])
cli("depth_negative", ["--depth", "-1"] + o, ["--depth"])
cli("depth_past_limit", ["--depth", "65"] + o, ["--depth"])
cli("depth_text", ["--depth", "deep"] + o, ["--depth", "whole number"])
cli("accel_unknown", ["--accel", "octree"] + o, ["--accel", "unknown 'octree'"])
cli("accel_empty", ["--accel", ""] + o, ["--accel"])
cli("svg_without_tree", ["--pick", "1,1", "--svg", out / "tree.svg"] + o, ["--svg", "whitted"])
cli("svg_without_pick", ["--svg", out / "tree.svg"] + o, ["--svg", "needs --pick"])
cli("svg_wrong_extension", ["--pick", "1,1", "--svg", out / "tree.png"] + o, ["--svg", "must end in .svg"])
run("cli svg_unwritable", [bin_dir / "ch06", "--width", "8", "--height", "8", "--pick", "1,1", "--svg",
                          "/proc/rtlab/t.svg"] + o, 1, ["cannot"])
cli("output_unwritable", ["--width", "8", "--height", "8", "-o", "/proc/rtlab/x.png"], ["cannot"], code=1)

# --- a scene file whose name is not UTF-8 --------------------------------------------------------

latin1 = os.fsencode(str(inputs)) + b"/caf\xe9.json"
with open(latin1, "wb") as f:
    f.write(good.encode())
for extra in (["--pick", "4,3"], ["--stats"]):
    r = subprocess.run([str(bin_dir / "ch05"), b"--scene", latin1, "--width", "8", "--height", "6",
                        "-o", str(out / "cafe.png")] + extra, capture_output=True)
    ok = r.returncode == 0
    try:
        json.loads(r.stdout)
    except ValueError:
        ok = False
    check(ok, f"non-UTF-8 scene name with {extra[0]}: exit {r.returncode}, stdout {r.stdout[:200]!r}, "
              f"stderr {r.stderr[:200]!r}")

# --- interrupted renders -------------------------------------------------------------------------
# SIGINT or SIGTERM at any moment: the run ends by the signal and leaves nothing, or it had
# finished and left a whole image. Never a half file, never a temporary.
slow = [str(bin_dir / "ch05"), "--scene", "meshes", "--width", "320", "--height", "240", "--spp", "2",
        "-o", str(out / "interrupted.pfm")]
for sig in (signal.SIGINT, signal.SIGTERM):
    for delay in (0.05, 0.2, 0.4, 0.8, 1.6):
        for p in out.iterdir():
            p.unlink()
        proc = subprocess.Popen(slow, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(delay)
        proc.send_signal(sig)
        code = proc.wait(timeout=60)
        files = leftovers()
        size = len(b"PF\n320 240\n-1.0\n") + 320 * 240 * 12
        whole = files == ["interrupted.pfm"] and (out / "interrupted.pfm").stat().st_size == size
        if code == 0:
            check(whole, f"{sig.name} after {delay} s: finished, but left {files}")
        else:
            # Ended by the signal: before the image was renamed into place (nothing left), or
            # after (a fast render, between the rename and the exit: the whole image).
            check(code == -sig and (not files or whole), f"{sig.name} after {delay} s: exit {code}, left {files}")

finish("bad_input_test")
