#!/usr/bin/env bash
# The tape measure through real mouse and keys under Xvfb (xdotool), read back from the test
# log. A 10 × 6 house (3 m walls, 45° hip roof) placed at (20, 5) and turned 90°, so its own
# point (x, y, z) is world (20 − y, 5 + x, z) and the tape reads world coordinates:
#  1. M, a click 4 px from the house's corner (10, 0, 0) and one near (0, 0, 3): both snap to
#     the corners, world (20, 15, 0) and (20, 5, 3), and the tape reads √109 = 10.440 m;
#  2. Esc clears the tape;
#  3. a click near the middle of the wall's foot snaps to the edge's midpoint, world (20, 10, 0),
#     and a click on the open ground at (26, 10, 0) ends the tape on the ground (z = 0);
#  4. M again leaves the tool: a click on the house then selects it, and no step was added to
#     the history (measuring changes nothing).
set -euo pipefail
editor=$1 work=$2
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
project=$work/house.corbel
cat >"$project" <<'JSON'
{"format": "corbel", "version": 2, "name": "House", "objects": [
  {"id": 1, "name": "House", "placement": {"translation": [20, 5, 0], "rotation": 90}, "extrusion": {
    "plan": {"loops": [[[0, 0], [10, 0], [10, 6], [0, 6]]], "edge_profiles": [["hip", "hip", "hip", "hip"]]},
    "profiles": [{"name": "hip", "points": [[0, 0], [0, 3], [1, 4]], "tags": ["wall", "roof"]}]}}]}
JSON

log=$work/house.jsonl
# Clicks the house's own point $1 (x,y,z), taken through its placement.
click_at() {
  local px py
  read -r px py <<<"$(screen "$(python3 -c 'import sys; x, y, z = map(float, sys.argv[1].split(",")); print(f"{20 - y},{5 + x},{z}")' "$1")")"
  xdotool mousemove --sync --window "$wid" "$px" "$py" click 1
}

"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['objects'] == 1 and not j.get('failed')"
wid=$(xdotool search --sync --onlyvisible --name 'house.corbel' | head -1)
read -r cx cy <<<"$(screen 20,10,1)"
xdotool mousemove --sync --window "$wid" "$cx" "$cy" key m
wait_for "j['last_action'] == 'tool.measure'"

near() {  # the Python test that the tape's end $1 is the world point $2 within 1e-9
  echo "all(abs(a - b) < 1e-9 for a, b in zip(j['tape']['$1'], [$2]))"
}
echo "== 1: corner to corner"
# 0.08 m in from each corner on the wall's face (object y = 0): a few pixels off the corner.
click_at 9.92,0,0.08
click_at 0.08,0,2.92
wait_for "'tape' in j"
wait_for "j['tape']['from_snap'] == 'corner' and j['tape']['to_snap'] == 'corner' and $(near from 20,15,0) and $(near to 20,5,3)"
python3 - "$log" <<'PY'
import json, math, sys
t = json.loads(open(sys.argv[1]).read().splitlines()[-1])["tape"]
assert abs(t["length"] - math.sqrt(109)) < 1e-9, f"tape {t['length']} m, expected sqrt(109) = {math.sqrt(109):.6f}"
print(f"tape {t['length']:.6f} m from {t['from']} to {t['to']}")
PY

echo "== 2: Esc clears the tape"
xdotool key Escape
wait_for "'tape' not in j and j['last_action'] == 'tool.measure'"

echo "== 3: a midpoint to the ground"
click_at 5.05,0,0.05
read -r gx gy <<<"$(screen 26,10,0)"
xdotool mousemove --sync --window "$wid" "$gx" "$gy" click 1
wait_for "'tape' in j"
wait_for "j['tape']['from_snap'] == 'midpoint' and $(near from 20,10,0) and j['tape']['to_snap'] == 'on ground' and j['tape']['to'][2] == 0 and abs(j['tape']['to'][0] - 26) < 0.5"

echo "== 4: M leaves the tool; a click selects again; nothing was added to the history"
xdotool key m
wait_for "'tape' not in j"
test "$(field "['undo']")" = "" || { echo "measuring added a step to the history: $(field "['undo']")"; exit 1; }
click_at 5,0,1.5
wait_for "j['selection'] == ['House']"
kill "$pid"
trap - EXIT
echo "studio tape test passed"
