#!/usr/bin/env bash
# Masonry objects built into one structure by hand, through real mouse and keys under Xvfb
# (xdotool): the arch on columns of Whiting et al. Fig. 8 as three objects, the arch left 1 cm
# above its columns (beyond the 1 mm contact tolerance, so together it rests on nothing).
#  1. G, Z and a pixel of pointer movement: the face snap lays the arch's springing faces on the
#     columns' tops, so the saved arch stands at z = 1.5 exactly (to 1e-12), and corbel-cli
#     statics --together with no contact tolerance at all finds it resting on them;
#  2. the thin arch and slender columns (t = 0.09, w = 0.15: the Fig. 8 model that falls) do not
#     stand together: corbel-cli says so before;
#  3. *Make them stand together* in the statics panel searches every object's free parameters
#     at once, one undo step; what it saves stands by corbel-cli statics --together (the strict
#     LP), and Ctrl+Z puts every object back.
set -euo pipefail
editor=$1 cli=$2 work=$3
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, click_widget, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
project=$work/arcade.corbel
cat >"$project" <<'JSON'
{"format": "corbel", "version": 2, "name": "Arcade", "objects": [
  {"id": 1, "name": "Left", "placement": {"translation": [-1, 0, 0]},
   "masonry": {"model": "column", "parameters": {"drums": 1, "height": 1.5, "radius": 0.10606601717798213, "sides": 4}}},
  {"id": 2, "name": "Right", "placement": {"translation": [1, 0, 0]},
   "masonry": {"model": "column", "parameters": {"drums": 1, "height": 1.5, "radius": 0.10606601717798213, "sides": 4}}},
  {"id": 3, "name": "Arch", "placement": {"translation": [0, 0, 1.51]},
   "masonry": {"model": "semicircular-arch", "parameters": {"radius": 1.0, "thickness": 0.09, "voussoirs": 8}}}]}
JSON
log=$work/arcade.jsonl
save() {
  xdotool key --clearmodifiers ctrl+s
  wait_for "not j['dirty']"
}
together() {  # corbel-cli's verdict on the saved objects together, with no contact tolerance
  { "$cli" statics "$project" --together --contact-tolerance 0 --json 2>&1 || true; } | python3 -c '
import json, sys
text = sys.stdin.read()
try:
    j = json.loads(text)
except ValueError:
    print("error: " + text.strip().splitlines()[-1]); sys.exit(0)
print("stands" if j["stands"] else "falls")'
}

echo "== 0: 1 cm apart, the arch rests on nothing"
test "$(together)" != stands
together

"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --select Arch --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['active'] == 'Arch' and 'together header' in j.get('widgets', {})"
wid=$(xdotool search --sync --onlyvisible --name 'arcade.corbel' | head -1)

echo "== 1: G Z, the face snap lays the arch on its columns"
read -r px py <<<"$(screen 0,0,2.5)"
xdotool mousemove --sync --window "$wid" "$px" "$py"
sleep 0.3
xdotool key --clearmodifiers g
sleep 0.3
xdotool key --clearmodifiers z
sleep 0.3
xdotool mousemove --sync --window "$wid" "$((px + 1))" "$py"
sleep 0.5
xdotool key --clearmodifiers Return
wait_for "j['undo'] == 'Move Arch'"
save
python3 -c '
import json, sys
o = [o for o in json.load(open(sys.argv[1]))["objects"] if o["name"] == "Arch"][0]
t = o["placement"]["translation"]
assert abs(t[2] - 1.5) < 1e-12 and abs(t[0]) < 1e-12 and abs(t[1]) < 1e-12, t
print("arch at", t)' "$project"

echo "== 2: on its columns, the thin arch falls"
verdict=$(together)
echo "$verdict"
test "$verdict" = falls

echo "== 3: Make them stand together"
click_widget "together header"
wait_for "'make them stand together' in j.get('widgets', {})"
click_widget "make them stand together"
WAIT_SECONDS=240 wait_for "j['undo'] == 'Make the masonry objects stand together'"
save
verdict=$(together)
echo "$verdict"
test "$verdict" = stands
python3 -c '
import json, sys
objs = {o["name"]: o["masonry"]["parameters"] for o in json.load(open(sys.argv[1]))["objects"]}
print("after:", objs)
assert objs["Arch"]["thickness"] > 0.09 or objs["Left"]["radius"] > 0.106066, objs' "$project"
xdotool key --clearmodifiers ctrl+z
wait_for "j['undo'] == 'Move Arch'"
save
test "$(together)" = falls
kill "$pid"
trap - EXIT
echo "statics together test passed"
