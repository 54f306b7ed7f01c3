#!/usr/bin/env bash
# Grown units taken over by hand through real mouse and keys under Xvfb (xdotool), read back
# from the saved project. A one-storey site (3 m) with two seeds that already have their target
# area, so the grown model is the seeds themselves: A [1, 9] × [1, 9] and B [12, 16] × [1, 5].
#  1. a click on A selects the site; "Freeze Units" from the command search (F3) turns both
#     into unit objects in one undo step: the site keeps no seeds and grows around unit objects;
#  2. P, a drag on A's east wall (x = 9) with 5 typed and Enter pushes it with collide-and-
#     extrude: by hand, y 1..5 meets B 3 m out (x = 12), y 5..9 runs the whole 5 m (x = 14), so
#     A is [1, 12] × [1, 5] and [1, 14] × [5, 9]; one undo step ("Push unit wall");
#  3. Ctrl+Z undoes the push alone: A is its seed again;
#  4. a drag up on A's ceiling (z = 3) with 2 typed moves it by the nearest whole storey (3 m):
#     A becomes a double volume [1, 9] × [1, 9] × [0, 6]; one undo step ("Move unit ceiling").
set -euo pipefail
editor=$1 work=$2
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
project=$work/units.corbel
cat >"$project" <<'JSON'
{"format": "corbel", "version": 2, "name": "Units", "objects": [
  {"id": 1, "name": "Site", "growth": {"seed": 1, "steps": -1, "site": {
    "format": "corbel-growth-site", "version": 1, "envelope": {"origin": [0, 0], "size": [30, 20]},
    "storeys": 1, "storey_height": 3, "alpha": 0.3,
    "seeds": [{"at": [1, 1], "size": [8, 8], "target_area": 64}, {"at": [12, 1], "size": [4, 4], "target_area": 16}]}}}]}
JSON

log=$work/units.jsonl
"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['objects'] == 1 and not j.get('failed')"
wid=$(xdotool search --sync --onlyvisible --name 'units.corbel' | head -1)

echo "== 1: the site selected by a click on A, its units frozen from the command search"
read -r ax ay <<<"$(screen 5,5,3)"
xdotool mousemove --sync --window "$wid" "$ax" "$ay" click 1
wait_for "j['selection'] == ['Site']"
n=$(field "['actions_run']")
xdotool key F3
wait_for "j.get('search') == '' and j['actions_run'] == $n + 1"
xdotool type --delay 40 "Freeze Units"
wait_for "j.get('search') == 'Freeze Units'"
xdotool key Return
wait_for "j['last_action'] == 'growth.freeze' and j['objects'] == 3 and j['undo'] == 'Freeze the units of Site' and not j.get('failed')"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"

expect_parts() {  # the saved parts of unit $1 against $2 (rows [x0, y0, z0, x1, y1, z1], any order)
  python3 - "$project" "$1" "$2" <<'PY'
import json, sys
o = {x["name"]: x for x in json.load(open(sys.argv[1]))["objects"]}
got, want = sorted(o[sys.argv[2]]["unit"]["parts"]), sorted(json.loads(sys.argv[3]))
ok = len(got) == len(want) and all(abs(a - b) < 1e-9 for g, w in zip(got, want) for a, b in zip(g, w))
print(f"{sys.argv[2]}: {got}")
sys.exit(0 if ok else f"{sys.argv[2]} is {got}, expected {want}")
PY
}
python3 - "$project" <<'PY'
import json, sys
o = {x["name"]: x for x in json.load(open(sys.argv[1]))["objects"]}
assert set(o) == {"Site", "Site unit 1", "Site unit 2"}, list(o)
g = o["Site"]["growth"]
assert g.get("around_units") is True and g["site"]["seeds"] == [], g
assert o["Site unit 1"]["unit"]["parts"] == [[1, 1, 0, 9, 9, 3]], o["Site unit 1"]["unit"]
assert o["Site unit 2"]["unit"]["parts"] == [[12, 1, 0, 16, 5, 3]], o["Site unit 2"]["unit"]
print("frozen: two unit objects where the seeds stood; the site grows around them")
PY

echo "== 2: A's east wall pushed 5 m (typed) collides with B and extrudes past it"
xdotool mousemove --sync --window "$wid" "$ax" "$ay" key p
wait_for "j['last_action'] == 'tool.push_pull'"
read -r px py <<<"$(screen 9,3,1.5)"
xdotool mousemove --sync --window "$wid" "$px" "$py"
xdotool mousedown 1 mousemove --sync --window "$wid" $((px + 12)) $((py - 4)) mousemove --sync --window "$wid" $((px + 25)) $((py - 8))
xdotool type --delay 60 "5"
xdotool key Return
xdotool mouseup 1
wait_for "j['undo'] == 'Push unit wall' and j['selection'] == ['Site unit 1']"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"
expect_parts "Site unit 1" "[[1, 1, 0, 12, 5, 3], [1, 5, 0, 14, 9, 3]]"
expect_parts "Site unit 2" "[[12, 1, 0, 16, 5, 3]]"

echo "== 3: Ctrl+Z undoes the push alone"
xdotool key --clearmodifiers Escape ctrl+z
wait_for "j['undo'] == 'Freeze the units of Site' and j['dirty']"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"
expect_parts "Site unit 1" "[[1, 1, 0, 9, 9, 3]]"

echo "== 4: A's ceiling dragged up, 2 typed: one whole storey (3 m), a double volume"
read -r cx cy <<<"$(screen 5,5,3)"
xdotool mousemove --sync --window "$wid" "$cx" "$cy"
xdotool mousedown 1 mousemove --sync --window "$wid" "$cx" $((cy - 10)) mousemove --sync --window "$wid" "$cx" $((cy - 20))
xdotool type --delay 60 "2"
xdotool key Return
xdotool mouseup 1
wait_for "j['undo'] == 'Move unit ceiling' and j['selection'] == ['Site unit 1']"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"
expect_parts "Site unit 1" "[[1, 1, 0, 9, 9, 6]]"
expect_parts "Site unit 2" "[[12, 1, 0, 16, 5, 3]]"
kill "$pid"
trap - EXIT
echo "studio units test passed"
