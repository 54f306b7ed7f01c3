#!/usr/bin/env bash
# The editor's input through real key presses and mouse moves under Xvfb (xdotool), with every
# frame slowed to about 5 fps (--frame-delay 200), read back from its test log (--test-log):
#  1. three boxes added by scripted actions, then three quick Ctrl+Z typed while one frame
#     lasts: all three are undone (the input queue keeps every tap), and the document is the
#     example again (not dirty);
#  2. a left drag of 100 px across the 3D view turns the camera by 40 degrees of azimuth (the
#     orbit rate, 0.4 degrees a pixel), and a wheel step zooms it in by the wheel's factor;
#  3. Ctrl+Q with nothing unsaved quits at once, with exit code 0;
#  4. on the Fig. 1 house, Delete with a plan corner selected and the pointer over the plan pane
#     deletes the corner, not the house; a click on the sky clears the selection, one on the house
#     selects it and Ctrl+click takes it out again; after a click on it Delete deletes the house,
#     one undo step that Ctrl+Z takes back;
#  5. a name typed into the Name field and left by a click elsewhere (no Enter) is kept.
set -euo pipefail
editor=$1 example=$2 work=$3
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
log=$work/test-log.jsonl


objects=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["objects"]))' "$example")
"$editor" --size 1280x800 --recover no --frame-delay 200 --autosave-seconds 3600 --test-log "$log" \
  --actions object.add_box,object.add_box,object.add_box "$example" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT

echo "== three boxes added, then three quick Ctrl+Z at 5 fps"
wait_for "j['actions_run'] == 3 and j['objects'] == $objects + 3 and j['dirty']"
wid=$(xdotool search --sync --onlyvisible --name 'corbel' | head -1)
xdotool mousemove --sync --window "$wid" 640 400
xdotool windowfocus --sync "$wid" 2>/dev/null || true
start=$(date +%s%N)
xdotool key --clearmodifiers --delay 15 ctrl+z ctrl+z ctrl+z
typed=$((($(date +%s%N) - start) / 1000000))
echo "typed three Ctrl+Z in $typed ms (a frame lasts at least 200 ms)"
wait_for "j['actions_run'] == 6 and j['last_action'] == 'edit.undo' and j['objects'] == $objects and not j['dirty']"
echo "all three undone: $(tail -1 "$log")"

echo "== a 100 px drag orbits by 40 degrees, a wheel step zooms by 0.88"
azimuth=$(field "['camera']['azimuth']")
distance=$(field "['camera']['distance']")
xdotool mousemove --sync --window "$wid" 600 400
xdotool mousedown 1
sleep 0.5
xdotool mousemove --sync --window "$wid" 700 400
sleep 0.5
xdotool mouseup 1
wait_for "abs(((j['camera']['azimuth'] - ($azimuth) + 40) + 180) % 360 - 180) < 1e-6"
xdotool click 4  # the wheel, away from the user: zoom in
wait_for "abs(j['camera']['distance'] - ($distance) * 0.88) < 1e-9 * ($distance)"
echo "orbited and zoomed: $(tail -1 "$log")"

echo "== Ctrl+Q with nothing unsaved quits"
xdotool key --clearmodifiers ctrl+q
for _ in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
if kill -0 "$pid" 2>/dev/null; then echo "the editor did not quit on Ctrl+Q"; exit 1; fi
trap - EXIT
wait "$pid" || { echo "the editor exited with $?"; exit 1; }

echo "== Delete over the plan pane removes the selected corner, not the house"
cp "$(dirname "$example")/house.corbel" "$work/house.corbel"
log=$work/house-log.jsonl
"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --select House --test-log "$log" "$work/house.corbel" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "'plan_corners' in j and j['active'] == 'House'"
wid=$(xdotool search --sync --onlyvisible --name 'house.corbel' | head -1)
corner=$(field "['plan_corners'][0][1]" | tr -d '[] ' | tr ',' ' ')
read -r cx cy <<<"$corner"
xdotool mousemove --sync --window "$wid" "${cx%.*}" "${cy%.*}"
xdotool click 1
xdotool key Delete
wait_for "j['objects'] == 2 and j['undo'] == 'Delete corner (House)' and len(j['plan_corners'][0]) == 3"
echo "corner deleted: $(tail -1 "$log" | cut -c1-160)"

echo "== clicks in the 3D view select: the sky clears, the house selects, Ctrl toggles it out"
# The 3D view's centre, where the camera looks at the house (the view narrows when the panes of
# a selected extrusion open, so it is read again after each change of selection).
centre() { field "['view']" | python3 -c 'import sys; x, y, w, h = eval(sys.stdin.read()); print(int(x + w / 2), int(y + h / 2))'; }
xdotool mousemove --sync --window "$wid" 560 100 click 1  # the sky: nothing there
wait_for "j['selection'] == [] and j['active'] is None"
read -r mx my <<<"$(centre)"
xdotool mousemove --sync --window "$wid" "$mx" "$my" click 1  # the house
wait_for "j['selection'] == ['House'] and j['active'] == 'House'"
read -r mx my <<<"$(centre)"
xdotool mousemove --sync --window "$wid" "$mx" "$my" keydown ctrl click 1 keyup ctrl
wait_for "j['selection'] == []"
echo "selected and toggled by clicks: $(tail -1 "$log" | cut -c1-120)"

echo "== Delete after a click on the house in the 3D view deletes it; Ctrl+Z brings it back"
read -r mx my <<<"$(centre)"
xdotool mousemove --sync --window "$wid" "$mx" "$my" click 1  # the view takes the keys from the plan pane
wait_for "j['active'] == 'House'"
xdotool key Delete
wait_for "j['objects'] == 1 and j['undo'] == 'Delete House' and j['active'] is None"
xdotool key --clearmodifiers ctrl+z
wait_for "j['objects'] == 2 and j['undo'] == 'Delete corner (House)'"

echo "== a name typed and left by a click is kept"
xdotool mousemove --sync --window "$wid" 100 62 click 1  # House in the object list
wait_for "j['active'] == 'House'"
xdotool mousemove --sync --window "$wid" 100 112 click 1  # its Name field
xdotool key --clearmodifiers ctrl+a
xdotool type --delay 30 Manor
read -r mx my <<<"$(centre)"
xdotool mousemove --sync --window "$wid" "$mx" "$my" click 1  # the house in the 3D view: the field is left
wait_for "j['active'] == 'Manor' and j['undo'] == 'Edit name of House'"
echo "renamed: $(tail -1 "$log" | cut -c1-120)"
kill "$pid"
trap - EXIT
echo "input test passed"
