#!/usr/bin/env bash
# Blender 3.4 (Debian's `blender`) imports corbel's glb as a user's File > Import does: every
# object with the triangles and the place that Blender's OBJ importer finds in the OBJ export of
# the same objects (tests/export/blender_import.py). A project of every kind of object and a
# textured old town. Exits 77 (skipped) where blender is not installed.
set -euo pipefail
cli=$1
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
command -v blender >/dev/null || { echo "blender is not installed (apt-get install blender): skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for f in glb obj; do
  "$cli" export "$source_dir/assets/examples/village.corbel" --out "$work/village.$f" >/dev/null
  "$cli" export "$source_dir/assets/examples/extrusions.corbel" --out "$work/extrusions.$f" >/dev/null
  "$cli" city "$source_dir/assets/examples/town-moosburg.geojson" --style "$source_dir/assets/styles/oldtown.json" \
    --seed 1 --out "$work/town.$f" >/dev/null 2>&1 || [[ $? -eq 1 ]]
done
rc=0
blender -b --factory-startup --python-exit-code 1 --python "$source_dir/tests/export/blender_import.py" -- \
  "$work/village.glb" "$work/village.obj" "$work/extrusions.glb" "$work/extrusions.obj" \
  "$work/town.glb" "$work/town.obj" >"$work/log" 2>&1 || rc=$?
grep -v "^Blender quit\|^Read blend\|^$" "$work/log" || true
exit $rc
