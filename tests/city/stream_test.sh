#!/usr/bin/env bash
# `corbel-cli city` reading its footprints a part at a time (--tiles, --tileset, a glb --out,
# without --render; docs/city.md "Memory") against the same command reading them whole
# (--stream-buildings 0):
#   stream_test.sh CORBEL_CLI FOOTPRINTS_DIR
# The buildings of Moosburg within 300 m of its origin (the shared footprints), cut into parts of
# about 60 buildings, so that most buildings' labels depend on neighbours read with another part:
# every file of the tileset, of the tiles and the --out glb, the per-building report and the summary's counts are
# byte for byte those of the whole read; a compressed glb decodes to the plain one. The same on the footprints turned into RFC 7946 lon/lat
# by the frame's own formulas (so the frame comes from the positions and they are reprojected),
# and the streamed tileset read as a 3D Tiles client reads it against the whole town's glb.
# The same for a Shapefile, a GeoPackage layer and a FlatGeobuf made by ogr2ogr, and with
# --where. Bad input (broken JSON, a feature that is not an object, no FeatureCollection, a layer
# not named, a bad filter) is refused with the file named.
set -euo pipefail
cli=$1
footprints=$2/moosburg_de.geojson
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap '[[ -n ${KEEP:-} ]] || rm -rf "$work"' EXIT
for m in @loaders.gl/3d-tiles @loaders.gl/core @loaders.gl/gltf gltf-validator; do
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
  diff -r "$work/$name-whole${ext:-}" "$work/$name-part${ext:-}" || { echo "$name: the streamed files differ"; exit 1; }
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
# One glb (--out): the buildings tile by tile, here of 40 m so that parts of about 60 are cut
# between many tiles, plain and with --compress, and at full detail, where the glb's buffers pass
# the 64 KiB it keeps in memory of each and go through temporary files.
out=(--out @.glb --tile-size 40)
ext=.glb
compare glb "$footprints"
compare glb-lonlat "$work/lonlat.geojson" --compress
compare glb-full "$footprints" --detail full --around 0,0,200 --textures on
(( $(stat -c %s "$work/glb-full-part.glb") > 4 << 20 )) || { echo "the full-detail glb is too small to spill"; exit 1; }
# Compressed at full detail, each kind of buffer view is encoded in chunks of 64 KiB as the
# buildings come: read by loaders.gl's own meshopt decoder, every accessor is the plain glb's,
# a kind takes several views, and the Khronos validator finds nothing wrong.
compare glb-full-compressed "$footprints" --detail full --around 0,0,200 --textures on --compress
MIN_VIEWS_OF_A_KIND=3 node "$source_dir/tests/city/compare_glb.js" "$work/glb-full-part.glb" "$work/glb-full-compressed-part.glb"
node "$source_dir/tests/export/validate_gltf.js" "$work/glb-full-compressed-part.glb"
# With --instances, each feature shape's copies go to a temporary file as the buildings come (a
# stream per shape, 4 KiB of each in memory): plain and compressed, enough copies of a shape
# that they pass through the file (a shape with more than 512: 4 KiB of rotations); the
# compressed file decodes to the plain one and passes the Khronos validator.
compare glb-instances "$footprints" --detail full --around 0,0,200 --instances
compare glb-instances-compressed "$footprints" --detail full --around 0,0,200 --instances --compress
node -e 'const j = JSON.parse(require("fs").readFileSync(process.argv[1]));
  if (!(j.instanced_features > 512 * j.feature_meshes)) { console.log(`too few copies: ${JSON.stringify(j)}`); process.exit(1); }' \
  "$work/glb-instances-part.json"
node "$source_dir/tests/city/compare_glb.js" "$work/glb-instances-part.glb" "$work/glb-instances-compressed-part.glb"
node "$source_dir/tests/export/validate_gltf.js" "$work/glb-instances-compressed-part.glb"
ext=
# A run that fails while the glb is written (no temporary folder to spill into) says why and
# leaves the existing --out as it was, with nothing beside it.
mkdir "$work/keep"
printf 'old' >"$work/keep/town.glb"
for tmp in "$work/no-such-folder" /proc; do
  if TMPDIR=$tmp "$cli" city "$footprints" --style "$style" --seed 1 --jobs 2 --around 0,0,300 --detail massing \
    --out "$work/keep/town.glb" >/dev/null 2>"$work/err"; then
    echo "TMPDIR=$tmp: the glb was written"; exit 1
  fi
  grep -q "temporary" "$work/err" || { echo "TMPDIR=$tmp: $(cat "$work/err")"; exit 1; }
  [[ $(cat "$work/keep/town.glb") == old && $(ls -A "$work/keep") == town.glb ]] ||
    { echo "TMPDIR=$tmp: the existing glb was touched: $(ls -A "$work/keep")"; exit 1; }
done

# Other formats, read through GDAL/OGR feature by feature: the footprints within 300 m written by
# ogr2ogr as a Shapefile in UTM, a GeoPackage in lon/lat beside a second layer (so --layer must
# name it) and a FlatGeobuf in web Mercator; each tileset streamed is the one read whole, with
# --where too.
command -v ogr2ogr >/dev/null || { echo "ogr2ogr is not installed: run bash scripts/setup"; exit 1; }
frame="+proj=eqc +lat_ts=$lat +lat_0=$lat +lon_0=$lon +x_0=0 +y_0=0 +R=$radius +units=m +no_defs"
ogr() { ogr2ogr -s_srs "$frame" -spat -300 -300 300 300 "$@" "$footprints" 2>/dev/null; }
ogr -f "ESRI Shapefile" -t_srs EPSG:32632 "$work/utm.shp"
ogr -f GPKG -t_srs EPSG:4326 -nln buildings "$work/lonlat.gpkg"
ogr -f GPKG -t_srs EPSG:4326 -nln other -update "$work/lonlat.gpkg"
ogr -f FlatGeobuf -t_srs EPSG:3857 "$work/mercator.fgb"
ogr2ogr -f GeoJSON -spat -300 -300 300 300 "$work/centre.geojson" "$footprints"  # in the file's frame
out=(--tileset @ --tile-buildings 16)
compare shapefile "$work/utm.shp"
compare geopackage "$work/lonlat.gpkg" --layer buildings
compare flatgeobuf-where "$work/mercator.fgb" --where "area_m2 > 100"
compare geojson-where "$work/centre.geojson" --where "area_m2 > 100"
grep -q '"buildings":[1-9]' "$work/flatgeobuf-where-part.json" || { echo "the filter left nothing"; exit 1; }
[[ $(node -p 'JSON.parse(require("fs").readFileSync(process.argv[1])).buildings' "$work/flatgeobuf-where-part.json") -lt \
   $(node -p 'JSON.parse(require("fs").readFileSync(process.argv[1])).buildings' "$work/shapefile-part.json") ]] ||
  { echo "--where filtered nothing out"; exit 1; }

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
# Through GDAL/OGR: a layer not there, a filter that is not OGR SQL.
"$cli" city "$work/lonlat.gpkg" --style "$style" --tileset "$work/bad-layer" 2>"$work/err" >/dev/null &&
  { echo "accepted a GeoPackage of two layers without --layer"; exit 1; }
grep -q "choose one with --layer" "$work/err" || { echo "two layers: $(cat "$work/err")"; exit 1; }
"$cli" city "$work/utm.shp" --style "$style" --where "no such field >" --tileset "$work/bad-where" 2>"$work/err" >/dev/null &&
  { echo "accepted a bad --where"; exit 1; }
grep -q "where" "$work/err" || { echo "bad --where: $(cat "$work/err")"; exit 1; }
echo "stream: ok"
