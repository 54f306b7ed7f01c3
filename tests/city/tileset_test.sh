#!/usr/bin/env bash
# `corbel-cli city --tileset` read as a 3D Tiles client reads it (tests/city/read_tileset.js,
# loaders.gl), every glb passing the Khronos glTF validator, and its bad input refused:
#   tileset_test.sh CORBEL_CLI FOOTPRINTS_DIR
# The 88 buildings of central Moosburg (the shared footprints, --around 0,0,130), at most 16 to
# a tile so the quadtree has inner tiles, plain and with --instances --compress; and 39 buildings
# 5.3 km from the town's origin (--around 4600,-2650,130), where placing them by the root's
# frame alone would put them metres away from where the footprints say.
set -euo pipefail
cli=$1
footprints=$2/moosburg_de.geojson
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for m in @loaders.gl/3d-tiles @loaders.gl/core @loaders.gl/gltf gltf-validator; do
  [[ -d "$source_dir/tools/node/node_modules/$m" ]] || { echo "$m is not installed: run bash scripts/setup"; exit 1; }
done
[[ -f "$footprints" ]] || { echo "no $footprints"; exit 1; }
# The town's origin as the file gives it (corbel's "frame" member), independent of the output.
read -r lon lat radius < <(node -e 'const f = JSON.parse(require("fs").readFileSync(process.argv[1])).frame;
  console.log(f.lon0, f.lat0, f.R_m)' "$footprints")
town=("$cli" city "$footprints" --style "$source_dir/assets/styles/oldtown.json" --seed 1 --around 0,0,130)
far=("$cli" city "$footprints" --style "$source_dir/assets/styles/oldtown.json" --seed 1 --around 4600,-2650,130)

"${town[@]}" --out "$work/whole.glb" >/dev/null 2>&1 || { echo "city --out failed"; exit 1; }
"${town[@]}" --tileset "$work/plain" --tile-buildings 16 --ground 420 >"$work/plain.json" 2>/dev/null ||
  { echo "city --tileset failed"; exit 1; }
echo "plain: $(cat "$work/plain.json")"
node "$source_dir/tests/city/read_tileset.js" "$work/plain" "$lon" "$lat" 420 "$work/whole.glb" "$radius"

"${town[@]}" --instances --compress --out "$work/whole-instances.glb" >/dev/null 2>&1 ||
  { echo "city --instances --out failed"; exit 1; }
"${town[@]}" --instances --compress --tileset "$work/instances" --tile-buildings 16 >/dev/null 2>&1 ||
  { echo "city --tileset --instances --compress failed"; exit 1; }
node "$source_dir/tests/city/read_tileset.js" "$work/instances" "$lon" "$lat" 0 "$work/whole-instances.glb" "$radius"

"${far[@]}" --out "$work/whole-far.glb" >/dev/null 2>&1 || { echo "city --out (far) failed"; exit 1; }
"${far[@]}" --tileset "$work/far" --tile-buildings 16 >/dev/null 2>&1 || { echo "city --tileset (far) failed"; exit 1; }
node "$source_dir/tests/city/read_tileset.js" "$work/far" "$lon" "$lat" 0 "$work/whole-far.glb" "$radius"

mapfile -t glbs < <(cat "$work/plain.glbs" "$work/instances.glbs" "$work/far.glbs")
echo "validating ${#glbs[@]} files"
node "$source_dir/tests/export/validate_gltf.js" "${glbs[@]}" | grep -v ": 0 errors, 0 warnings$" || true
node "$source_dir/tests/export/validate_gltf.js" "${glbs[@]}" >/dev/null

# Bad input: a clear error, nothing written.
expect_error() {  # PATTERN ARGS...: exits non-zero with PATTERN on stderr
  local pattern=$1
  shift
  if "${town[@]}" "$@" >/dev/null 2>"$work/err"; then echo "accepted: $*"; exit 1; fi
  grep -q -- "$pattern" "$work/err" || { echo "for $*: expected '$pattern', got: $(cat "$work/err")"; exit 1; }
}
mkdir "$work/full" && touch "$work/full/notes.txt"
expect_error "is not empty; give a new or empty folder" --tileset "$work/full"
[[ $(ls "$work/full") == notes.txt ]] || { echo "a refused --tileset wrote into the folder"; exit 1; }
touch "$work/file"
expect_error "cannot write into $work/file/set" --tileset "$work/file/set"
expect_error "exists and is not a folder" --tileset "$work/file"
expect_error "no place on the Earth" --tileset "$work/local" --crs local
[[ ! -e "$work/local" ]] || { echo "a refused --tileset left its folder"; exit 1; }
echo "tileset: ok"
