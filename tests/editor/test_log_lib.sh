# Shared by the editor's xdotool tests: read the editor's --test-log (JSON lines, one a frame).
# They use the caller's globals: $log (the test log) and $pid (the editor's process);
# WAIT_SECONDS (default 90) bounds each wait.

# The last line of the test log, and a field of it (python3 reads the JSON): field "['view'][0]".
last() { tail -1 "$log"; }
field() { python3 -c 'import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])'"$1"')' "$log"; }

# Waits until the last line of the log makes the Python expression $1 (over `j`) true; fails
# the test if the editor exits or the time runs out, printing the last line.
wait_for() {
  local what=$1 deadline=$((SECONDS + ${WAIT_SECONDS:-90}))
  while ((SECONDS < deadline)); do
    kill -0 "$pid" 2>/dev/null || { echo "the editor exited while waiting for: $what"; exit 1; }
    if [[ -s $log ]] && python3 -c 'import json,sys; j=json.loads(open(sys.argv[1]).read().splitlines()[-1]); sys.exit(0 if ('"$what"') else 1)' "$log"; then
      return 0
    fi
    sleep 0.2
  done
  echo "timed out waiting for: $what"
  echo "last line: $(last 2>/dev/null)"
  exit 1
}
