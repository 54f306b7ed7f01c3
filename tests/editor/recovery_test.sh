#!/usr/bin/env bash
# Autosave under Xvfb, one recovery slot per open document:
#  1. the Fig. 1 house edited in one editor and the temple in another, both killed after their
#     autosave: the next start recovers one and saves it where it came from, the start after
#     that the other, and no recovery file is left;
#  2. a second editor on a file another has open is told so (stderr), and the two autosave
#     apart: two recovery files, neither written over the other.
set -euo pipefail
editor=$1 examples=$2 work=$3
source "$(dirname "$0")/test_log_lib.sh"  # wait_for, screen, under_xvfb
under_xvfb "$@"
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
count() { python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["objects"]))' "$1"; }
slots() { ls "$work"/state/recovery/*.corbel 2>/dev/null | wc -l; }
# Waits until the last line of a test log makes the Python expression $2 (over `j`) true.
wait_for() {
  local log=$1 what=$2 deadline=$((SECONDS + 90))
  while ((SECONDS < deadline)); do
    if [[ -s $log ]] && python3 -c 'import json,sys; j=json.loads(open(sys.argv[1]).read().splitlines()[-1]); sys.exit(0 if ('"$what"') else 1)' "$log"; then
      return 0
    fi
    sleep 0.2
  done
  echo "timed out waiting for $what in $log: $(tail -1 "$log" 2>/dev/null)"
  exit 1
}
edit() {  # $1: project, $2: test log; adds a box and autosaves it at once
  "$editor" --size 1000x700 --recover no --actions object.add_box --autosave-seconds 0 --test-log "$2" "$1" \
    >"$2.out" 2>&1 &
}

cp "$examples/house.corbel" "$work/house.corbel"
cp "$examples/temple.corbel" "$work/temple.corbel"
house=$(count "$work/house.corbel") temple=$(count "$work/temple.corbel")

echo "== two editors, two documents, both killed after their autosave"
edit "$work/house.corbel" "$work/house.log"
a=$!
edit "$work/temple.corbel" "$work/temple.log"
b=$!
wait_for "$work/house.log" "j['actions_run'] == 1 and j['dirty']"
wait_for "$work/temple.log" "j['actions_run'] == 1 and j['dirty']"
for _ in $(seq 1 50); do (($(slots) == 2)) && break; sleep 0.2; done
kill -9 "$a" "$b"
wait "$a" "$b" 2>/dev/null || true
[[ $(slots) -eq 2 ]] || { echo "expected two recovery files, found $(slots)"; ls -l "$work/state/recovery"; exit 1; }

echo "== the next two starts recover one each and save it home"
for _ in 1 2; do
  "$editor" --size 1000x700 --recover yes --actions file.save --quit-after-frames 8
done
[[ $(count "$work/house.corbel") -eq $((house + 1)) ]] || { echo "the house's box was not recovered"; exit 1; }
[[ $(count "$work/temple.corbel") -eq $((temple + 1)) ]] || { echo "the temple's box was not recovered"; exit 1; }
[[ $(slots) -eq 0 ]] || { echo "recovery files are left after both were saved: $(slots)"; exit 1; }
echo "both edits recovered: house $house -> $((house + 1)) objects, temple $temple -> $((temple + 1))"

echo "== two editors on one file: told, and autosaving apart"
edit "$work/house.corbel" "$work/first.log"
a=$!
wait_for "$work/first.log" "j['actions_run'] == 1 and j['dirty']"
edit "$work/house.corbel" "$work/second.log"
b=$!
wait_for "$work/second.log" "j['actions_run'] == 1 and j['dirty']"
grep -q "is open in another corbel (process $a)" "$work/second.log.out" ||
  { echo "the second editor was not told: $(cat "$work/second.log.out")"; exit 1; }
for _ in $(seq 1 50); do (($(slots) == 2)) && break; sleep 0.2; done
[[ $(slots) -eq 2 ]] || { echo "the two editors should autosave to two files, found $(slots)"; exit 1; }
kill -9 "$a" "$b"
wait "$a" "$b" 2>/dev/null || true
echo "recovery test passed"
