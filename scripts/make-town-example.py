#!/usr/bin/env python3
"""Writes assets/examples/town.corbel: the buildings of a 140 m square of Moosburg an der Isar
from ../shared/data/footprints/moosburg_de.geojson (ODbL 1.0, (c) OpenStreetMap contributors),
each an extrusion: four-cornered footprints get gabled roofs on their long sides, others hips.
Run from the repository root; the output is committed, so this only reruns by hand."""
import json
import math
import sys

SRC = "../shared/data/footprints/moosburg_de.geojson"
CX, CY, HALF = -410.6, -837.1, 70.0


def main():
    data = json.load(open(SRC))
    objects = []
    for f in data["features"]:
        rings = [r[:-1] for r in f["geometry"]["coordinates"]]
        outer = rings[0]
        cx = sum(p[0] for p in outer) / len(outer)
        cy = sum(p[1] for p in outer) / len(outer)
        if abs(cx - CX) > HALF or abs(cy - CY) > HALF:
            continue
        loops = [[[round(p[0] - CX, 3), round(p[1] - CY, 3)] for p in r] for r in rings]
        area = f["properties"].get("area_m2", 0)
        kind = f["properties"].get("src_building", "yes")
        wall = 3.0 if area < 40 or kind in ("garage", "garages", "shed") else (9.0 if area > 400 else 6.5)
        pitch = 25.0 if wall == 3.0 else 42.0
        run = 1.0 / math.tan(math.radians(pitch))
        profiles = [{"name": "eaves", "points": [[0, 0], [0, wall], [-0.3, wall], [-0.3 + 8 * run, wall + 8]],
                     "tags": ["wall", "soffit", "roof"]},
                    {"name": "gable", "points": [[0, 0], [0, wall], [-0.3, wall], [-0.3, wall + 1]],
                     "tags": ["wall", "soffit", "gable"]}]
        if len(loops) == 1 and len(outer) == 4:
            lengths = [math.dist(outer[i], outer[(i + 1) % 4]) for i in range(4)]
            longer = 0 if lengths[0] + lengths[2] >= lengths[1] + lengths[3] else 1
            names = [["eaves" if i % 2 == longer else "gable" for i in range(4)]]
            plan = {"loops": loops, "edge_profiles": names}
        else:
            plan = {"loops": loops, "profile": "eaves"}
        objects.append({"id": len(objects) + 1, "name": f["properties"]["source_id"], "visible": True,
                        "extrusion": {"material": ["plaster", "stone", "brick"][len(objects) % 3],
                                      "roof_material": "roof_tile", "base": 0, "priority": "maximise_volume",
                                      "plan": plan, "profiles": profiles}})
    objects.append({"id": len(objects) + 1, "name": "Ground", "visible": True,
                    "box": {"origin": [0, 0, -0.2], "size": [2 * HALF + 40, 2 * HALF + 40, 0.2], "rotation": 0,
                            "material": "grass", "repeat": {"count": [1, 1], "spacing": [0, 0]}}})
    doc = {"format": "corbel", "version": 1,
           "name": "Town block, Moosburg an der Isar (footprints: ODbL 1.0, (c) OpenStreetMap contributors)",
           "objects": objects}
    with open("assets/examples/town.corbel", "w") as out:
        out.write(json.dumps(doc, indent=0) + "\n")
    print(f"{len(objects) - 1} buildings", file=sys.stderr)


if __name__ == "__main__":
    main()
