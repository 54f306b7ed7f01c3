#!/usr/bin/env bash
# The extrusion's ambiguity priority (Kelly & Wonka Sec. 4.8) in the left panel, through real
# mouse and keys under Xvfb (xdotool), read back from the saved project. A house saved with the
# manual priority:
#  1. opens showing "manual" in the Ambiguity combo (it once showed "minimise volume");
#  2. a click on the combo and on "minimise volume" saves "minimise_volume";
#  3. the same with "manual" saves "manual" again;
#  4. Ctrl+Z goes back to minimise volume, in the file and in the combo (each pick is one undo
#     step; picks of a list never merge as typed values do).
set -euo pipefail
editor=$1 work=$2
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, click_widget, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
project=$work/house.corbel
cat >"$project" <<'JSON'
{"format": "corbel", "version": 2, "name": "House", "objects": [
  {"id": 1, "name": "House", "extrusion": {"priority": "manual",
    "plan": {"loops": [[[0, 0], [10, 0], [10, 6], [0, 6]]], "edge_profiles": [["hip", "hip", "hip", "hip"]]},
    "profiles": [{"name": "hip", "points": [[0, 0], [0, 3], [1, 4]], "tags": ["wall", "roof"]}]}}]}
JSON
log=$work/house.jsonl
manual="manual (segment tags high, low)"

saved() {  # saves and checks the file's priority is $1
  xdotool key --clearmodifiers ctrl+s
  wait_for "not j['dirty']"
  python3 -c 'import json,sys; p=json.load(open(sys.argv[1]))["objects"][0]["extrusion"]["priority"]; assert p == sys.argv[2], f"saved {p}, expected {sys.argv[2]}"; print("saved", p)' "$project" "$1"
}

"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --select House --test-log "$log" "$project" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['active'] == 'House'"
wid=$(xdotool search --sync --onlyvisible --name 'house.corbel' | head -1)

echo "== 1: the combo shows manual"
wait_for "'ambiguity = $manual' in j.get('widgets', {})"
echo "== 2: minimise volume"
click_widget "ambiguity"
click_widget "ambiguity: minimise volume"
wait_for "'ambiguity = minimise volume' in j.get('widgets', {}) and j['dirty']"
saved minimise_volume
echo "== 3: manual again"
click_widget "ambiguity"
click_widget "ambiguity: $manual"
wait_for "'ambiguity = $manual' in j.get('widgets', {}) and j['dirty']"
saved manual
echo "== 4: Ctrl+Z"
xdotool key --clearmodifiers ctrl+z
wait_for "'ambiguity = minimise volume' in j.get('widgets', {}) and j['dirty']"
saved minimise_volume
kill "$pid"
trap - EXIT
echo "priority test passed"
