#!/usr/bin/env bash
# The KIFS panel's View through real mouse and keys under Xvfb (xdotool): on the H preset
# (its inner shell fills the facade's openings), a click selects the building; F12 saves the
# shaded view; the View combo, clicked open, gives "Fractal alone (Fig. 3c)" and then "Facade
# ids (Fig. 5-6)", each saved with F12. Each picture must differ from the shaded one over part
# of the 3D view (screenshot_check, the KIFS panel left out): the mode reached the ray-marcher.
# The editor's screenshots are PNGs of the window (View > Save Screenshot, NAME-shot-N.png).
set -euo pipefail
editor=$1 check=$2 kifs=$3 work=$4
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, click_widget, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
project=$work/fractal.corbel
height=$(python3 - "$kifs/h.json" "$project" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
json.dump({"format": "corbel", "version": 2, "name": "Fractal",
           "objects": [{"id": 1, "name": "Fractal", "kifs": spec}]}, open(sys.argv[2], "w"))
print(spec["mass"]["height"])
PY
)
log=$work/view.jsonl
"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['objects'] == 1 and not j.get('failed')"
wid=$(xdotool search --sync --onlyvisible --name 'fractal.corbel' | head -1)

shot() {  # F12, then waits for NAME-shot-$1.png
  sleep 1.5  # the ray-marched layer refines to full size once the view is still
  xdotool mousemove --sync --window "$wid" 700 60 key F12
  local deadline=$((SECONDS + 60))
  until [[ -s $work/fractal-shot-$1.png ]]; do
    ((SECONDS < deadline)) || { echo "no screenshot $1"; exit 1; }
    sleep 0.2
  done
}

echo "== the building selected by a click, the shaded view saved"
read -r bx by <<<"$(screen 0,0,"$(python3 -c "print($height / 2)")")"
xdotool mousemove --sync --window "$wid" "$bx" "$by" click 1
wait_for "j['selection'] == ['Fractal'] and 'kifs: view = Shaded' in j.get('widgets', {})"
shot 1
pane=$(python3 -c 'import json,sys; v=json.loads(open(sys.argv[1]).read().splitlines()[-1])["view"]; print(int(1280 - v[0] - v[2]))' "$log")

pick() {  # the View combo opened by a click, then the item $1
  click_widget "kifs: view"
  click_widget "kifs: view: $1"
  wait_for "'kifs: view = $1' in j['widgets']"
}
echo "== Fractal alone"
pick "Fractal alone (Fig. 3c)"
shot 2
echo "== Facade ids"
pick "Facade ids (Fig. 5-6)"
shot 3
kill "$pid"
trap - EXIT
"$check" "$work/fractal-shot-2.png" "$work/fractal-shot-1.png" 0.005 "$pane"
"$check" "$work/fractal-shot-3.png" "$work/fractal-shot-1.png" 0.05 "$pane"
echo "kifs view test passed"
