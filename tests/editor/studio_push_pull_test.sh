#!/usr/bin/env bash
# Push/pull on a building through real mouse and keys under Xvfb (xdotool), read back from the
# saved project. A 10 × 6 house (corners (0, 0), (10, 0), (10, 6), (0, 6)), 3 m walls and a 45°
# hip roof on one profile shared by every edge, placed at (20, 5) and turned 90° (so the drags
# work in its own frame: object point (x, y, z) is world (20 − y, 5 + x, z)), seen from the
# south-east of the world:
#  1. P, a drag on the south wall with 1.5 typed and Enter pushes edge 0 out to y = −1.5: the
#     plan is 10 × 7.5 (the side edges 7.5 m long), one undo step ("Push wall");
#  2. a drag on the south roof with 30 typed turns the shared profile's roof segment to 30°
#     for every edge ("Turn roof");
#  3. the same on the west roof with Alt held and 60 typed gives edge 3 its own copy at 60°,
#     the other edges keep 30°;
#     the profile pane then shows that copy;
#  4. Ctrl+Z undoes step 3 alone; the placement never changes (one step per drag); the project is saved and read back.
set -euo pipefail
editor=$1 work=$2
shots=${3:-}  # a folder for screenshots while dragging (optional)
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
# A screenshot while dragging, for looking at (the editor writes no test log line mid-drag, so
# it is given two seconds to draw the typed value; the checks never depend on it).
shot() { [[ -z $shots ]] || { mkdir -p "$shots"; sleep 2; xwd -root -silent >"$shots/$1.xwd"; }; }
# Presses on the house's point $1 (x,y,z in its own frame), drags the pointer 25 px up and right, types $2 and
# Enter, releases; $3 (optional) is a key held during the press and the drag (not while typing:
# X11 sends no characters with Alt held); $4 names the screenshot taken before Enter.
drag_typed() {
  local px py
  read -r px py <<<"$(screen "$(python3 -c 'import sys; x, y, z = map(float, sys.argv[1].split(",")); print(f"{20 - y},{5 + x},{z}")' "$1")")"
  xdotool mousemove --sync --window "$wid" "$px" "$py"
  [[ -z ${3:-} ]] || xdotool keydown "$3"
  xdotool mousedown 1 mousemove --sync --window "$wid" $((px + 12)) $((py - 8)) mousemove --sync --window "$wid" $((px + 25)) $((py - 15))
  [[ -z ${3:-} ]] || xdotool keyup "$3"
  xdotool type --delay 60 "$2"
  shot "$4"
  xdotool key Return
  xdotool mouseup 1
}

"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['objects'] == 1 and not j.get('failed')"
wid=$(xdotool search --sync --onlyvisible --name 'house.corbel' | head -1)
read -r cx cy <<<"$(screen 5,3,1)"
xdotool mousemove --sync --window "$wid" "$cx" "$cy" key p
wait_for "j['last_action'] == 'tool.push_pull'"

echo "== the south wall pushed out 1.5 m (typed)"
drag_typed 5,0,1.5 1.5 "" push-wall
wait_for "j['undo'] == 'Push wall' and j['selection'] == ['House']"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"

echo "== the south roof turned to 30° (typed): every edge on the shared profile"
# 1 m in from the pushed eaves (y = −1.5) at 45°: (5, −0.5, 4).
drag_typed 5,-0.5,4 30 "" turn-roof
wait_for "j['undo'] == 'Turn roof' and j.get('profile') == 'hip'"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"

echo "== the west roof turned to 60° with Alt: edge 3 alone"
# 1 m in from the west eaves (x = 0) at the 30° roof: (1, 2.25, 3 + tan 30°).
drag_typed "1,2.25,$(python3 -c 'import math; print(3 + math.tan(math.radians(30)))')" 60 Alt_L turn-roof-alone
wait_for "j['undo'] == 'Turn roof' and j['dirty']"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"

check() {  # the saved plan and profiles against the hand values; $1: whether edge 3 has its own profile
  python3 - "$project" "$1" <<'PY'
import json, math, sys
o = json.load(open(sys.argv[1]))["objects"][0]["extrusion"]
own = sys.argv[2] == "own"
loop = o["plan"]["loops"][0]
want = [[0, -1.5], [10, -1.5], [10, 6], [0, 6]]
assert all(abs(a - b) < 1e-9 for p, q in zip(loop, want) for a, b in zip(p, q)), f"plan {loop}, expected {want}"
side = math.dist(loop[1], loop[2])
assert abs(side - 7.5) < 1e-9, f"east edge {side} m, expected 7.5"
profiles = {p["name"]: p["points"] for p in o["profiles"]}
names = o["plan"]["edge_profiles"][0] if "edge_profiles" in o["plan"] else [o["plan"]["profile"]] * 4  # one for all
def pitch(name):
    (w0, z0), (w1, z1) = profiles[name][1], profiles[name][2]
    return math.degrees(math.atan2(z1 - z0, w1 - w0))
shared = [names[i] for i in (0, 1, 2)]
assert len(set(shared)) == 1, f"edges 0, 1, 2 on {shared}"
assert abs(pitch(shared[0]) - 30) < 1e-9, f"shared roof pitch {pitch(shared[0])}, expected 30"
if own:
    assert names[3] != shared[0], "edge 3 has no profile of its own"
    assert abs(pitch(names[3]) - 60) < 1e-9, f"edge 3's roof pitch {pitch(names[3])}, expected 60"
else:
    assert names[3] == shared[0] and len(profiles) == 1, f"after undo edge 3 is on {names[3]} of {list(profiles)}"
p = json.load(open(sys.argv[1]))["objects"][0]["placement"]
assert p["translation"][:2] == [20, 5] and p["rotation"] == 90, f"placement {p} changed"
print(f"plan 10 x {side:.3f} m; roof pitch {pitch(shared[0]):.3f} deg on edges 0, 1, 2; edge 3 on {names[3]!r} at {pitch(names[3]):.3f} deg")
PY
}
check own
echo "== the profile pane shows the copy edge 3 turned on"
own=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["objects"][0]["extrusion"]["plan"]["edge_profiles"][0][3])' "$project")
wait_for "j.get('profile') == '$own' and '$own' != 'hip'"

echo "== Ctrl+Z undoes the Alt turn alone"
xdotool key --clearmodifiers ctrl+z
wait_for "j['undo'] == 'Turn roof' and j['dirty']"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"
check shared
kill "$pid"
trap - EXIT
echo "studio push/pull test passed"
