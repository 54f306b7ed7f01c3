#!/usr/bin/env bash
# A KIFS building that follows another object is drawn in the editor's 3D view: the screenshot
# of assets/examples/kifs-on-house.corbel (the box facade carved from the hidden Fig. 1 house)
# must differ from the same project with the ornament hidden over at least 2 % of the viewport
# (screenshot_check). Before the editor baked followers' masses, both pictures were the ground
# alone. The screenshot run waits for the bake (a scripted run waits for its workers).
set -euo pipefail
editor=$1 check=$2 examples=$3 work=$4
source "$(dirname "$0")/test_log_lib.sh"  # under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
cp "$examples/kifs-on-house.corbel" "$work/shown.corbel"
python3 - "$work/shown.corbel" "$work/hidden.corbel" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
ornament = [o for o in d["objects"] if "kifs" in o][0]
assert ornament["kifs"]["mass"]["footprint"] == "object", ornament["kifs"]["mass"]
ornament["visible"] = False
json.dump(d, open(sys.argv[2], "w"))
PY
for which in shown hidden; do
  "$editor" --size 1280x800 --recover no --autosave-seconds 0 --screenshot "$work/$which.png" --quit-after-frames 20 \
    "$work/$which.corbel" >"$work/$which.log" 2>&1
done
if grep -q "KIFS building" "$work/shown.log"; then cat "$work/shown.log"; exit 1; fi
"$check" "$work/shown.png" "$work/hidden.png" 0.02
echo "kifs follower test passed"
