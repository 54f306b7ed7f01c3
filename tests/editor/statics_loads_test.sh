#!/usr/bin/env bash
# Loads placed by clicking blocks in the 3D view (the statics panel's *Place a load*), through
# real mouse and keys under Xvfb (xdotool), read back from the saved project and by corbel-cli
# statics --json, which resolves each load on the model independently of the editor. One
# square pier (0.4 × 0.4 × 2 m, a single drum: x, y in [-0.2, 0.2], z in [0, 2]):
#  1. with *Place a load* on, a click on the middle of the top face places 1000 kg there:
#     saved on "column/drum 0", force (0, 0, -9810) N, acting at z = 2 (the top face);
#  2. with *wind (Pa)* chosen, a click on the +x face at (0.2, 0, 1) places 600 Pa on it: the
#     CLI resolves it to 600 Pa x 0.8 m2 = 480 N pushing along -x, at the face's centre (0.2, 0, 1);
#  3. Ctrl+Z takes the wind back (each load is one undo step) and the weight stays;
#  4. the alpha/sqrt(2) box saves "conservative_friction": true, one undo step.
# With a fourth argument, a folder, it leaves a screenshot (xwd) of the two loads there for the guide.
set -euo pipefail
editor=$1 cli=$2 work=$3 shots=${4:-}
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, click_widget, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
project=$work/pier.corbel
cat >"$project" <<'JSON'
{"format": "corbel", "version": 2, "name": "Pier", "objects": [
  {"id": 1, "name": "Pier", "masonry": {"model": "column",
    "parameters": {"drums": 1, "height": 2.0, "radius": 0.28284271247461906, "sides": 4}, "friction": 2.0}}]}
JSON
log=$work/pier.jsonl

click_at() {  # a point of the pier, projected by the log's camera
  local px py
  read -r px py <<<"$(screen "$1")"
  xdotool mousemove --sync --window "$wid" "$px" "$py" click 1
}
save() {
  xdotool key --clearmodifiers ctrl+s
  wait_for "not j['dirty']"
}
loads() {  # the saved project's loads, as corbel-cli statics --json resolves them
  "$cli" statics "$project" --json | python3 -c 'import json,sys; print(json.dumps(json.load(sys.stdin).get("loads", [])))'
}

"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --select Pier --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['active'] == 'Pier' and 'place load' in j.get('widgets', {})"
wid=$(xdotool search --sync --onlyvisible --name 'pier.corbel' | head -1)

echo "== 1: a weight on the top face"
click_widget "place load"
sleep 0.5  # the view is the same size with the tool on; the click goes to the next frame
click_at 0,0,2
wait_for "j['dirty'] and j['undo'] == 'Add load 1'"
save
loads | python3 -c '
import json, sys
l = json.loads(sys.stdin.read())
assert len(l) == 1, l
w = l[0]
assert w["block"] == "column/drum 0" and w["name"] == "load 1", w
assert all(abs(a - b) < 1e-6 for a, b in zip(w["force"], [0, 0, -9810])), w
assert abs(w["at"][2] - 2) < 1e-9 and abs(w["at"][0]) < 0.05 and abs(w["at"][1]) < 0.05, w
print("weight:", w)'

echo "== 2: wind on the +x face"
click_widget "load kind"
click_widget "load kind: wind (Pa)"
wait_for "'load kind = wind (Pa)' in j.get('widgets', {})"
click_at 0.2,0,1
wait_for "j['undo'] == 'Add wind 1'"
save
loads | python3 -c '
import json, sys
l = json.loads(sys.stdin.read())
assert len(l) == 2, l
w = l[1]
assert w["block"] == "column/drum 0" and w["name"] == "wind 1", w
assert all(abs(a - b) < 1e-9 for a, b in zip(w["force"], [-480, 0, 0])), w
assert all(abs(a - b) < 1e-9 for a, b in zip(w["at"], [0.2, 0, 1])), w
print("wind:", w)'
[[ -z $shots ]] || { mkdir -p "$shots"; sleep 1; xwd -root -silent >"$shots/loads.xwd"; }

echo "== 3: Ctrl+Z takes the wind back"
xdotool key --clearmodifiers ctrl+z
wait_for "j['undo'] == 'Add load 1'"
save
test "$(loads | python3 -c 'import json,sys; print(len(json.loads(sys.stdin.read())))')" = 1

echo "== 4: alpha/sqrt(2)"
click_widget "place load"  # the tool off again
click_widget "conservative friction"
wait_for "j['undo'] == 'Use friction α/√2'"
save
python3 -c 'import json,sys; m=json.load(open(sys.argv[1]))["objects"][0]["masonry"]; assert m["conservative_friction"] is True and m["friction"] == 2.0, m; print("saved", m["friction"], m["conservative_friction"], m["kern"])' "$project"
kill "$pid"
trap - EXIT
echo "statics loads test passed"
