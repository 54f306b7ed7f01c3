#!/usr/bin/env python3
"""Writes the 10,524 real footprints of ../shared/data/footprints as one GeoJSON file for the
city benchmark: Kathmandu as it is, Moosburg moved 12 km east so the two towns do not overlap
(both files are already in local metres)."""
import json
import sys

root = sys.argv[1] if len(sys.argv) > 1 else "../shared/data/footprints"
out = sys.argv[2] if len(sys.argv) > 2 else "/tmp/footprints-10524.geojson"
features = []
for name, shift in (("kathmandu_np", 0.0), ("moosburg_de", 12000.0)):
    with open(f"{root}/{name}.geojson") as f:
        data = json.load(f)
    for feature in data["features"]:
        g = feature["geometry"]
        rings = g["coordinates"] if g["type"] == "Polygon" else [r for p in g["coordinates"] for r in p]
        for ring in rings:
            for p in ring:
                p[0] += shift
        features.append(feature)
with open(out, "w") as f:
    json.dump({"type": "FeatureCollection", "frame": {"units": "m", "projection": "two local frames side by side"},
               "features": features}, f)
print(out, len(features))
