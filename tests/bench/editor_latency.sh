#!/usr/bin/env bash
# The editor's latency from a mouse event to the frame that shows the new shell, on the Fig. 1
# house (assets/examples/house.corbel) under Xvfb (llvmpipe): Push/Pull on the front wall, the
# pointer moved 2 px at a time 80 times (each move a new plan, a new shell, a new frame). The
# editor's --latency-log gives each presented state's latency (editor/latency.h); this writes
# their median, 90th percentile and largest as scripts/benchmarks' results JSON to $3.
#   tests/bench/editor_latency.sh EDITOR WORKDIR RESULTS.json
set -euo pipefail
editor=$1 work=$2 results=$3
source "$(dirname "$0")/../editor/test_log_lib.sh"  # wait_for, screen, under_xvfb
under_xvfb "$@"
root=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
cp "$root/assets/examples/house.corbel" "$work/house.corbel"
log=$work/house.jsonl latency=$work/latency.jsonl
"$editor" --size 1280x800 --recover no --autosave-seconds 3600 --test-log "$log" --latency-log "$latency" "$work/house.corbel" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wait_for "j['objects'] == 2 and not j.get('failed')"
wid=$(xdotool search --sync --onlyvisible --name 'house.corbel' | head -1)
read -r px py <<<"$(screen 3,0,1.2)"  # the front wall (y = 0), left of the door
xdotool mousemove --sync --window "$wid" "$px" "$py" key p
wait_for "j['last_action'] == 'tool.push_pull'"
xdotool mousedown 1
for i in $(seq 1 80); do
  xdotool mousemove --sync --window "$wid" "$px" $((py + 2 * i))
  sleep 0.05
done
xdotool mouseup 1
wait_for "j['undo'] == 'Push wall'"
kill "$pid"
trap - EXIT
python3 - "$latency" "$results" <<'PY'
import json, statistics, sys
ms = sorted(json.loads(line)["ms"] for line in open(sys.argv[1]) if line.strip())
if len(ms) < 10:
    sys.exit(f"editor_latency: only {len(ms)} frames showed a new shell (expected dozens)")
p90 = ms[min(len(ms) - 1, int(0.9 * len(ms)))]
out = {f"PushPullFig1/{k}": {"real_s": v / 1000, "frames": len(ms)}
       for k, v in (("median", statistics.median(ms)), ("p90", p90), ("max", ms[-1]))}
json.dump(out, open(sys.argv[2], "w"), indent=1)
print(f"{len(ms)} frames: median {statistics.median(ms):.1f} ms, p90 {p90:.1f} ms, max {ms[-1]:.1f} ms")
PY
