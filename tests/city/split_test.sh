#!/usr/bin/env bash
# corbel-cli city-split, per-tile builds run by GNU parallel, and city-merge, read back as a 3D
# Tiles client reads them (tests/city/read_tileset.js, loaders.gl):
#   split_test.sh CORBEL_CLI FOOTPRINTS_DIR
# Central Moosburg (the shared footprints' buildings within a 240 m square, cut out by ogr2ogr)
# split on a 100 m grid with a 70 m margin (the labels look 60 m for walls; the file has no
# streets), each tile built into its own tileset, the tilesets merged: every building of the same
# footprints built whole is in exactly one leaf tile, no tile's building lies outside its
# tile's cell, the leaves' triangles are the whole town's (each building labelled and built as in
# the whole town), and the Khronos validator finds no error in any glb. Then memory by tile
# (four copies against one) and a missing tile refused.
set -euo pipefail
cli=$1
footprints=$2/moosburg_de.geojson
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for m in @loaders.gl/3d-tiles @loaders.gl/core @loaders.gl/gltf gltf-validator; do
  [[ -d "$source_dir/tools/node/node_modules/$m" ]] || { echo "$m is not installed: run bash scripts/setup"; exit 1; }
done
command -v parallel >/dev/null || { echo "GNU parallel is not installed: run bash scripts/setup"; exit 1; }
command -v ogr2ogr >/dev/null || { echo "ogr2ogr is not installed: run bash scripts/setup"; exit 1; }
read -r lon lat radius < <(node -e 'const f = JSON.parse(require("fs").readFileSync(process.argv[1])).frame;
  console.log(f.lon0, f.lat0, f.R_m)' "$footprints")
# The file's positions are metres about (lon0, lat0); GDAL takes them as numbers and copies the
# "frame" member.
ogr2ogr -f GeoJSON -spat -120 -120 120 120 "$work/centre.geojson" "$footprints"
style=$source_dir/assets/styles/oldtown.json

"$cli" city "$work/centre.geojson" --style "$style" --seed 1 --jobs 2 --out "$work/whole.glb" >"$work/whole.json" 2>/dev/null ||
  [[ $? == 1 ]] || { echo "city --out failed"; exit 1; }
echo "whole: $(cat "$work/whole.json")"
"$cli" city-split "$work/centre.geojson" --grid 0.1 --margin 70 --out "$work/split" >"$work/split.json"
echo "split: $(cat "$work/split.json")"
tiles=$(wc -l <"$work/split/tiles.txt")
(( tiles >= 4 )) || { echo "only $tiles tiles"; exit 1; }
# Each tile's source holds its own buildings in its cell and margin ones (not built) around them.
node -e '
  const fs = require("fs"), [dir, grid] = [process.argv[1], Number(process.argv[2])];
  let own = 0;
  for (const name of fs.readFileSync(dir + "/tiles.txt", "utf8").split("\n").filter(Boolean)) {
    const [x, y] = name.split("_").map(Number);
    const fc = JSON.parse(fs.readFileSync(`${dir}/sources/${name}.geojson`));
    for (const f of fc.features) {
      if (f.properties.corbel_margin) continue;
      ++own;
      const ring = f.geometry.coordinates[0].slice(0, -1);
      const c = [0, 1].map((k) => ring.reduce((s, p) => s + p[k], 0) / ring.length);
      if (Math.floor(c[0] / grid) !== x || Math.floor(c[1] / grid) !== y) { console.log(`${f.id} in tile ${name} has its centre at ${c}`); process.exit(1); }
    }
  }
  console.log(`${own} buildings owned`);' "$work/split" 100

parallel -j 2 --halt now,fail=1 "'$cli' city '$work/split/sources/{}.geojson' --style '$style' --seed 1 --jobs 1 \
  --tileset '$work/split/tilesets/{}' --tile-buildings 16 >/dev/null 2>&1 || [ \$? = 1 ]" :::: "$work/split/tiles.txt"
"$cli" city-merge "$work/split" >"$work/merge.json"
echo "merge: $(cat "$work/merge.json")"
node "$source_dir/tests/city/read_tileset.js" "$work/split" "$lon" "$lat" 0 "$work/whole.glb" "$radius"

mapfile -t glbs < "$work/split.glbs"
echo "validating ${#glbs[@]} files"
node "$source_dir/tests/export/validate_gltf.js" "${glbs[@]}" | grep -v ": 0 errors, 0 warnings$" || true
node "$source_dir/tests/export/validate_gltf.js" "${glbs[@]}" >/dev/null

# Memory by tile: four copies of the same footprints side by side (1 km apart, a whole number of
# cells, so each copy is cut into the same tiles). What a tile's build holds is its source: the
# largest source (own and margin buildings) of four copies is exactly one copy's, 4 x the tiles.
# The tile builds' peak resident memory (GNU time's %M) is printed, and held to 10 % over one
# copy's; at this size it is mostly the process's own (about 100 MB: libraries, GDAL, PROJ).
# (city-split itself holds the whole source: docs/city.md, "Memory".)
node -e '
  const fs = require("fs"), fc = JSON.parse(fs.readFileSync(process.argv[1]));
  const out = [];
  for (let k = 0; k < 4; ++k)
    for (const f of fc.features) {
      const g = JSON.parse(JSON.stringify(f));
      for (const ring of g.geometry.coordinates) for (const p of ring) p[0] += 1000 * k;
      g.properties.source_id += "/" + k;
      out.push(g);
    }
  fc.features = out;
  fs.writeFileSync(process.argv[2], JSON.stringify(fc));' "$work/centre.geojson" "$work/four.geojson"
peak() {  # SOURCE NAME: "TILES LARGEST_SOURCE PEAK_kB" of NAME's tiles
  "$cli" city-split "$1" --grid 0.1 --margin 70 --out "$work/$2" >/dev/null
  parallel -j 2 "/usr/bin/time -f %M -o '$work/$2/{}.rss' '$cli' city '$work/$2/sources/{}.geojson' --style '$style' \
    --detail massing --jobs 1 --textures off --out '$work/$2/{}.glb' >/dev/null 2>&1 || [ \$? = 1 ]" :::: "$work/$2/tiles.txt"
  echo "$(wc -l <"$work/$2/tiles.txt") $(for f in "$work/$2"/sources/*.geojson; do grep -o '"type":"Feature"' "$f" | wc -l; done |
    sort -n | tail -1) $(cat "$work/$2"/*.rss | sort -n | tail -1)"
}
read -r tiles1 largest1 one < <(peak "$work/centre.geojson" one)
read -r tiles4 largest4 four < <(peak "$work/four.geojson" four)
echo "one copy: $tiles1 tiles, largest source $largest1 buildings, tile builds' peak $one kB;" \
  "four copies: $tiles4 tiles, $largest4, $four kB"
(( tiles4 == 4 * tiles1 && largest4 == largest1 )) || { echo "four copies' tiles are not one copy's four times over"; exit 1; }
(( four * 10 <= one * 11 )) || { echo "a tile of four copies took $four kB, over 110 % of one copy's $one kB"; exit 1; }

# A tile not built: named, nothing written.
rm -r "$work/split/tilesets/$(head -1 "$work/split/tiles.txt")" "$work/split/tileset.json"
if "$cli" city-merge "$work/split" >/dev/null 2>"$work/err"; then echo "merged with a tile missing"; exit 1; fi
grep -q "missing (has tile" "$work/err" || { echo "expected a missing tile named, got: $(cat "$work/err")"; exit 1; }
[[ ! -e "$work/split/tileset.json" ]] || { echo "a refused merge wrote tileset.json"; exit 1; }
echo "split: ok"
