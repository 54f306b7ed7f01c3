#!/usr/bin/env bash
# Every example project exported as glb, and a town written by `corbel-cli city` (plain, with
# --instances, and compressed), pass the Khronos glTF validator with no error and no warning.
# Needs node and tools/node's packages (scripts/setup installs both).
set -euo pipefail
cli=$1
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[[ -d "$source_dir/tools/node/node_modules/gltf-validator" ]] ||
  { echo "gltf-validator is not installed: run bash scripts/setup"; exit 1; }
for project in "$source_dir"/assets/examples/*.corbel; do
  "$cli" export "$project" --out "$work/$(basename "$project" .corbel).glb" >/dev/null 2>&1 ||
    { echo "export failed: $project"; exit 1; }
done
"$cli" city "$source_dir/assets/examples/town-moosburg.geojson" --style "$source_dir/assets/styles/oldtown.json" \
  --seed 1 --out "$work/city-oldtown.glb" >/dev/null 2>&1 || { echo "city failed"; exit 1; }
"$cli" city "$source_dir/assets/examples/town-moosburg.geojson" --style "$source_dir/assets/styles/oldtown.json" \
  --seed 1 --instances --out "$work/city-oldtown-instances.glb" >/dev/null 2>&1 || { echo "city --instances failed"; exit 1; }
# Compressed: the validator checks the document and the fallback buffer, not the compressed data
# (tests/city/output_test.cpp decodes that).
"$cli" city "$source_dir/assets/examples/town-moosburg.geojson" --style "$source_dir/assets/styles/oldtown.json" \
  --seed 1 --instances --compress --out "$work/city-oldtown-compressed.glb" >/dev/null 2>&1 || { echo "city --compress failed"; exit 1; }
count=$(ls "$work"/*.glb | wc -l)
echo "validating $count files"
node "$source_dir/tests/export/validate_gltf.js" "$work"/*.glb
