#!/usr/bin/env bash
# `corbel-cli city` reading its footprints a part at a time (--tiles, --tileset without --out or
# --render; docs/city.md "Memory") against the same command reading them whole
# (--stream-buildings 0):
#   stream_test.sh CORBEL_CLI FOOTPRINTS_DIR
# The buildings of Moosburg within 300 m of its origin (the shared footprints), cut into parts of
# about 60 buildings, so that most buildings' labels depend on neighbours read with another part:
# every file of the tileset and of the tiles, the per-building report and the summary's counts are
# byte for byte those of the whole read. The same on the footprints turned into RFC 7946 lon/lat
# by the frame's own formulas (so the frame comes from the positions and they are reprojected),
# and the streamed tileset read as a 3D Tiles client reads it against the whole town's glb.
# Bad input (broken JSON, a feature that is not an object, no FeatureCollection) is refused with
# the file named.
set -euo pipefail
cli=$1
footprints=$2/moosburg_de.geojson
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for m in @loaders.gl/3d-tiles @loaders.gl/core @loaders.gl/gltf; do
  [[ -d "$source_dir/tools/node/node_modules/$m" ]] || { echo "$m is not installed: run bash scripts/setup"; exit 1; }
done
[[ -f "$footprints" ]] || { echo "no $footprints"; exit 1; }
style=$source_dir/assets/styles/oldtown.json
read -r lon lat radius < <(node -e 'const f = JSON.parse(require("fs").readFileSync(process.argv[1])).frame;
  console.log(f.lon0, f.lat0, f.R_m)' "$footprints")
# RFC 7946 lon/lat: x = R cos(lat0) (lon - lon0), y = R (lat - lat0), angles in radians.
node -e '
  const fs = require("fs"), fc = JSON.parse(fs.readFileSync(process.argv[1])), f = fc.frame;
  const d = Math.PI / 180, R = f.R_m;
  delete fc.frame;
  const map = (c) => Array.isArray(c[0]) ? c.map(map) : [f.lon0 + c[0] / (R * Math.cos(f.lat0 * d)) / d, f.lat0 + c[1] / R / d];
  for (const g of fc.features) g.geometry.coordinates = map(g.geometry.coordinates);
  fs.writeFileSync(process.argv[2], JSON.stringify(fc));' "$footprints" "$work/lonlat.geojson"

compare() {  # NAME SOURCE ARGS...: streamed against whole, every output file alike
  local name=$1 src=$2
  shift 2
  local args=("$cli" city "$src" --style "$style" --seed 1 --jobs 2 --around 0,0,300 --detail massing "$@")
  "${args[@]}" --stream-buildings 0 "${out[@]/@/$work/$name-whole}" --report "$work/$name-whole.jsonl" \
    >"$work/$name-whole.json" 2>/dev/null || [[ $? == 1 ]] || { echo "$name: the whole read failed"; exit 1; }
  "${args[@]}" --stream-buildings 60 "${out[@]/@/$work/$name-part}" --report "$work/$name-part.jsonl" \
    >"$work/$name-part.json" 2>/dev/null || [[ $? == 1 ]] || { echo "$name: the streamed read failed"; exit 1; }
  grep -q '"streamed":true' "$work/$name-part.json" || { echo "$name: not streamed: $(cat "$work/$name-part.json")"; exit 1; }
  echo "$name: $(cat "$work/$name-part.json")"
  diff -r "$work/$name-whole" "$work/$name-part" || { echo "$name: the streamed files differ"; exit 1; }
  diff "$work/$name-whole.jsonl" "$work/$name-part.jsonl" || { echo "$name: the streamed report differs"; exit 1; }
  node -e '
    const [a, b] = process.argv.slice(1).map((f) => { const j = JSON.parse(require("fs").readFileSync(f));
      for (const k of ["read_s", "build_s", "total_s", "streamed"]) delete j[k]; return JSON.stringify(j); });
    if (a !== b) { console.log(`summaries differ:\n${a}\n${b}`); process.exit(1); }' "$work/$name-whole.json" "$work/$name-part.json"
}
out=(--tileset @ --tile-buildings 16)
compare tileset "$footprints"
compare tileset-lonlat "$work/lonlat.geojson"
out=(--tiles @ --tile-size 100)
compare tiles "$footprints"
n=$(ls "$work/tiles-part" | wc -l)
(( n >= 16 )) || { echo "only $n tiles"; exit 1; }

# The streamed tileset as a client reads it, against the same buildings written whole.
"$cli" city "$footprints" --style "$style" --seed 1 --jobs 2 --around 0,0,300 --detail massing --out "$work/whole.glb" \
  >/dev/null 2>&1 || [[ $? == 1 ]] || { echo "city --out failed"; exit 1; }
node "$source_dir/tests/city/read_tileset.js" "$work/tileset-part" "$lon" "$lat" 0 "$work/whole.glb" "$radius"

# Bad input: named, nothing built.
refused() {  # TEXT EXPECTED
  printf '%s' "$1" >"$work/bad.geojson"
  rm -rf "$work/bad"
  if "$cli" city "$work/bad.geojson" --style "$style" --crs local --tiles "$work/bad" >/dev/null 2>"$work/err"; then
    echo "accepted: $1"; exit 1
  fi
  grep -q "bad.geojson" "$work/err" && grep -q "$2" "$work/err" || { echo "for $1 expected $2, got: $(cat "$work/err")"; exit 1; }
}
refused '{"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": ' "not JSON"
refused '{"type": "FeatureCollection", "features": [null]}' "not an object"
refused '{"type": "Feature", "geometry": null}' "FeatureCollection"
echo "stream: ok"
