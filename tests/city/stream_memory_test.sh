#!/usr/bin/env bash
# A streamed town's peak memory does not grow with its number of buildings (docs/city.md,
# "Memory"):
#   stream_memory_test.sh CORBEL_CLI FOOTPRINTS_DIR
# The Moosburg buildings within 120 m of its origin (the shared footprints), twice and 16 times
# side by side (1 km apart, ids suffixed), built streamed into a tileset, into one glb and into
# one glb with --compress (massing, and at full detail, where a compressed glb holds tens of kB of
# each building), and at full detail with --instances, plain and compressed, in parts of 64: the peak
# resident memory (GNU time's) of the 16 copies may exceed the two copies' by at most 2 kB for
# each building added. Two, not one: the glb writer holds up to 64 KiB of each kind of buffer
# before it spills, which a single copy of these buildings does not always fill, so against
# one copy that fixed cost would count as growth. What a streamed town holds of each building to the end is its place in
# the tiling, about 100 bytes; a whole read holds several kB of each (footprint, labels,
# properties), and the same two read whole must grow by more than the bound, or the test could
# not tell the two apart. jemalloc is asked to hand freed pages back at once, so that the peak
# is what is held, not what its 10 s decay has not yet returned (which depends on the timing).
set -euo pipefail
cli=$1
footprints=$2/moosburg_de.geojson
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[[ -x /usr/bin/time ]] || { echo "GNU time is not installed (Debian's time): run bash scripts/setup"; exit 1; }
[[ -f "$footprints" ]] || { echo "no $footprints"; exit 1; }
style=$source_dir/assets/styles/oldtown.json
node -e '
  const fs = require("fs"), fc = JSON.parse(fs.readFileSync(process.argv[1]));
  const flat = (c) => Array.isArray(c[0][0]) ? c.flatMap(flat) : c;
  const near = fc.features.filter((f) => {
    const p = flat(f.geometry.coordinates), n = p.length;
    const x = p.reduce((s, q) => s + q[0], 0) / n, y = p.reduce((s, q) => s + q[1], 0) / n;
    return Math.hypot(x, y) <= 120;
  });
  for (const copies of [2, 16]) {
    const out = [];
    for (let k = 0; k < copies; ++k)
      for (const f of near) {
        const g = JSON.parse(JSON.stringify(f));
        const move = (c) => Array.isArray(c[0]) ? c.map(move) : [c[0] + 1000 * k, c[1]];
        g.geometry.coordinates = move(g.geometry.coordinates);
        if (k) g.properties.source_id += "/" + k;
        out.push(g);
      }
    fs.writeFileSync(`${process.argv[2]}/x${copies}.geojson`, JSON.stringify({...fc, features: out}));
  }' "$footprints" "$work"

peak() {  # NAME SOURCE STREAM-BUILDINGS OUTPUT...: prints the peak resident memory, kB
  local name=$1 src=$2 parts=$3
  shift 3
  MALLOC_CONF=dirty_decay_ms:0,muzzy_decay_ms:0 /usr/bin/time -f %M -o "$work/$name.rss" "$cli" city "$src" --style "$style" --seed 1 --jobs 2 --detail "${detail:-massing}" \
    "${@/@/$work/$name}" --stream-buildings "$parts" >"$work/$name.json" 2>/dev/null ||
    [[ $? == 1 ]] || { echo "$name: city failed"; exit 1; }
  tail -1 "$work/$name.rss"
}
count() { node -p 'JSON.parse(require("fs").readFileSync(process.argv[1])).buildings' "$work/$1.json"; }
check() {  # OUTPUT...: the streamed peak's growth within the bound, the whole read's beyond it
  local one many added bound wholeOne wholeMany
  one=$(peak one "$work/x2.geojson" 64 "$@")
  many=$(peak many "$work/x16.geojson" 64 "$@")
  grep -q '"streamed":true' "$work/many.json" || { echo "not streamed: $(cat "$work/many.json")"; exit 1; }
  added=$(( $(count many) - $(count one) ))
  (( added > 1000 )) || { echo "only $added buildings added"; exit 1; }
  bound=$(( added * 2000 / 1024 ))  # kB
  wholeOne=$(peak whole-one "$work/x2.geojson" 0 "$@")
  wholeMany=$(peak whole-many "$work/x16.geojson" 0 "$@")
  echo "${detail:-massing} $*: streamed: $one kB for $(count one) buildings, $many kB for $(count many); read whole: $wholeOne kB, $wholeMany kB; bound +$bound kB"
  (( wholeMany - wholeOne > bound )) || { echo "read whole, the peak grew by only $((wholeMany - wholeOne)) kB: the bound tells nothing"; exit 1; }
  (( many - one <= bound )) || { echo "$1: streamed, the peak grew by $((many - one)) kB, more than $bound kB"; exit 1; }
}
check --tileset @ --tile-buildings 16
# One glb: its buffers and the JSON's per-building arrays go through temporary files.
check --out @.glb
check --out @.glb --compress
# At full detail the compressed buffers are encoded a chunk at a time as the buildings come; were a
# kind of buffer view encoded whole at the end, it would be held in memory whole.
detail=full check --out @.glb --compress
# With --instances each feature shape's copies (15.5 a building here; 96 bytes each in memory,
# 20 as written) go to a temporary file as the buildings come, so the same bound holds: were they
# held, they alone would take 1.5 kB of each building's 2 kB, on top of the 1 kB or so that the
# glb's buffers filling their memory add here.
detail=full check --out @.glb --instances
detail=full check --out @.glb --instances --compress
echo "stream memory: ok"
