#!/usr/bin/env bash
# The user guide's first-ten-minutes tutorial, done by real mouse and keys under Xvfb
# (xdotool) exactly as the guide says, and read back from the saved project. Widgets are
# clicked where the test log says they were drawn (its "widgets", editor/widget_marks.h).
#  1. Object > Add > Extrusion > L (Hip Roof): the L plan (0, 0) (12, 0) (12, 5) (6, 5) (6, 10)
#     (0, 10), every edge on the hip profile;
#  2. a gable end: edge 1 (the east end) clicked in the plan pane, "gable" taken from the
#     profile library, then Assign profile… > gable;
#  3. a dormer: edge 0 (south) clicked, Add step here > Add (a dormer at its middle);
#  4. windows: edge 0 clicked, Add feature here, kind window, 0.1 along, Add; then its Repeat
#     set to row (to 0.9 of the wall); a door: edge 3 (in the L's corner, facing east), kind
#     door, 0.5 along, 0 m high;
#  5. push/pull: a click on the house, P, the east gable wall dragged with 2 typed and Enter: the plan's east end at
#     x = 14;
#  6. a second building: Ctrl+D duplicates the house beside it, R 90 Enter turns it;
#  7. a KIFS tower: Object > Add > KIFS Building puts it beside the buildings; a click on it,
#     then G Y -10 Enter moves it 10 m south;
#  8. Ctrl+S; the project holds the three objects with every value above, and nothing failed
#     to build.
# With a third argument, a folder, it leaves a screenshot of each step there (xwd) for the guide.
set -euo pipefail
editor=$1 work=$2
shots=${3:-}
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
project=$work/tutorial.corbel
echo '{"format": "corbel", "version": 2, "name": "Tutorial", "objects": []}' >"$project"
log=$work/tutorial.jsonl

# A screenshot for the guide (the log's last line is written once the frame settled, so the
# picture is the state the checks saw; a second lets the last frame reach the screen).
shot() { [[ -z $shots ]] || { mkdir -p "$shots"; sleep 1; xwd -root -silent >"$shots/$1.xwd"; }; }
# The centre of widget $1 on the log's last line (waits for it to be drawn).
widget() {
  wait_for "'$1' in j.get('widgets', {})"
  python3 -c 'import json,sys; r=json.loads(open(sys.argv[1]).read().splitlines()[-1])["widgets"][sys.argv[2]]; print(int((r[0] + r[2]) / 2), int((r[1] + r[3]) / 2))' "$log" "$1"
}
click_widget() {
  local at x y
  at=$(widget "$1") || { echo "$at"; exit 1; }
  read -r x y <<<"$at"
  xdotool mousemove --sync --window "$wid" "$x" "$y" click 1
}
# A value typed into slider or field $1: Ctrl+click makes a slider a text field; Ctrl+A selects
# what is there.
type_into() {
  local at x y
  at=$(widget "$1") || { echo "$at"; exit 1; }
  read -r x y <<<"$at"
  xdotool mousemove --sync --window "$wid" "$x" "$y" keydown ctrl click 1 keyup ctrl
  xdotool key --clearmodifiers ctrl+a
  xdotool type --delay 40 "$2"
  xdotool key Return
}
# Clicks plan edge $1 of the first loop in the plan pane, at fraction $2 along it (default the
# middle), and waits until it is the one selected edge.
click_edge() {
  local x y
  read -r x y <<<"$(python3 -c 'import json,sys; c=json.loads(open(sys.argv[1]).read().splitlines()[-1])["plan_corners"][0]; i=int(sys.argv[2]); t=float(sys.argv[3]); a, b = c[i], c[(i + 1) % len(c)]; print(int(round(a[0] + t * (b[0] - a[0]))), int(round(a[1] + t * (b[1] - a[1]))))' "$log" "$1" "${2:-0.5}")"
  xdotool mousemove --sync --window "$wid" "$x" "$y" click 1
  wait_for "j.get('plan_edges') == [[0, $1]] and 'plan: add step here' in j.get('widgets', {})"
}
# Runs menu path $1 ("Object", "Object/Add", ...) down to the action $2 by clicking each level.
menu() {
  local path=$1 action=$2 sofar=""
  IFS=/ read -ra levels <<<"$path"
  for level in "${levels[@]}"; do
    sofar=${sofar:+$sofar/}$level
    click_widget "menu: $sofar"
  done
  wait_for "'action: $action' in j.get('widgets', {})"
  [[ -z ${MENU_SHOT:-} ]] || shot "$MENU_SHOT"
  click_widget "action: $action"
}
view_centre() {
  python3 -c 'import json,sys; v=json.loads(open(sys.argv[1]).read().splitlines()[-1])["view"]; print(int(v[0] + v[2] / 2), int(v[1] + v[3] / 2))' "$log"
}
save() {
  xdotool key --clearmodifiers ctrl+s
  wait_for "not j['dirty']"
}

"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['objects'] == 0"
wid=$(xdotool search --sync --onlyvisible --name 'tutorial.corbel' | head -1)

echo "== 1: an L-shaped house"
MENU_SHOT=tutorial-1-menu menu Object/Add/Extrusion object.add_extrusion_l
wait_for "j['undo'] == 'Add L extrusion' and j['active'] == 'L plan' and 'plan_corners' in j and not j.get('failed')"
shot tutorial-1-house

echo "== 2: a gable end on edge 1"
click_edge 1
click_widget "profile: library"
click_widget "profile: library: gable"
wait_for "j['undo'].startswith('Add profile gable')"
click_widget "plan: assign profile"
click_widget "plan: assign profile: gable"
wait_for "j['undo'].startswith('Assign profile gable') and not j.get('failed')"
shot tutorial-2-gable

echo "== 3: a dormer on edge 0"
click_edge 0
click_widget "plan: add step here"
click_widget "add step: add"
wait_for "j['undo'].startswith('Add dormer') and not j.get('failed')"
shot tutorial-3-dormer

echo "== 4: a row of windows on edge 0, a door on edge 3"
click_edge 0 0.25  # its middle holds the dormer's marker
click_widget "plan: add feature here"
click_widget "add feature: kind"
click_widget "add feature: kind: window"
type_into "add feature: along" 0.1
click_widget "add feature: add"
wait_for "j['undo'].startswith('Add window')"
click_widget "feature: repeat"
click_widget "feature: repeat: row"
wait_for "j['undo'].startswith('Repeat window') and not j.get('failed')"
click_edge 3
click_widget "plan: add feature here"
click_widget "add feature: kind"
click_widget "add feature: kind: door"
type_into "add feature: along" 0.5
type_into "add feature: height" 0
click_widget "add feature: add"
wait_for "j['undo'].startswith('Add door') and not j.get('failed')"
shot tutorial-4-features

echo "== 5: push/pull the gable end 2 m out"
# A click on the house gives the 3D view the keys (the plan pane had them).
read -r cx cy <<<"$(screen 3,3,1.5)"
xdotool mousemove --sync --window "$wid" "$cx" "$cy" click 1
wait_for "j['active'] == 'L plan' and j['selection'] == ['L plan']"
xdotool key p
wait_for "j['last_action'] == 'tool.push_pull'"
read -r px py <<<"$(screen 12,2.5,1.5)"
xdotool mousemove --sync --window "$wid" "$px" "$py"
xdotool mousedown 1 mousemove --sync --window "$wid" $((px + 12)) $((py - 4)) mousemove --sync --window "$wid" $((px + 25)) $((py - 8))
xdotool type --delay 60 2
xdotool key Return
xdotool mouseup 1
wait_for "j['undo'] == 'Push wall' and not j.get('failed')"
xdotool key p
wait_for "j['last_action'] == 'tool.push_pull' and j['actions_run'] >= 2"
shot tutorial-5-push

echo "== 6: a second building"
xdotool key --clearmodifiers ctrl+d
wait_for "j['undo'].startswith('Duplicate') and j['objects'] == 2"
xdotool key r
xdotool type --delay 60 90
xdotool key Return
wait_for "j['undo'].startswith('Rotate') and not j.get('failed')"
shot tutorial-6-second

echo "== 7: a KIFS tower"
menu Object/Add object.add_kifs
wait_for "j['undo'] == 'Add KIFS building' and j['objects'] == 3 and j.get('active_in_view') is True"
save
added=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["objects"][2]["placement"]["translation"][1])' "$project")
# A click on the tower gives the view the keys (the menu had them), then G Y -10 Enter.
read -r cx cy <<<"$(view_centre)"
xdotool mousemove --sync --window "$wid" "$cx" "$cy" click 1
wait_for "j['active'] == 'KIFS building'"
xdotool key g key y
xdotool type --delay 60 -- -10
xdotool key Return
wait_for "j['undo'].startswith('Move') and not j.get('failed')"
xdotool key Home
wait_for "j['last_action'] == 'view.frame'"
shot tutorial-7-town
save

echo "== 8: the saved project"
python3 - "$project" "$added" <<'PY'
import json, math, sys
objects = json.load(open(sys.argv[1]))["objects"]
assert [o["name"] for o in objects] == ["L plan", "L plan 2", "KIFS building"], [o["name"] for o in objects]
house, second, tower = objects
e = house["extrusion"]
loop = e["plan"]["loops"][0]
want = [[0, 0], [14, 0], [14, 5], [6, 5], [6, 10], [0, 10]]
assert all(math.dist(p, q) < 1e-9 for p, q in zip(loop, want)) and len(loop) == 6, f"plan {loop}, expected {want}"
names = e["plan"]["edge_profiles"][0]
assert names[1] == "gable" and all(n == "hip" for i, n in enumerate(names) if i != 1), f"edge profiles {names}"
gable = next(p for p in e["profiles"] if p["name"] == "gable")
assert all(q[0] == 0 for q in gable["points"]), f"a gable end's profile is vertical: {gable}"
steps = e.get("steps", [])
assert len(steps) == 1 and steps[0]["name"] == "dormer" and steps[0]["anchor"]["edge"] == 0 and steps[0]["anchor"]["fraction"] == 0.5, f"steps {steps}"
anchors = {a["name"]: a for a in e["anchors"]}
w, d = anchors["window"], anchors["door"]
assert w["edge"] == 0 and abs(w["fraction"] - 0.1) < 1e-6 and w["height"] == 1 and w["repeat"]["kind"] == "row", f"window {w}"
assert abs(w["repeat"]["along"] - 0.9) < 1e-9, f"window row ends at {w['repeat']['along']}, expected 0.9"
assert d["edge"] == 3 and abs(d["fraction"] - 0.5) < 1e-6 and d["height"] == 0, f"door {d}"
assert second["extrusion"] == e, "the duplicate differs from the house"
p = second["placement"]
assert p["rotation"] == 90 and p["translation"][0] >= 14 + 2 - 1e-9, f"second building's placement {p}"
t = tower["placement"]["translation"]
# Added beside the scene: at least 4 m east of the second building, whose turned plan ends at
# x = 23 + 5 = 28 (its centre (16 + 7, 5), its 10 m depth now along x); then moved 10 m south.
assert t[0] >= 28 + 4, f"tower added at x = {t[0]}, inside the buildings"
assert abs(t[1] - (float(sys.argv[2]) - 10)) < 1e-9, f"tower at y = {t[1]}, added at {sys.argv[2]}, expected 10 m south"
print(f"plan {loop}; edge profiles {names}; dormer on edge 0; window row {w['fraction']}..{w['repeat']['along']} on edge 0; "
      f"door at {d['fraction']}; second building at {p['translation']} turned {p['rotation']} deg; tower at {t}")
PY
kill "$pid"
trap - EXIT
echo "tutorial test passed"
