#!/usr/bin/env bash
# Typed lengths in the plan and profile panes through real mouse and keys under Xvfb (xdotool),
# read back from the saved project. A 10 × 6 house (corners (0, 0), (10, 0), (10, 6), (0, 6))
# on one profile, 3 m of wall under a 45° roof segment ((0, 3) to (1, 4)):
#  1. a click on edge 0 in the plan pane, 12.5 typed and Enter: corner 1 goes to (12.5, 0), the
#     rest stay ("Set edge length");
#  2. corner 2 dragged, 5 typed and Enter before the release: edge 1 (from corner 1) is 5 m
#     long; Ctrl+Z takes drag and length back together, corner 2 at (10, 6) again;
#  3. a click on the roof segment in the profile pane, 2 typed and Enter: its top at
#     (√2, 3 + √2), still at 45° ("Set segment length").
set -euo pipefail
editor=$1 work=$2
shots=${3:-}  # a folder for screenshots of the typed value (optional)
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
project=$work/house.corbel
cat >"$project" <<'JSON'
{"format": "corbel", "version": 2, "name": "House", "objects": [
  {"id": 1, "name": "House", "extrusion": {
    "plan": {"loops": [[[0, 0], [10, 0], [10, 6], [0, 6]]], "edge_profiles": [["hip", "hip", "hip", "hip"]]},
    "profiles": [{"name": "hip", "points": [[0, 0], [0, 3], [1, 4]], "tags": ["wall", "roof"]}]}}]}
JSON

log=$work/house.jsonl
# A screenshot for looking at (the editor writes no test log line while a number is typed, so
# it is given two seconds to draw it; the checks never depend on it).
shot() { [[ -z $shots ]] || { mkdir -p "$shots"; sleep 2; xwd -root -silent >"$shots/$1.xwd"; }; }
# The pixel halfway between two points of the log's last line ($1, $2: Python expressions).
middle() { python3 -c 'import json,sys; j=json.loads(open(sys.argv[1]).read().splitlines()[-1]); a, b = eval(sys.argv[2]), eval(sys.argv[3]); print(int(round((a[0] + b[0]) / 2)), int(round((a[1] + b[1]) / 2)))' "$log" "$1" "$2"; }
save() {
  xdotool key --clearmodifiers ctrl+s
  wait_for "not j['dirty']"
}
# Checks the saved project: $1 is Python over `plan` (the loop's corners) and `profile` (the
# hip profile's points) that must hold.
check() {
  python3 - "$project" "$1" <<'PY'
import json, math, sys
o = json.load(open(sys.argv[1]))["objects"][0]["extrusion"]
plan = o["plan"]["loops"][0]
profile = o["profiles"][0]["points"]
assert eval(sys.argv[2]), f"{sys.argv[2]} fails: plan {plan}, profile {profile}"
PY
}

"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --select House --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "'plan_corners' in j and 'profile_points' in j and j['active'] == 'House'"
wid=$(xdotool search --sync --onlyvisible --name 'house.corbel' | head -1)

echo "== edge 0 selected in the plan pane, 12.5 typed"
read -r x y <<<"$(middle "j['plan_corners'][0][0]" "j['plan_corners'][0][1]")"
xdotool mousemove --sync --window "$wid" "$x" "$y" click 1
xdotool type --delay 60 12.5
shot plan-typed
xdotool key Return
wait_for "j['undo'] == 'Set edge length (House)'"
save
check "all(math.dist(p, q) < 1e-9 for p, q in zip(plan, [[0, 0], [12.5, 0], [10, 6], [0, 6]]))"
echo "edge 0 is 12.5 m: $(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["objects"][0]["extrusion"]["plan"]["loops"][0])' "$project")"

echo "== corner 2 dragged with 5 typed: edge 1 is 5 m, one undo step"
read -r x y <<<"$(middle "j['plan_corners'][0][2]" "j['plan_corners'][0][2]")"
xdotool mousemove --sync --window "$wid" "$x" "$y"
xdotool mousedown 1 mousemove --sync --window "$wid" $((x + 12)) $((y - 8)) mousemove --sync --window "$wid" $((x + 25)) $((y - 15))
xdotool type --delay 60 5
shot plan-drag-typed
xdotool key Return
xdotool mouseup 1
wait_for "j['undo'] == 'Move corner (House)' and j['dirty']"
save
check "abs(math.dist(plan[1], plan[2]) - 5) < 1e-9 and all(math.dist(plan[i], q) < 1e-9 for i, q in ((0, [0, 0]), (1, [12.5, 0]), (3, [0, 6]))) and math.dist(plan[2], [10, 6]) > 0.1"
xdotool key --clearmodifiers ctrl+z
wait_for "j['undo'] == 'Set edge length (House)' and j['dirty']"
save
check "all(math.dist(p, q) < 1e-9 for p, q in zip(plan, [[0, 0], [12.5, 0], [10, 6], [0, 6]]))"
echo "dragged to 5 m and undone in one step"

echo "== the roof segment picked in the profile pane, 2 typed"
read -r x y <<<"$(middle "j['profile_points'][1]" "j['profile_points'][2]")"
xdotool mousemove --sync --window "$wid" "$x" "$y" click 1
xdotool type --delay 60 2
shot profile-typed
xdotool key Return
wait_for "j['undo'] == 'Set segment length (House)'"
save
check "profile[:2] == [[0, 0], [0, 3]] and math.dist(profile[2], [math.sqrt(2), 3 + math.sqrt(2)]) < 1e-9"
echo "roof segment 2 m at 45°: $(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["objects"][0]["extrusion"]["profiles"][0]["points"])' "$project")"
kill "$pid"
trap - EXIT
echo "plan dimensions test passed"
