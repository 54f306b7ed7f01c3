#!/usr/bin/env bash
# The editor under Xvfb, as a user would meet it (its command line first: --help, --version and
# bad options exit 2 before any window opens):
#  1. it opens the example and its screenshot shows the model (compared with an empty project);
#  2. an edit made by a scripted action is autosaved to the recovery file while unsaved, and a
#     new session recovers it;
#  3. the Fig. 4 (j–n) house is built through the plan and profile panes' operations by an edit
#     script, with a screenshot after each stage, and the result is a closed shell;
#  4. a plan traced over a background image, with a forced step, shows the image in the plan
#     pane (the shot differs from the same plan without it) and stays one closed shell; a
#     missing image is reported in the log and the editor carries on;
#  5. the masonry arch opens with its statics panel, and Make It Stand (a scripted action)
#     changes it into an arch that the CLI's analysis calls standing; simulated for a second
#     without its keystone (scripted actions), the arch in the 3D view is no longer the design,
#     and the Document is unchanged (nothing to recover);
#  6. a KIFS building is ray-marched in the 3D view: with its panel open, the shot differs from
#     the same project with the building hidden;
#  7. two growth.step actions on the Alpha site grown 10 steps save it grown 12, and the saved
#     site builds as closed shells;
#  8. form completion on the grown Alpha site: seeds from the model, Generate, Fit, Extrude adds
#     unit objects that build as closed shells (the shot differs from the site alone); undone, the
#     document is the untouched example (nothing to recover); redone (Ctrl+Y), the same units.
#  9. the growth site editor on Alpha: Add Core (a scripted action) saves a fifth core, 3 x 3 m at
#     the envelope's first free grid point (0, 0), and the site still builds as closed shells;
#     sliced two storeys down with the statistics and the view maps shown, the shot differs from
#     the site alone; undone, the document is the untouched example (nothing to recover).
#  9a. the Alpha model grown on GL view maps (the default) and, with growth.gl_view_maps, on the
#     exact ones, or with growth.gl_pixel_next on 0.5 m GL pixels: the inspector shots differ from
#     the default's (another model, other maps) and nothing is recovered;
#  9b. the Site tab's frame on Alpha: Add a Storey and Widen the Site (scripted actions) save 6
#     storeys and a 95 x 50 m box, the site still builds as closed shells and the shot (the Site
#     tab with its envelope fields) differs from the site alone; undone twice, nothing to recover.
# 10. a town (the old-town example): the next building picked and its type overridden (scripted
#     actions) is saved as an override and the 3D view differs from the town as styled; undone, the
#     document is the untouched example (nothing to recover);
# 10b. the next building's first edge picked and given the style's next profile (scripted
#     actions) is saved as an edge override ("0:0") and the town still builds;
# 11. a street added beside that town and bent (scripted actions) is saved, builds its plots as
#     houses (the saved project checks closed) that show in the 3D view; undone twice, nothing.
set -euo pipefail
editor=$1 cli=$2 check=$3 example=$4 work=$5 script=${6:-}
rm -rf "$work" && mkdir -p "$work"
export CORBEL_STATE_DIR=$work/state
command -v xvfb-run >/dev/null || { echo "xvfb-run is missing (scripts/setup installs it)"; exit 1; }
run() { xvfb-run -a -s "-screen 0 1440x900x24" "$editor" --size 1440x900 "$@"; }
# The autosaved document of the last run (one recovery slot per open document), or "".
recovery() { ls "$work"/state/recovery/*.corbel 2>/dev/null | head -1; }

echo "== the command line: --help, --version and bad options, before any window opens"
"$editor" --help | grep -q -- "--recover" || { echo "corbel --help does not list --recover"; exit 1; }
"$editor" --version | grep -q "^corbel [0-9.]* (project format [0-9]*)$" || { echo "corbel --version"; exit 1; }
for bad in "--bogus" "--size 100x100" "--recover maybe" "--quit-after-frames" "a.corbel b.corbel"; do
  set +e
  # shellcheck disable=SC2086
  message=$("$editor" $bad 2>&1 >/dev/null)
  code=$?
  set -e
  [[ $code -eq 2 && $message == "corbel: "* ]] || { echo "corbel $bad: exit $code, '$message' (expected 2)"; exit 1; }
done

echo "== screenshot of the example and of an empty project"
run --recover no --screenshot "$work/model.png" --quit-after-frames 8 "$example"
run --recover no --screenshot "$work/empty.png" --quit-after-frames 8
"$check" "$work/model.png" "$work/empty.png" 0.05

echo "== autosave of unsaved work, then recovery"
objects_before=$("$cli" check "$example" | tail -1)
run --recover no --actions object.add_box --autosave-seconds 0 --quit-after-frames 8 "$example"
test -f "$(recovery)" || { echo "no recovery file was written"; exit 1; }
objects_after=$("$cli" check "$(recovery)" | tail -1)
echo "example: $objects_before; recovery: $objects_after"
before=$(sed -E 's/.*"objects":([0-9]+).*/\1/' <<<"$objects_before")
after=$(sed -E 's/.*"objects":([0-9]+).*/\1/' <<<"$objects_after")
[[ $after -eq $((before + 1)) ]] || { echo "recovery file should hold the added box"; exit 1; }
cmp -s "$example" "$(recovery)" && { echo "recovery must not be the untouched example"; exit 1; }
run --recover yes --screenshot "$work/recovered.png" --quit-after-frames 8
"$check" "$work/recovered.png" "$work/empty.png" 0.05
if [[ -n $script ]]; then
  echo "== the Fig. 4 house by edit script"
  rm -rf "$work/state"
  run --recover no --script "$script" --script-shots "$work/shots" --autosave-seconds 0 --quit-after-frames 40
  shots=("$work"/shots/*.png)
  [[ ${#shots[@]} -eq 4 ]] || { echo "expected a screenshot per stage (4), found ${#shots[@]}"; exit 1; }
  for s in "${shots[@]}"; do "$check" "$s" "$work/empty.png" 0.05; done
  test -f "$(recovery)" || { echo "the scripted document was not autosaved"; exit 1; }
  summary=$("$cli" check "$(recovery)" | tail -1)
  echo "scripted house: $summary"
  [[ $summary == '{"objects":1,"failed":0}' ]] || { echo "the scripted house should be one closed shell"; exit 1; }
fi
echo "== tracing over a background image, and a missing one"
image=$(cd "$(dirname "$example")/../../docs/images" && pwd)/house.png
trace() {  # $1: the image (or nothing), $2: the shots folder
  {
    echo '{"stage": "traced", "op": "new_extrusion", "name": "T", "profile": "hip", "points": [[0, 0], [12, 0], [12, 8], [0, 8]]}'
    [[ -n $1 ]] && echo '{"stage": "traced", "op": "set_background", "object": "T", "image": "'"$1"'", "scale": 0.01, "origin": [-2, -2], "opacity": 0.8}'
    echo '{"stage": "traced", "op": "add_forced_step", "object": "T", "loop": 0, "edge": 0, "points": [[7, 1], [10, 1], [10, -2], [7, -2]], "height": 0, "profile": "hip"}'
  } > "$work/trace.jsonl"
  rm -rf "$work/state"
  run --recover no --script "$work/trace.jsonl" --script-shots "$2" --autosave-seconds 0 --quit-after-frames 30 > "$work/trace.log" 2>&1
}
trace "$image" "$work/traced"
summary=$("$cli" check "$(recovery)" | tail -1)
[[ $summary == '{"objects":1,"failed":0}' ]] || { echo "the traced plan with its forced step should be one closed shell: $summary"; exit 1; }
grep -q '"plan_background"' "$(recovery)" || { echo "the background was not saved with the object"; exit 1; }
trace "" "$work/untraced"
"$check" "$work/traced/01-traced.png" "$work/untraced/01-traced.png" 0.02
trace "$work/no-such-image.png" "$work/missing"
test -f "$work/missing/01-traced.png" || { echo "a missing background image stopped the editor"; exit 1; }
echo "== the statics panel of the masonry arch, and Make It Stand"
masonry=$(dirname "$example")/masonry-arch.corbel
run --recover no --select "Arch on columns" --screenshot "$work/masonry.png" --quit-after-frames 8 "$masonry"
"$check" "$work/masonry.png" "$work/empty.png" 0.02
"$cli" statics "$masonry" --json | grep -q '"stands":false' || { echo "the example arch should not stand as saved"; exit 1; }
rm -rf "$work/state"
run --recover no --select "Arch on columns" --actions statics.make_stand --autosave-seconds 0 \
  --screenshot "$work/masonry-standing.png" --quit-after-frames 8 "$masonry"
test -f "$(recovery)" || { echo "Make It Stand changed nothing (no recovery file)"; exit 1; }
stood=$("$cli" statics "$(recovery)" --json)
echo "after Make It Stand: $stood"
grep -q '"stands":true' <<<"$stood" || { echo "the arch should stand after Make It Stand"; exit 1; }
echo "== the energy landscape over the arch's two free parameters (Fig. 8)"
rm -rf "$work/state"
run --recover no --select "Arch on columns" --actions statics.landscape_grid --autosave-seconds 0 \
  --screenshot "$work/masonry-grid.png" --quit-after-frames 8 "$masonry"
test ! -e "$(recovery)" || { echo "choosing the landscape's parameters must not change the Document"; exit 1; }
# The grid of coloured cells replaces the one-parameter plot in the panel.
"$check" "$work/masonry-grid.png" "$work/masonry.png" 0.005
echo "== the collapse simulation: the arch without its keystone, a second on"
rm -rf "$work/state"
run --recover no --select "Arch on columns" --actions statics.sim_remove --autosave-seconds 0 \
  --screenshot "$work/collapse-0s.png" --quit-after-frames 8 "$masonry"
run --recover no --select "Arch on columns" --actions statics.sim_remove,statics.simulate --autosave-seconds 0 \
  --screenshot "$work/collapse-1s.png" --quit-after-frames 8 "$masonry"
test ! -e "$(recovery)" || { echo "a simulation must not change the Document (it was autosaved)"; exit 1; }
# Only the 3D view counts (the statics panel's numbers change too): the falling voussoirs and the
# gap they leave differ from the arch as built.
"$check" "$work/collapse-1s.png" "$work/collapse-0s.png" 0.01 460
echo "== a KIFS building, ray-marched in the 3D view"
kifs=$(dirname "$example")/kifs-h.corbel
sed '0,/"visible": true/s//"visible": false/' "$kifs" > "$work/kifs-hidden.corbel"
grep -q '"visible": false' "$work/kifs-hidden.corbel" || { echo "could not hide the KIFS building"; exit 1; }
run --recover no --select "H building" --screenshot "$work/kifs.png" --quit-after-frames 6 "$kifs"
run --recover no --select "H building" --screenshot "$work/kifs-hidden.png" --quit-after-frames 6 "$work/kifs-hidden.corbel"
"$check" "$work/kifs.png" "$work/kifs-hidden.png" 0.05
echo "== growth: Step twice"
alpha=$(dirname "$example")/housing-alpha.corbel
sed 's/"steps": -1/"steps": 10/' "$alpha" > "$work/alpha10.corbel"
rm -rf "$work/state"
run --recover no --select "Alpha" --actions growth.step,growth.step --autosave-seconds 0 \
  --screenshot "$work/growth.png" --quit-after-frames 8 "$work/alpha10.corbel"
test -f "$(recovery)" || { echo "Step changed nothing (no recovery file)"; exit 1; }
grep -q '"steps": 12' "$(recovery)" || { echo "two steps should make 12"; exit 1; }
summary=$("$cli" check "$(recovery)" 2>/dev/null | tail -1)
[[ $summary == '{"objects":1,"failed":0}' ]] || { echo "the grown site should be closed shells: $summary"; exit 1; }
echo "== form completion: seeds from the model, generate, fit, extrude, undo, redo"
completing=(completion.seeds,completion.generate,completion.fit,completion.extrude)
rm -rf "$work/state"
run --recover no --select "Alpha" --actions "${completing[0]}" --autosave-seconds 0 \
  --screenshot "$work/completion.png" --quit-after-frames 12 "$alpha"
test -f "$(recovery)" || { echo "Extrude to units changed nothing (no recovery file)"; exit 1; }
cp "$(recovery)" "$work/completed.corbel"
summary=$("$cli" check "$work/completed.corbel" 2>/dev/null | tail -1)
echo "completed: $summary"
units=$(sed -E 's/.*"objects":([0-9]+).*/\1/' <<<"$summary")
[[ $units -ge 2 && $summary == *'"failed":0}' ]] || { echo "the extruded units should be closed shells: $summary"; exit 1; }
grep -q '"unit": {' "$work/completed.corbel" || { echo "no unit objects were saved"; exit 1; }
run --recover no --select "Alpha" --screenshot "$work/site.png" --quit-after-frames 6 "$alpha"
"$check" "$work/completion.png" "$work/site.png" 0.01
rm -rf "$work/state"
run --recover no --select "Alpha" --actions "${completing[0]},edit.undo" --autosave-seconds 0 --quit-after-frames 12 "$alpha"
test -f "$(recovery)" && { echo "undo should leave the example untouched (a recovery file was written)"; exit 1; }
run --recover no --select "Alpha" --actions "${completing[0]},edit.undo,edit.redo_y" --autosave-seconds 0 \
  --quit-after-frames 14 "$alpha"
cmp -s "$(recovery)" "$work/completed.corbel" || { echo "redo should bring back the same units"; exit 1; }
echo "== growth view maps: GL (the default) against exact, a setting that changes nothing in the document"
rm -rf "$work/state"
run --recover no --select "Alpha" --actions growth.statistics,growth.view_maps --autosave-seconds 0 \
  --screenshot "$work/maps-gl.png" --quit-after-frames 30 "$alpha"
run --recover no --select "Alpha" --actions growth.gl_view_maps,growth.statistics,growth.view_maps --autosave-seconds 0 \
  --screenshot "$work/maps-exact.png" --quit-after-frames 30 "$alpha"
run --recover no --select "Alpha" --actions growth.gl_pixel_next,growth.statistics,growth.view_maps --autosave-seconds 0 \
  --screenshot "$work/maps-gl-coarse.png" --quit-after-frames 30 "$alpha"
test -f "$(recovery)" && { echo "switching the view maps should leave the document untouched"; exit 1; }
"$check" "$work/maps-gl.png" "$work/maps-exact.png" 0.01
"$check" "$work/maps-gl.png" "$work/maps-gl-coarse.png" 0.01
echo "== growth site editor: add a core, slice, statistics, view maps, undo"
rm -rf "$work/state"
run --recover no --select "Alpha" --actions growth.add_core,growth.slice_down,growth.slice_down,growth.statistics,growth.view_maps \
  --autosave-seconds 0 --screenshot "$work/growth-editor.png" --quit-after-frames 12 "$alpha"
test -f "$(recovery)" || { echo "Add Core changed nothing (no recovery file)"; exit 1; }
tr -d ' \n' < "$(recovery)" | grep -q '{"at":\[0.0,0.0\],"name":"core5","size":\[3.0,3.0\]}' ||
  { echo "the added core should be saved at (0, 0), 3 x 3 m"; exit 1; }
summary=$("$cli" check "$(recovery)" 2>/dev/null | tail -1)
[[ $summary == '{"objects":1,"failed":0}' ]] || { echo "the site with a new core should build as closed shells: $summary"; exit 1; }
"$check" "$work/growth-editor.png" "$work/site.png" 0.01
rm -rf "$work/state"
run --recover no --select "Alpha" --actions growth.add_core,edit.undo --autosave-seconds 0 --quit-after-frames 8 "$alpha"
test -f "$(recovery)" && { echo "undoing Add Core should leave the example untouched"; exit 1; }
echo "== growth site frame: a storey more, a wider envelope, undo"
rm -rf "$work/state"
run --recover no --select "Alpha" --actions growth.site,growth.add_storey,growth.widen_site --autosave-seconds 0 \
  --screenshot "$work/growth-frame.png" --quit-after-frames 12 "$alpha"
test -f "$(recovery)" || { echo "the frame edits changed nothing (no recovery file)"; exit 1; }
frame=$(tr -d ' \n' < "$(recovery)")
grep -q '"envelope":{"origin":\[0.0,0.0\],"size":\[95.0,50.0\]}' <<<"$frame" ||
  { echo "the widened envelope should be saved as a 95 x 50 m box"; exit 1; }
grep -Eq '"storeys":6[,}]' <<<"$frame" || { echo "the site should be saved with 6 storeys"; exit 1; }
summary=$("$cli" check "$(recovery)" 2>/dev/null | tail -1)
[[ $summary == '{"objects":1,"failed":0}' ]] || { echo "the wider, taller site should build as closed shells: $summary"; exit 1; }
"$check" "$work/growth-frame.png" "$work/site.png" 0.01
rm -rf "$work/state"
run --recover no --select "Alpha" --actions growth.add_storey,growth.widen_site,edit.undo,edit.undo --autosave-seconds 0 \
  --quit-after-frames 10 "$alpha"
test -f "$(recovery)" && { echo "undoing the frame edits should leave the example untouched"; exit 1; }
echo "== shadows from a lowered sun (a view setting: nothing to recover)"
rm -rf "$work/state"
run --recover no --select "Alpha" --actions view.shadows,view.sun_lower,view.sun_lower --autosave-seconds 0 \
  --screenshot "$work/growth-shadows.png" --quit-after-frames 8 "$alpha"
test -f "$(recovery)" && { echo "shadows should not change the document"; exit 1; }
"$check" "$work/growth-shadows.png" "$work/site.png" 0.05
echo "== a town: pick a building, override its type, undo"
town=$(dirname "$example")/town-oldtown.corbel
rm -rf "$work/state"
run --recover no --select "Town" --actions town.next,town.next_type --autosave-seconds 0 \
  --screenshot "$work/town-override.png" --quit-after-frames 10 "$town"
test -f "$(recovery)" || { echo "the override changed nothing (no recovery file)"; exit 1; }
grep -q '"overrides": {' "$(recovery)" || { echo "no override was saved"; exit 1; }
summary=$("$cli" check "$(recovery)" 2>/dev/null | tail -1)
echo "overridden: $summary"
[[ $summary == *'"failed":0}' ]] || { echo "the overridden town should build: $summary"; exit 1; }
run --recover no --select "Town" --actions town.next --autosave-seconds 0 --screenshot "$work/town.png" \
  --quit-after-frames 10 "$town"
# Only the 3D view counts (the panel lists the override too): the one restyled building differs.
"$check" "$work/town-override.png" "$work/town.png" 0.0005 460
rm -rf "$work/state"
run --recover no --select "Town" --actions town.next,town.next_type,edit.undo --autosave-seconds 0 \
  --quit-after-frames 12 "$town"
test -f "$(recovery)" && { echo "undo should leave the town example untouched (a recovery file was written)"; exit 1; }
echo "== a town: pick a building's edge in the plan view and override its profile"
rm -rf "$work/state"
run --recover no --select "Town" --actions town.next,town.next_edge,town.next_edge_profile --autosave-seconds 0 \
  --screenshot "$work/town-edge.png" --quit-after-frames 10 "$town"
test -f "$(recovery)" || { echo "the edge override changed nothing (no recovery file)"; exit 1; }
grep -q '"edges": {' "$(recovery)" || { echo "no edge override was saved"; exit 1; }
grep -q '"0:0": "' "$(recovery)" || { echo "the edge override should name edge 0:0"; exit 1; }
summary=$("$cli" check "$(recovery)" 2>/dev/null | tail -1)
echo "edge overridden: $summary"
[[ $summary == *'"failed":0}' ]] || { echo "the town with an edge override should build: $summary"; exit 1; }
echo "== a town: add a street beside it and bend it; its plots are built as houses"
rm -rf "$work/state"
run --recover no --select "Town" --actions town.next,town.add_street,town.bend_street --autosave-seconds 0 \
  --screenshot "$work/town-street.png" --quit-after-frames 12 "$town"
test -f "$(recovery)" || { echo "adding a street changed nothing (no recovery file)"; exit 1; }
grep -q '"streets": \[' "$(recovery)" || { echo "no street was saved"; exit 1; }
summary=$("$cli" check "$(recovery)" 2>/dev/null | tail -1)
echo "with a street: $summary"
[[ $summary == *'"failed":0}' ]] || { echo "the town with a street should build: $summary"; exit 1; }
# The street's houses stand south of the town, in the 3D view.
"$check" "$work/town-street.png" "$work/town.png" 0.01 460
rm -rf "$work/state"
run --recover no --select "Town" --actions town.add_street,town.bend_street,edit.undo,edit.undo --autosave-seconds 0 \
  --quit-after-frames 12 "$town"
test -f "$(recovery)" && { echo "undoing the street should leave the town untouched"; exit 1; }
echo "editor test passed"
