#!/usr/bin/env bash
# The studio's selection and placement through real mouse and keys under Xvfb (xdotool), read
# back from the editor's test log and from the saved projects. Two 4 m boxes, A centred on
# (−10, 0) and B on (10, 0), seen from the top (View > Top: x to the right, y up):
#  1. the pointer over B hovers it; B then a drag round A selects A alone; Ctrl+drag round both
#     selects both;
#  2. a click on A, then a drag of the gizmo's x arrow with 3.5 typed and Enter moves A by
#     exactly (3.5, 0, 0), one undo step ("Move A");
#  3. R, 90, Enter turns A a quarter about its base centre (−6.5, 0): its translation goes to
#     (−6.5, 0) + R90·(3.5 + 6.5, 0) = (−6.5, 10), its rotation to 90;
#  4. Ctrl+D duplicates it 6 m (its 4 m width and 2 m) along x: "A 2" at (−0.5, 10), turned 90;
#  5. Ctrl+C there, Ctrl+V in a second editor on a project in another folder: the pasted object
#     keeps its placement, and its plan background, relative to the first project's folder,
#     is written relative to the second's.
set -euo pipefail
editor=$1 work=$2
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work/one/images" "$work/two"
export CORBEL_STATE_DIR=$work/state
python3 - "$work/one/images/plan.png" <<'PY'
import struct, sys, zlib
# A 2 × 2 grey PNG, written by hand.
raw = b"".join(b"\x00" + b"\x80\x80\x80" * 2 for _ in range(2))
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
open(sys.argv[1], "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0))
                              + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
PY
cat >"$work/one/boxes.corbel" <<'JSON'
{"format": "corbel", "version": 2, "name": "Boxes", "objects": [
  {"id": 1, "name": "A", "box": {"origin": [-10, 0, 0], "size": [4, 4, 4]},
   "plan_background": {"image": "images/plan.png", "scale": 0.5, "origin": [0, 0], "opacity": 0.5}},
  {"id": 2, "name": "B", "box": {"origin": [10, 0, 0], "size": [4, 4, 4]}}]}
JSON
cat >"$work/two/empty.corbel" <<'JSON'
{"format": "corbel", "version": 2, "name": "Empty", "objects": []}
JSON

log=$work/one.jsonl
placement() {  # the saved placement of object $2 in project $1, as "x y z rotation"
  python3 -c 'import json,sys
o = [o for o in json.load(open(sys.argv[1]))["objects"] if o["name"] == sys.argv[2]][0]
p = o.get("placement", {})
t = p.get("translation", [0, 0, 0])
print(*[round(v, 9) for v in t], round(p.get("rotation", 0), 9))' "$1" "$2"
}
expect_placement() {
  local got
  got=$(placement "$1" "$2")
  [[ $got == "$3" ]] || { echo "$2 in $1: placement $got, expected $3"; exit 1; }
  echo "$2 placed at $got (translation x y z, rotation)"
}

"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --test-log "$log" --actions view.top,view.orthographic "$work/one/boxes.corbel" &
pid=$!
trap 'kill $pid 2>/dev/null || true; if [[ -n ${pid2:-} ]]; then kill $pid2 2>/dev/null || true; fi' EXIT
wait_for "j['actions_run'] == 2 and j['camera']['elevation'] == 90 and not j['camera']['orthographic']"
wid=$(xdotool search --sync --onlyvisible --name 'boxes.corbel' | head -1)

echo "== hover, box select with B, Ctrl+drag round both"
read -r bx by <<<"$(screen 10,0,4)"
xdotool mousemove --sync --window "$wid" "$bx" "$by"
wait_for "j['hover'] == 'B'"
# A drag starts 20 px outside its box's corner, but inside the view (its left edge is the
# splitter's, which would take the press).
read -r vx vy <<<"$(python3 -c 'import json,sys; v=json.loads(open(sys.argv[1]).read().splitlines()[-1])["view"]; print(int(v[0]), int(v[1]))' "$log")"
inside() { local v=$1 lo=${2%.*}; ((v < lo + 3)) && v=$((lo + 3)); echo "$v"; }
read -r x0 y0 x1 y1 <<<"$(screen -14,4,0 -6,-4,0 | tr '\n' ' ')"
sx=$(inside $((x0 - 20)) "$vx"); sy=$(inside $((y0 - 20)) "$vy")
xdotool mousemove --sync --window "$wid" "$sx" "$sy"
xdotool key b
xdotool mousedown 1 mousemove --sync --window "$wid" $((x0 + 5)) $((y0 + 5)) mousemove --sync --window "$wid" $((x1 + 20)) $((y1 + 20)) mouseup 1
wait_for "j['selection'] == ['A']"
read -r x0 y0 x1 y1 <<<"$(screen -14,4,0 14,-4,0 | tr '\n' ' ')"
sx=$(inside $((x0 - 20)) "$vx"); sy=$(inside $((y0 - 20)) "$vy")
xdotool mousemove --sync --window "$wid" "$sx" "$sy" keydown ctrl mousedown 1 \
  mousemove --sync --window "$wid" $((x0 + 5)) $((y0 + 5)) mousemove --sync --window "$wid" $((x1 + 20)) $((y1 + 20)) mouseup 1 keyup ctrl
wait_for "sorted(j['selection']) == ['A', 'B']"
echo "box selections: $(last | cut -c1-100)"

echo "== the gizmo's x arrow dragged with 3.5 typed moves A by 3.5 m"
read -r ax ay <<<"$(screen -10,0,4)"
xdotool mousemove --sync --window "$wid" "$ax" "$ay" click 1
wait_for "j['selection'] == ['A']"
# The arrow runs from the base centre (−10, 0, 0) along x for 0.15 of the camera's distance.
len=$(python3 -c 'import json,sys; print(0.15 * json.loads(open(sys.argv[1]).read().splitlines()[-1])["camera"]["distance"])' "$log")
read -r gx gy <<<"$(screen "$(python3 -c "print(-10 + 0.6 * $len)"),0,0")"
xdotool mousemove --sync --window "$wid" "$gx" "$gy" mousedown 1
xdotool mousemove --sync --window "$wid" $((gx + 15)) "$gy" mousemove --sync --window "$wid" $((gx + 40)) $((gy + 30))

xdotool type --delay 60 3.5
xdotool key Return
xdotool mouseup 1
wait_for "j['undo'] == 'Move A'"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"
expect_placement "$work/one/boxes.corbel" A "3.5 0.0 0.0 0.0"

echo "== R 90 Enter turns A a quarter about its base centre"
xdotool mousemove --sync --window "$wid" "$bx" "$by" key r
xdotool type --delay 60 90
xdotool key Return
wait_for "j['undo'] == 'Rotate A'"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"
expect_placement "$work/one/boxes.corbel" A "-6.5 10.0 0.0 90.0"

echo "== Ctrl+D duplicates A beside itself"
xdotool key --clearmodifiers ctrl+d
wait_for "j['objects'] == 3 and j['selection'] == ['A 2']"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"
expect_placement "$work/one/boxes.corbel" "A 2" "-0.5 10.0 0.0 90.0"

echo "== Ctrl+C here, Ctrl+V in another editor on a project in another folder"
xdotool key --clearmodifiers ctrl+c
wait_for "j['last_action'] == 'object.copy'"
log1=$log
log=$work/two.jsonl
"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --test-log "$log" "$work/two/empty.corbel" &
pid2=$!
pid1=$pid
pid=$pid2
wait_for "j['objects'] == 0"
wid2=$(xdotool search --sync --onlyvisible --name 'empty.corbel' | head -1)
xdotool windowactivate --sync "$wid2" 2>/dev/null || xdotool windowfocus --sync "$wid2"
xdotool mousemove --sync --window "$wid2" 640 400 key --clearmodifiers ctrl+v
wait_for "j['objects'] == 1 and j['selection'] == ['A 2']"
xdotool key --clearmodifiers ctrl+s
wait_for "not j['dirty']"
expect_placement "$work/two/empty.corbel" "A 2" "-0.5 10.0 0.0 90.0"
image=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["objects"][0]["plan_background"]["image"])' "$work/two/empty.corbel")
[[ $image == ../one/images/plan.png ]] || { echo "pasted background image: $image, expected ../one/images/plan.png"; exit 1; }
echo "pasted with its image read from one/ and written for two/: $image"
kill "$pid1" "$pid2"
trap - EXIT
echo "studio selection test passed"
