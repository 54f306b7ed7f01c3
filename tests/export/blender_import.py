# Run by blender_import_test.sh inside Blender 3.4 (`blender -b --factory-startup --python THIS
# -- A.glb A.obj [B.glb B.obj ...]`): imports each glb with Blender's glTF importer and the OBJ
# export of the same objects with its OBJ importer, and compares them object by object: the
# triangles (a polygon of n corners is n - 2) and the world bounding box (within 1 mm: glb
# positions are quantized to at most 1 mm steps). Prints one line per pair; exits 1 on a
# difference.
import math
import re
import sys

import numpy

numpy.bool = bool  # Debian's Blender 3.4 add-ons still use numpy.bool, which numpy 1.24 removed
import bpy  # noqa: E402


def token(name):
    # docs/export.md: OBJ names are one token; Blender adds .001 to a name it has seen.
    return re.sub(r"[^A-Za-z0-9._-]", "_", re.sub(r"\.\d{3}$", "", name))


def load(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if path.endswith(".glb"):
        result = bpy.ops.import_scene.gltf(filepath=path)
    else:
        result = bpy.ops.wm.obj_import(filepath=path)
    if "FINISHED" not in result:
        raise SystemExit(f"{path}: import {result}")
    out = {}
    for obj in bpy.context.scene.objects:
        if obj.type != "MESH":
            continue
        m = obj.matrix_world
        points = [m @ v.co for v in obj.data.vertices]
        lo = [min(p[k] for p in points) for k in range(3)]
        hi = [max(p[k] for p in points) for k in range(3)]
        tris = sum(len(p.vertices) - 2 for p in obj.data.polygons)
        key = token(obj.name)
        if key in out:  # two objects of one name: add them up
            t, a, b = out[key]
            out[key] = (t + tris, [min(x, y) for x, y in zip(a, lo)], [max(x, y) for x, y in zip(b, hi)])
        else:
            out[key] = (tris, lo, hi)
    return out


args = sys.argv[sys.argv.index("--") + 1:]
bad = 0
for glb, obj in zip(args[0::2], args[1::2]):
    a, b = load(glb), load(obj)
    problems = []
    if set(a) != set(b):
        problems.append(f"objects differ: only glb {sorted(set(a) - set(b))[:5]}, only obj {sorted(set(b) - set(a))[:5]}")
    worst = 0.0
    for name in set(a) & set(b):
        if a[name][0] != b[name][0]:
            problems.append(f"{name}: {a[name][0]} triangles from the glb, {b[name][0]} from the obj")
        for k in range(3):
            for x, y in ((a[name][1][k], b[name][1][k]), (a[name][2][k], b[name][2][k])):
                worst = max(worst, abs(x - y))
    if worst > 1e-3:
        problems.append(f"bounding boxes differ by {worst} m")
    triangles = sum(v[0] for v in a.values())
    print(f"{glb}: {len(a)} objects, {triangles} triangles, boxes within {worst:.2e} m of the obj's: "
          f"{'ok' if not problems else 'DIFFERENT'}")
    for p in problems[:10]:
        print("  " + p)
    bad += bool(problems)
sys.exit(1 if bad else 0)
