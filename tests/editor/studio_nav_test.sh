#!/usr/bin/env bash
# The studio's navigation, layout and Add through real keys and mouse under Xvfb (xdotool),
# read back from the editor's test log (--test-log) and from the files it saves:
#  1. "1" looks from the front, orthographic; a click on the axis widget's Z knob turns to the
#     top view (elevation 90°, still orthographic); "5" toggles perspective and back;
#  2. in that top view a wheel step with the pointer off the centre zooms by 0.88 and moves the
#     target 12 % of the way to the point under the pointer (computed here from the log's view);
#  3. a 100 px drag of the left splitter widens the object panel by 100 px (the view starts
#     100 px further right); quit, start again: the layout is read back from settings.json;
#  4. the command search (F3): "bottom" and Enter looks from below;
#  5. Add of each kind through the command search: box, the gallery's rectangle, L, T, U and
#     courtyard, KIFS, a masonry template and a growth site; each is selected and in view, one
#     undo step each; Ctrl+S saves and the saved project has each kind (courtyard: two loops).
set -euo pipefail
editor=$1 example=$2 work=$3
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
log=$work/test-log.jsonl
cp "$example" "$work/studio.corbel"

WAIT_SECONDS=120
start() {
  : >"$log"
  "$editor" --size 1280x800 --recover no --autosave-seconds 3600 --test-log "$log" "$work/studio.corbel" &
  pid=$!
  trap 'kill $pid 2>/dev/null || true' EXIT
  wait_for "j['frame'] >= 0"
  wid=$(xdotool search --sync --onlyvisible --name 'studio.corbel' | head -1)
  xdotool windowfocus --sync "$wid" 2>/dev/null || true
}
# The 3D view's centre, and a point of it at fractions (fx, fy) of its width and height.
at() { field "['view']" | python3 -c 'import sys; x, y, w, h = eval(sys.stdin.read()); print(int(x + w * '"$1"'), int(y + h * '"$2"'))'; }
quit() {
  xdotool key --clearmodifiers ctrl+q
  for _ in $(seq 1 150); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
  if kill -0 "$pid" 2>/dev/null; then echo "the editor did not quit on Ctrl+Q"; exit 1; fi
  trap - EXIT
  wait "$pid" || { echo "the editor exited with $?"; exit 1; }
}

start
echo "== 1: front view on '1', the axis widget's Z turns to the top, '5' toggles the projection"
read -r mx my <<<"$(at 0.5 0.5)"
xdotool mousemove --sync --window "$wid" "$mx" "$my"
xdotool key 1
wait_for "j['last_action'] == 'view.front' and j['camera']['orthographic'] and abs(j['camera']['elevation']) < 1e-9 and abs(j['camera']['azimuth'] + 90) < 1e-9"
# The widget's centre is 56 px in from the view's top right corner; from the front, +Z points
# straight up, 42 px (its radius) above the centre.
read -r zx zy <<<"$(field "['view']" | python3 -c 'import sys; x, y, w, h = eval(sys.stdin.read()); print(int(x + w - 56), int(y + 56 - 42))')"
xdotool mousemove --sync --window "$wid" "$zx" "$zy" click 1
wait_for "j['camera']['orthographic'] and abs(j['camera']['elevation'] - 90) < 1e-9"
echo "top view from the axis widget: $(tail -1 "$log" | cut -c1-200)"
read -r mx my <<<"$(at 0.5 0.5)"
xdotool mousemove --sync --window "$wid" "$mx" "$my"
xdotool key 5
wait_for "j['last_action'] == 'view.orthographic' and not j['camera']['orthographic']"
xdotool key 5
wait_for "j['actions_run'] >= 3 and j['camera']['orthographic']"

echo "== 2: the wheel zooms towards the pointer"
read -r px py <<<"$(at 0.8 0.3)"
before=$(tail -1 "$log")
xdotool mousemove --sync --window "$wid" "$px" "$py"
xdotool click 4
expect=$(python3 - "$before" "$px" "$py" <<'PY'
import json, math, sys
j = json.loads(sys.argv[1]); px, py = float(sys.argv[2]), float(sys.argv[3])
x, y, w, h = j['view']; c = j['camera']
# From the top (azimuth -90): screen right is +X, screen up is +Y; the view shows a half
# height of distance * tan(20 deg) at the target.
half = c['distance'] * math.tan(math.radians(20))
ndx, ndy = 2 * (px - x) / w - 1, 1 - 2 * (py - y) / h
tx = c['target'][0] + 0.12 * ndx * half * w / h
ty = c['target'][1] + 0.12 * ndy * half
print(f"abs(j['camera']['distance'] - {c['distance'] * 0.88!r}) < 1e-6 and abs(j['camera']['target'][0] - {tx!r}) < 1e-6 and abs(j['camera']['target'][1] - {ty!r}) < 1e-6")
PY
)
wait_for "$expect"
echo "zoomed towards the pointer: $(tail -1 "$log" | cut -c1-200)"

echo "== 3: a splitter drag widens the object panel, kept in the settings"
vx=$(field "['view'][0]")
sx=$(python3 -c "print(int($vx - 3))")
sy=$(python3 -c "print(int($(field "['view'][1]") + 200))")
xdotool mousemove --sync --window "$wid" "$sx" "$sy" mousedown 1
xdotool mousemove --sync --window "$wid" $((sx + 50)) "$sy"
xdotool mousemove --sync --window "$wid" $((sx + 100)) "$sy"
xdotool mouseup 1
wait_for "abs(j['view'][0] - ($vx + 100)) < 0.5"
quit
python3 - "$CORBEL_STATE_DIR/settings.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert abs(s['panels']['left'] - 420) < 0.5, s  # 320 + 100
print("settings.json:", s)
PY
start
wait_for "abs(j['view'][0] - ($vx + 100)) < 0.5"
echo "the wider panel is back after a restart: view at x = $(field "['view'][0]")"

echo "== 4: the command search runs a command typed by name"
read -r mx my <<<"$(at 0.5 0.5)"
xdotool mousemove --sync --window "$wid" "$mx" "$my"
search() {
  local n
  read -r mx my <<<"$(at 0.5 0.5)"  # the view narrows when a selected object's panel opens
  xdotool mousemove --sync --window "$wid" "$mx" "$my"
  n=$(field "['actions_run']")
  xdotool key F3
  wait_for "j.get('search') == '' and j['actions_run'] == $n + 1"
  xdotool type --delay 40 "$1"
  wait_for "j.get('search') == '$1'"
  xdotool key Return
  wait_for "'search' not in j and j['actions_run'] >= $n + 2"
}
search "bottom"
wait_for "j['last_action'] == 'view.bottom' and abs(j['camera']['elevation'] + 90) < 1e-9 and j['camera']['orthographic']"
echo "ran from the search: $(tail -1 "$log" | cut -c1-160)"

echo "== 5: Add of each kind, each selected and in view, one undo step"
objects=$(field "['objects']")
n=0
add() {  # query, action id, the new object's name, its undo label
  search "$1"
  n=$((n + 1))
  wait_for "j['last_action'] == '$2' and j['objects'] == $objects + $n and j['active'] == '$3' and j['undo'] == '$4' and j.get('active_in_view') is True"
  echo "added $3: in view, undo '$4'"
}
add "add box" object.add_box "Box" "Add box"
add "rectangle hip" object.add_extrusion "Extrusion" "Add extrusion"
add "l hip" object.add_extrusion_l "L plan" "Add L extrusion"
add "t hip" object.add_extrusion_t "T plan" "Add T extrusion"
add "u hip" object.add_extrusion_u "U plan" "Add U extrusion"
add "courtyard" object.add_extrusion_courtyard "Courtyard plan" "Add Courtyard extrusion"
add "kifs building" object.add_kifs "KIFS building" "Add KIFS building"
add "arch on columns" object.add_masonry_arch-on-columns "Arch on Columns" "Add masonry arch-on-columns"
add "growth site" object.add_growth "Growth site" "Add growth site"
xdotool key --clearmodifiers ctrl+z
wait_for "j['objects'] == $objects + $n - 1 and j['undo'] == 'Add masonry arch-on-columns'"
xdotool key --clearmodifiers ctrl+shift+z
wait_for "j['objects'] == $objects + $n and j['undo'] == 'Add growth site'"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"
quit
python3 - "$work/studio.corbel" "$objects" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1])); before = int(sys.argv[2])
new = doc['objects'][before:]
kinds = {o['name']: [k for k in ('box', 'extrusion', 'kifs', 'masonry', 'growth', 'town') if k in o][0] for o in new}
assert kinds == {'Box': 'box', 'Extrusion': 'extrusion', 'L plan': 'extrusion', 'T plan': 'extrusion',
                 'U plan': 'extrusion', 'Courtyard plan': 'extrusion', 'KIFS building': 'kifs',
                 'Arch on Columns': 'masonry', 'Growth site': 'growth'}, kinds
by = {o['name']: o for o in new}
def corners(o): return [len(l) for l in o['extrusion']['plan']['loops']]
assert corners(by['L plan']) == [6] and corners(by['T plan']) == [8] and corners(by['U plan']) == [8], by
assert corners(by['Courtyard plan']) == [4, 4], corners(by['Courtyard plan'])
assert by['Arch on Columns']['masonry']['model'] == 'arch-on-columns'
print("saved kinds:", kinds)
PY
echo "studio navigation test passed"
