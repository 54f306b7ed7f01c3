#!/usr/bin/env bash
# An extrusion built in stone from the editor's left panel, through real mouse and keys under
# Xvfb (xdotool), read back by corbel-cli statics --object (the strict LP on the stone model):
#  1. "Stone house, thin walls" (stone-house.corbel): steep heavy roof, no ties, 0.2 m walls;
#     corbel-cli says they fall;
#  2. *Make the walls stand* searches the wall thickness: one undo step, the saved walls are
#     thicker and corbel-cli says they stand; Ctrl+Z brings the thin walls back;
#  3. *Build in stone* unticked drops the masonry section (the object saves without it),
#     ticked again gives the defaults of core/stone_walls.h (0.5 m walls).
set -euo pipefail
editor=$1 cli=$2 examples=$3 work=$4
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, click_widget, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
project=$work/stone-house.corbel
cp "$examples/stone-house.corbel" "$project"
log=$work/stone.jsonl
thin="Stone house, thin walls"
save() {
  xdotool key --clearmodifiers ctrl+s
  wait_for "not j['dirty']"
}
verdict() {  # corbel-cli's strict verdict on the saved thin-walled house
  { "$cli" statics "$project" --object "$thin" --json 2>&1 || true; } |
    python3 -c 'import json,sys; j=json.loads(sys.stdin.read()); print("stands" if j["stands"] else "falls")'
}
section() {  # the saved masonry section of the thin-walled house, as JSON
  python3 -c 'import json,sys; o=[o for o in json.load(open(sys.argv[1]))["objects"] if o["name"] == sys.argv[2]][0]; print(json.dumps(o["extrusion"].get("masonry")))' "$project" "$thin"
}

echo "== 1: the thin walls fall"
test "$(verdict)" = falls

"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --select "$thin" --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['active'] == '$thin' and 'build in stone' in j.get('widgets', {})"
wid=$(xdotool search --sync --onlyvisible --name 'stone-house.corbel' | head -1)
# The stone section is at the foot of the left panel: once its verdict is in, scroll it into view.
WAIT_SECONDS=180 wait_for "'stone verdict' in j.get('widgets', {})"
xdotool mousemove --sync --window "$wid" 150 400 click --repeat 20 5
sleep 1

echo "== 2: Make the walls stand"
click_widget "stone make it stand"
WAIT_SECONDS=240 wait_for "j['undo'] == 'Make the stone walls of $thin stand'"
save
after=$(section)
echo "after: $after"
python3 -c 'import json,sys; m=json.loads(sys.argv[1]); assert m["thickness"] > 0.2 and m["course_height"] == 0.5 and m["covering_weight"] == 1500, m' "$after"
test "$(verdict)" = stands
xdotool key --clearmodifiers ctrl+z
wait_for "j['undo'] != 'Make the stone walls of $thin stand'"
save
python3 -c 'import json,sys; m=json.loads(sys.argv[1]); assert m["thickness"] == 0.2, m' "$(section)"

echo "== 3: Build in stone off and on"
click_widget "build in stone"
wait_for "j['undo'] == 'Walls not in stone'"
save
test "$(section)" = null
click_widget "build in stone"
wait_for "j['undo'] == 'Build the walls in stone'"
save
python3 -c 'import json,sys; m=json.loads(sys.argv[1]); assert m["thickness"] == 0.5 and m["course_height"] == 0.4, m' "$(section)"
kill "$pid"
trap - EXIT
echo "stone panel test passed"
