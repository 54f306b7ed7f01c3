# Shared by the editor's xdotool tests: read the editor's --test-log (JSON lines, one a frame).
# They use the caller's globals: $log (the test log) and $pid (the editor's process);
# WAIT_SECONDS (default 90) bounds each wait.

# Runs the calling script again inside Xvfb (one 1280 × 800 screen) unless it is already there:
# call it first, with the script's own arguments.
under_xvfb() {
  [[ -z ${CORBEL_INSIDE_XVFB:-} ]] || return 0
  command -v xvfb-run >/dev/null || { echo "xvfb-run is missing (scripts/setup installs it)"; exit 1; }
  command -v xdotool >/dev/null || { echo "xdotool is missing (scripts/setup installs it)"; exit 1; }
  exec env CORBEL_INSIDE_XVFB=1 xvfb-run -a -s "-screen 0 1280x800x24" bash "$0" "$@"
}

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

# Window pixels of scene points ("x,y,z" each), from the camera and view of the log's last line
# (render/camera: OrbitCamera; perspective or orthographic; straight down, up on the screen is
# −(cos az, sin az)).
screen() {
  python3 - "$log" "$@" <<'PY'
import json, math, sys
j = json.loads(open(sys.argv[1]).read().splitlines()[-1])
c, (vx, vy, vw, vh) = j["camera"], j["view"]
az, el, d = math.radians(c["azimuth"]), math.radians(c["elevation"]), c["distance"]
t = c["target"]
back = (math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el))
eye = [t[i] + d * back[i] for i in range(3)]
up = (-math.cos(az), -math.sin(az), 0.0) if abs(c["elevation"]) > 89.9 else (0.0, 0.0, 1.0)
f = [-b for b in back]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a): l = math.sqrt(sum(x * x for x in a)); return tuple(x / l for x in a)
s = norm(cross(f, up)); u = cross(s, f)
focal = 1 / math.tan(math.radians(40) / 2)
for arg in sys.argv[2:]:
    p = [float(v) for v in arg.split(",")]
    q = [p[i] - eye[i] for i in range(3)]
    x, y, z = sum(q[i] * s[i] for i in range(3)), sum(q[i] * u[i] for i in range(3)), sum(q[i] * f[i] for i in range(3))
    if c.get("orthographic"):  # parallel rays: the view is 2 d tan(fov/2) tall at any depth
        nx, ny = focal * x / (d * vw / vh), focal * y / d
    else:
        nx, ny = focal * x / (z * vw / vh), focal * y / z
    print(int(round(vx + (nx + 1) / 2 * vw)), int(round(vy + (1 - ny) / 2 * vh)))
PY
}

# Clicks the middle of the widget the log names $1 (editor/widget_marks.h), once it is drawn; uses
# the caller's $wid (the editor's window).
click_widget() {
  wait_for "'$1' in j.get('widgets', {})"
  local x y
  read -r x y <<<"$(python3 -c 'import json,sys; r=json.loads(open(sys.argv[1]).read().splitlines()[-1])["widgets"][sys.argv[2]]; print(int((r[0] + r[2]) / 2), int((r[1] + r[3]) / 2))' "$log" "$1")"
  xdotool mousemove --sync --window "$wid" "$x" "$y" click 1
}
