// The editor's commands: every action registered once (app.h, actions.h). The menus,
// shortcuts and help built from this registry are in app_menus.cpp.
#include "editor/app.h"

#include "city/ogr_source.h"

#include "editor/gestures.h"
#include "editor/menu_order.h"
#include "editor/new_objects.h"
#include "editor/shape_gallery.h"
#include "editor/stone_edits.h"
#include "extrude/edit.h"
#include "kifs/kernel.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>

namespace corbel::editor {

void App::runAction(const Action& a) { actions_.run(a); }

// ---------------------------------------------------------------- actions

void App::registerActions() {
  registerStudioActions();  // app_studio.cpp
  registerPushPullActions();  // app_push_pull.cpp
  registerTapeActions();      // app_tape.cpp
  auto doc = [this] { return history_.current(); };
  auto add = [this](Action a) { actions_.add(std::move(a)); };
  add({"file.new", "File", "New", "Start an empty project.", {GLFW_KEY_N, true}, false, [this] { newDocument(); }});
  add({"file.open", "File", "Open…", "Open a project file (.corbel).", {GLFW_KEY_O, true}, false, [this] {
         guardUnsaved([this] {
           fileDialog_.open(FileDialog::Mode::Open, "Open project", {".corbel"}, path_, [this](const std::string& p) {
             // The unsaved-changes question was already answered.
             history_.markSaved();
             openFile(p);
           });
         });
       }});
  add({"file.save",
       "File",
       "Save",
       "Save the project (atomic: the old file stays intact until the new one is complete).",
       {GLFW_KEY_S, true},
       false,
       [this] { save(); }});
  add({"file.save_as",
       "File",
       "Save As…",
       "Save the project under a new name.",
       {GLFW_KEY_S, true, true},
       false,
       [this] { saveAs(); }});
  add({"file.export",
       "File",
       "Export…",
       "Export the visible objects to glTF (.glb), OBJ, PLY or OFF.",
       {GLFW_KEY_E, true},
       false,
       [this] { exportScene(); },
       {},
       {},
       true});
  add({"file.quit",
       "File",
       "Quit",
       "Close corbel (asks before discarding changes).",
       {GLFW_KEY_Q, true},
       false,
       [this] { guardUnsaved([this] { quitRequested_ = true; }); },
       {},
       {},
       true});

  add({"edit.undo",
       "Edit",
       "Undo",
       "Undo the last change to the document.",
       {GLFW_KEY_Z, true},
       false,
       [this] {
         if (history_.undo()) log("Undo");
       },
       [this] { return history_.canUndo(); }});
  add({"edit.redo",
       "Edit",
       "Redo",
       "Redo the change undone last.",
       {GLFW_KEY_Z, true, true},
       false,
       [this] {
         if (history_.redo()) log("Redo");
       },
       [this] { return history_.canRedo(); }});
  add({"edit.redo_y",
       "",
       "Redo",
       "Redo the change undone last (Ctrl+Y, as on Windows).",
       {GLFW_KEY_Y, true},
       false,
       [this] {
         if (history_.redo()) log("Redo");
       },
       [this] { return history_.canRedo(); }});

  // Object > Add: every kind of object, each added beside the scene (masonry and KIFS at the
  // origin, which their specs fix), selected, brought into view and one undo step.
  auto added = [this](Document d, ObjectId id, const std::string& label) {
    commit(std::move(d), label);
    selection_.select(id);
    reveal(id);
    log(label);
  };
  add({"object.add_box",
       "Object/Add",
       "Box",
       "Add a mass-model box next to the existing objects.",
       {GLFW_KEY_B, true},
       true,
       [this, doc, added] {
         Document d = doc();
         BoxSpec b;
         BBox box = scene_.bounds();
         if (!box.empty()) b.origin = Vec3(box.hi[0] + 4.0 + b.size[0] / 2, box.center()[1], 0.0);
         const ObjectId id = d.add("Box", b);
         added(std::move(d), id, "Add box");
       }});
  add({"object.add_extrusion",
       "Object/Add/Extrusion",
       "Rectangle (Hip Roof)",
       "Add a procedural extrusion (a 12 × 8 m plan on the hip profile) next to the existing objects; edit it in the "
       "plan and profile panes.",
       {GLFW_KEY_X, true, true},
       true,
       [this, doc, added] {
         Document d = doc();
         const ObjectId id = d.add("Extrusion", galleryExtrusion(GalleryShape::Rectangle, besideScene(scene_.bounds(), 8)));
         added(std::move(d), id, "Add extrusion");
       }});
  for (GalleryShape shape : kGalleryShapes) {
    if (shape == GalleryShape::Rectangle) continue;  // object.add_extrusion
    const GalleryInfo info = galleryInfo(shape);
    add({std::string("object.add_extrusion_") + info.id,
         "Object/Add/Extrusion",
         std::string(info.label) + " (Hip Roof)",
         std::string(info.help) + " A procedural extrusion on the hip profile, next to the existing objects.",
         {},
         true,
         [this, doc, added, shape, info] {
           Document d = doc();
           const auto loops = galleryLoops(shape);
           BBox plan;
           for (const Vec2& p : loops[0]) plan.add(Vec3(p[0], p[1], 0));
           const ObjectId id =
               d.add(info.label + std::string(" plan"), galleryExtrusion(shape, besideScene(scene_.bounds(), plan.size()[1])));
           added(std::move(d), id, std::string("Add ") + info.label + " extrusion");
         }});
  }
  add({"object.add_kifs",
       "Object/Add",
       "KIFS Building",
       "Add a KIFS fractal building (McGraw; the box preset) next to the existing objects; edit it in the KIFS "
       "panel.",
       {},
       true,
       [this, doc, added] {
         Document d = doc();
         const ObjectId id = d.add("KIFS building", kifs::specOf(kifs::preset("box"), "box"));
         // Beside the scene, as the other kinds are added: the fractal's own bounds (it has no
         // faces) placed with their lower left corner where besideScene says.
         Document one;
         one.objects.push_back(*d.find(id));
         const BBox own = render::raymarchedKifs(one, nullptr).bounds;
         BBox scene = scene_.bounds();
         scene.add(render::raymarchedKifs(history_.current(), nullptr).bounds);
         if (!scene.empty() && !own.empty()) {
           const Vec2 at = besideScene(scene, own.size()[1]);
           d.find(id)->placement.translation = Vec3(at[0] - own.lo[0], at[1] - own.lo[1], 0);
         }
         added(std::move(d), id, "Add KIFS building");
       }});
  for (const MasonryTemplate& t : masonryTemplates()) {
    add({"object.add_masonry_" + t.model,
         t.example ? "Object/Add/Masonry/Examples" : "Object/Add/Masonry",
         t.label,
         "Add the statics " + std::string(t.example ? "example " : "template ") + t.model +
             " (Whiting et al. 2009) next to the existing objects; analyse it, load it and make it stand in the "
             "statics panel.",
         {},
         true,
         [this, doc, added, t] {
           Document d = doc();
           const MasonrySpec spec = masonryObject(t.model);
           const ObjectId id = d.add(t.label.substr(0, t.label.find(" (")), spec);
           // Beside the scene, as the other kinds are added, its ground slab included.
           const BBox own = masonryBounds(spec), scene = scene_.bounds();
           if (!scene.empty() && !own.empty()) {
             const Vec2 at = besideScene(scene, own.size()[1]);
             d.find(id)->placement.translation = Vec3(at[0] - own.lo[0], at[1] - own.lo[1], 0);
           }
           added(std::move(d), id, "Add masonry " + t.model);
         }});
  }
  add({"object.add_growth",
       "Object/Add",
       "Growth Site",
       "Add a 30 × 20 m growth site (Ng) of 3 storeys round one core, with 8 seeds at its landings, next to the "
       "existing objects; edit and grow it in the growth panel.",
       {},
       true,
       [this, doc, added] {
         Document d = doc();
         const ObjectId id = d.add("Growth site", starterGrowthSite(besideScene(scene_.bounds(), 20)));
         added(std::move(d), id, "Add growth site");
       }});
  add({"object.add_town",
       "Object/Add",
       "Town...",
       "Add a town (Kelly & Wonka Sec. 3.7): choose a footprint file in any vector format GDAL reads (GeoJSON, "
       "Shapefile, GeoPackage, FlatGeobuf, ...); it is styled with "
       "assets/styles/mixed.json until another style is picked in the Town panel.",
       {},
       false,
       [this, doc, added] {
         fileDialog_.open(FileDialog::Mode::Open, "Open footprints", city::vectorFileExtensions(), path_,
                          [doc, added](const std::string& path) {
                            Document d = doc();
                            TownSpec t;
                            t.footprints = path;
                            t.style = std::string(CORBEL_ASSETS_DIR) + "/styles/mixed.json";
                            const ObjectId id = d.add("Town", t);
                            added(std::move(d), id, "Add town");
                          });
       }});
  add({"object.duplicate",
       "Object",
       "Duplicate",
       "Copy the selected objects beside themselves (moved along x by their width and 2 m).",
       {GLFW_KEY_D, true},
       true,
       [this] { duplicateSelected(); },
       [this] { return selected().has_value(); }});
  add({"object.delete",
       "Object",
       "Delete",
       "Delete the selected object (one undo step). Over a kernel's pane, Delete removes what is selected there instead.",
       {GLFW_KEY_DELETE},
       true,
       [this, doc] {
         Document d = doc();
         const std::string name = d.find(*selected())->name;
         d.remove(*selected());
         selection_.clear();
         commit(std::move(d), "Delete " + name);
         log("Deleted " + name + " (Edit > Undo brings it back)");
       },
       [this] { return selected().has_value(); }});

  add({"view.frame", "View", "Frame All", "Fit the visible objects in the view.", {GLFW_KEY_HOME}, false, [this] {
         frameAll();
       }});
  add({"view.screenshot", "View", "Save Screenshot",
       "Save the window as a PNG beside the project (NAME-shot-N.png), as this frame draws it.", {GLFW_KEY_F12},
       false, [this] { screenshotDue_ = true; }});
  // The angled view is perspective; the six sides are orthographic, as Blender's side views
  // are. Top-row digits do what the numpad's do (Blender's "emulate numpad"), Ctrl the opposite side.
  add({"view.perspective",
       "View",
       "Angled View",
       "Look from above at an angle, in perspective.",
       {GLFW_KEY_KP_5},
       false,
       [this] {
         render::applyPreset(view_.camera, render::CameraPreset::Perspective);
         view_.camera.orthographic = false;
         frameAll();
       },
       {},
       {},
       true});
  auto side = [this, add](const char* id, const char* label, const char* help, int key, int numpad, bool ctrl,
                          render::CameraPreset p) {
    auto look = [this, p] {
      render::applyPreset(view_.camera, p);
      view_.camera.orthographic = true;
      frameAll();
    };
    add({id, "View", label, help, {key, ctrl}, false, look});
    add({std::string(id) + "_numpad", "", label, std::string(help) + " (the numpad's key)", {numpad, ctrl}, false, look});
  };
  using P = render::CameraPreset;
  side("view.front", "Front", "Look along +Y, orthographic.", GLFW_KEY_1, GLFW_KEY_KP_1, false, P::Front);
  side("view.back", "Back", "Look along -Y, orthographic.", GLFW_KEY_1, GLFW_KEY_KP_1, true, P::Back);
  side("view.right", "Right", "Look along -X, orthographic.", GLFW_KEY_3, GLFW_KEY_KP_3, false, P::Right);
  side("view.left", "Left", "Look along +X, orthographic.", GLFW_KEY_3, GLFW_KEY_KP_3, true, P::Left);
  side("view.top", "Top", "Look straight down, orthographic.", GLFW_KEY_7, GLFW_KEY_KP_7, false, P::Top);
  side("view.bottom", "Bottom", "Look straight up, orthographic.", GLFW_KEY_7, GLFW_KEY_KP_7, true, P::Bottom);
  add({"view.orthographic",
       "View",
       "Orthographic",
       "Switch between orthographic and perspective projection (the model keeps its size at the view's centre).",
       {GLFW_KEY_5},
       false,
       [this] { view_.camera.orthographic = !view_.camera.orthographic; },
       {},
       [this] { return view_.camera.orthographic; }});
  // The layout (app_layout.cpp): Blender's keys for its side bars, a browser's for the scale.
  add({"view.left_panel",
       "View",
       "Left Panel",
       "Show or hide the object panel (its splitter does the same on a double-click).",
       {GLFW_KEY_T},
       false,
       [this] { togglePanel(true); },
       {},
       [this] { return userSettings_.panels.leftShown; },
       true});
  add({"view.right_panel",
       "View",
       "Right Panel",
       "Show or hide the selected object's panel (plan and profile panes, statics, KIFS, growth, town).",
       {GLFW_KEY_N},
       false,
       [this] { togglePanel(false); },
       {},
       [this] { return userSettings_.panels.rightShown; }});
  add({"view.ui_larger", "View", "UI Larger", "Scale the interface up by 10 %.", {GLFW_KEY_EQUAL, true}, false,
       [this] { setUiScale(uiScale() + 0.1f); }});
  add({"view.ui_smaller", "View", "UI Smaller", "Scale the interface down by 10 %.", {GLFW_KEY_MINUS, true}, false,
       [this] { setUiScale(uiScale() - 0.1f); }});
  add({"view.ui_monitor",
       "View",
       "UI Scale of the Monitor",
       "Scale the interface as the monitor asks (its content scale), forgetting a chosen scale.",
       {GLFW_KEY_0, true},
       false,
       [this] { setUiScale(std::nullopt); }});
  add({"command.search",
       "Edit",
       "Search Commands...",
       "Find any command by typing words of its name, menu or help, and run it (Blender's F3; Ctrl+Shift+P too).",
       {GLFW_KEY_F3},
       false,
       [this] { openCommandSearch(); },
       {},
       {},
       true});
  add({"command.search_palette", "", "Search Commands...", "The command search (as VS Code's command palette).",
       {GLFW_KEY_P, true, true}, false, [this] { openCommandSearch(); }});
  add({"view.wireframe",
       "View",
       "Wireframe",
       "Draw edges only.",
       {GLFW_KEY_W, false, false, true},
       false,
       [this] { settings_.wireframe = !settings_.wireframe; },
       {},
       [this] { return settings_.wireframe; },
       true});
  add({"view.edges",
       "View",
       "Edges",
       "Outline every face.",
       {},
       false,
       [this] { settings_.edges = !settings_.edges; },
       {},
       [this] { return settings_.edges; }});
  add({"view.grid",
       "View",
       "Ground Grid",
       "Show the ground grid at z = 0.",
       {},
       false,
       [this] { settings_.grid = !settings_.grid; },
       {},
       [this] { return settings_.grid; }});
  // Shadows from a movable sun (Ng, Fig. 8.5); the growth panel's Grow tab has the sun's sliders.
  add({"view.shadows",
       "View",
       "Shadows",
       "Cast shadows from the sun onto the model and the ground.",
       {},
       false,
       [this] { settings_.shadows = !settings_.shadows; },
       {},
       [this] { return settings_.shadows; },
       true});
  add({"view.sun_later", "View", "Sun Later", "Move the sun 15° on (its azimuth, towards +Y).", {}, false, [this] {
         sunAzimuth_ = std::remainder(sunAzimuth_ + 15.0, 360.0);
       }});
  add({"view.sun_earlier", "View", "Sun Earlier", "Move the sun 15° back.", {}, false, [this] {
         sunAzimuth_ = std::remainder(sunAzimuth_ - 15.0, 360.0);
       }});
  add({"view.sun_lower",
       "View",
       "Sun Lower",
       "Lower the sun by 10° (at least 5° above the ground).",
       {},
       false,
       [this] { sunElevation_ = std::max(5.0, sunElevation_ - 10.0); }});

  add({"tools.validate",
       "Tools",
       "Validate All Objects",
       "Check every object's shell (closed, 2-manifold, Euler characteristic), in the background.",
       {},
       false,
       [this] {
         auto snapshot = std::make_shared<Scene>(scene_);
         auto lines = std::make_shared<std::vector<std::string>>();
         startJob(
             "Validating objects",
             [snapshot, lines](Progress& progress) {
               std::size_t i = 0;
               const std::size_t n = snapshot->objects().size();
               for (const auto& [id, info] : snapshot->objects()) {
                 if (progress.cancelled()) throw Cancelled();
                 const ValidityReport r = snapshot->validate(id);
                 std::string line = info.name + ": " + (r.closedManifold() ? "closed 2-manifold" : "PROBLEMS") + ", " +
                                    std::to_string(r.faces) + " faces, Euler " + std::to_string(r.euler);
                 for (const auto& p : r.problems()) line += "; " + p;
                 lines->push_back(line);
                 progress.report(double(++i) / n, info.name);
               }
             },
             [this, lines] {
               for (const auto& l : *lines) log(l, l.find("PROBLEMS") != std::string::npos);
             });
       }});
  add({"statics.make_stand",
       "Statics",
       "Make It Stand",
       "Search the selected masonry object's free parameters, within their bounds, for a structure that stands "
       "(in the background; one undo step).",
       {GLFW_KEY_M, true, true},
       true,
       [this] { statics_.makeItStand(staticsHost()); },
       [this] { return selectedMasonry() && !statics_.searching(); }});
  add({"statics.cancel",
       "Statics",
       "Cancel Search",
       "Stop the running search; nothing changes.",
       {},
       false,
       [this] { statics_.cancelSearch(); },
       [this] { return statics_.searching(); }});
  // An extrusion built in stone (the left panel's "Build in stone", editor/stone_panel.h).
  auto selectedExtrusion = [this]() -> const ExtrusionSpec* {
    const DocObject* o = selected() ? history_.current().find(*selected()) : nullptr;
    return o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr;
  };
  add({"statics.build_in_stone",
       "Statics",
       "Build in Stone",
       "Course the selected extrusion's walls into stone blocks carrying its roof, or back to a plain shell (one "
       "undo step; its settings are in the left panel).",
       {},
       false,
       [this, selectedExtrusion] {
         const ExtrusionSpec* e = selectedExtrusion();
         if (!e) return;
         const bool on = !e->masonry;
         commit(setStone(history_.current(), *selected(), on), on ? "Build the walls in stone" : "Walls not in stone");
       },
       [selectedExtrusion] { return selectedExtrusion() != nullptr; }});
  add({"statics.make_walls_stand",
       "Statics",
       "Make the Stone Walls Stand",
       "Search the wall thickness of the selected extrusion built in stone until its walls carry the roof (in the "
       "background; one undo step).",
       {},
       true,
       [this] { stone_.makeItStand(staticsHost()); },
       [this, selectedExtrusion] {
         const ExtrusionSpec* e = selectedExtrusion();
         return e && e->masonry && stoneFor_ == selected() && !stone_.searching();
       }});
  // The collapse simulation (Sec. 5): never a Document change, so none is undoable.
  auto masonrySelected = [this] { return selectedMasonry() != nullptr; };
  add({"statics.analyse_together",
       "Statics",
       "Analyse All Masonry Together",
       "Analyse the selected masonry object with every other masonry object as one structure: each rests on the "
       "others where their faces meet (within the panel's contact tolerance).",
       {},
       false,
       [this] { statics_.analyseTogether(staticsHost()); },
       masonrySelected});
  add({"statics.make_stand_together",
       "Statics",
       "Make All Masonry Stand Together",
       "Search the free parameters of every masonry object at once until they stand together (one undo step).",
       {},
       true,
       [this] { statics_.makeThemStand(staticsHost()); },
       masonrySelected});
  add({"statics.place_load",
       "Statics",
       "Place Loads by Click",
       "While on, a click on a block of the selected masonry object places a load there: a weight where you "
       "click or wind on the face you click, as chosen in the statics panel (one undo step each).",
       {},
       false,
       [this] { statics_.setPlacingLoad(!statics_.placingLoad()); },
       masonrySelected,
       [this] { return statics_.placingLoad(); }});
  add({"statics.sim_play",
       "Statics",
       "Simulate: Play / Pause",
       "Play the selected masonry object's collapse simulation in real time (as fast as the frame budget "
       "allows); again to pause.",
       {},
       false,
       [this] { statics_.simulatePlay(staticsHost()); },
       masonrySelected,
       [this] { return statics_.simulationPlaying(); },
       true});
  add({"statics.sim_step",
       "Statics",
       "Simulate: Step",
       "Advance the simulation by one fixed step (1/240 s).",
       {},
       false,
       [this] { statics_.simulateStep(staticsHost()); },
       masonrySelected});
  add({"statics.simulate",
       "Statics",
       "Simulate: Run 1 s",
       "Advance the simulation by one simulated second at once (240 steps; the window waits for it).",
       {},
       false,
       [this] { statics_.simulateStep(staticsHost(), 240); },
       masonrySelected});
  add({"statics.sim_reset",
       "Statics",
       "Simulate: Reset",
       "Return the simulation to the design state, paused.",
       {},
       false,
       [this] { statics_.simulateReset(staticsHost()); },
       masonrySelected});
  add({"statics.sim_shake",
       "Statics",
       "Simulate: Shake",
       "Shake the ground as in the paper (4 m/s within 1/60 s on a 10 m model, scaled to this one).",
       {},
       false,
       [this] { statics_.simulateShake(staticsHost()); },
       masonrySelected});
  add({"statics.sim_remove",
       "Statics",
       "Simulate: Remove Block",
       "Take the block chosen in the Simulate section (at first the top one) out of the simulation.",
       {},
       false,
       [this] { statics_.simulateRemove(staticsHost()); },
       masonrySelected});
  add({"statics.landscape_grid",
       "Statics",
       "Energy Landscape over Two Parameters",
       "Sample y/W² over a grid of the selected masonry object's first two free parameters (Fig. 8) in the "
       "statics panel; again for the landscape over one parameter.",
       {},
       false,
       [this] { statics_.toggleLandscapeGrid(staticsHost()); },
       masonrySelected,
       [this] { return statics_.landscapeGridChosen(); }});
  add({"statics.analyse_scene",
       "Statics",
       "Analyse Every Block in the Scene",
       "Analyse every object of kind Block in the Scene together (each connected piece one block, density by "
       "material, the objects ticked in the statics panel carried as loads), and show it in the view.",
       {},
       false,
       [this] { statics_.analyseScene(staticsHost()); },
       masonrySelected});
  add({"statics.sim_close",
       "Statics",
       "Simulate: Close",
       "Stop simulating and show the design again.",
       {},
       false,
       [this] { statics_.closeSimulation(); },
       [this] { return statics_.simulating(); }});
  auto growthSelected = [this] { return selectedGrowth() != nullptr; };
  add({"growth.step",
       "Growth",
       "Step",
       "Grow the selected site one step more (one undo step).",
       {},
       true,
       [this] { growthPanel_.step(growthHost()); },
       growthSelected});
  add({"growth.run",
       "Growth",
       "Run / Pause",
       "Grow the selected site step by step as the view catches up, until every unit stops; again to pause.",
       {},
       true,
       [this] { growthPanel_.toggleRun(growthHost()); },
       growthSelected,
       [this] { return growthPanel_.running(); }});
  // The site editor, the slice, the statistics and the view maps of the selected growth site.
  add({"growth.add_core",
       "Growth",
       "Add Core",
       "Add a 3 x 3 m core at the first free place of the selected site (one undo step).",
       {},
       true,
       [this] { growthPanel_.add(growthHost(), SiteItem::Core); },
       growthSelected,
       {},
       true});
  add({"growth.add_circulation",
       "Growth",
       "Add Circulation",
       "Add a 3 x 3 m landing, one storey high, on the Site tab's plan storey (one undo step).",
       {},
       true,
       [this] { growthPanel_.add(growthHost(), SiteItem::Circulation); },
       growthSelected});
  add({"growth.add_seed",
       "Growth",
       "Add Seed",
       "Add a 3 x 3 m seed of 60 m² at the first free, supported place on the plan storey (one undo step).",
       {},
       true,
       [this] { growthPanel_.add(growthHost(), SiteItem::Seed); },
       growthSelected});
  add({"growth.delete",
       "Growth",
       "Delete Site Entry",
       "Delete the core, circulation or seed picked in the Site tab.",
       {},
       true,
       [this] { growthPanel_.removeSelected(growthHost()); },
       [this, growthSelected] { return growthSelected() && growthPanel_.hasSelection(); }});
  add({"growth.add_storey",
       "Growth",
       "Add a Storey",
       "Give the selected site one storey more, of the same height (one undo step).",
       {},
       true,
       [this] { growthPanel_.addStorey(growthHost()); },
       growthSelected});
  add({"growth.widen_site",
       "Growth",
       "Widen the Site by 5 m",
       "Make the selected site's box envelope 5 m longer in x (one undo step).",
       {},
       true,
       [this] { growthPanel_.widenSite(growthHost(), 5.0); },
       growthSelected});
  add({"growth.site",
       "Growth",
       "Show the Site",
       "Show the Site tab: cores, circulation and seeds.",
       {},
       false,
       [this] { growthPanel_.showTab(1); },
       growthSelected});
  add({"growth.slice_down",
       "Growth",
       "Slice a Storey Lower",
       "Hide one storey more of the selected site in the 3D view (Fig. 8.3; a view setting).",
       {},
       false,
       [this] { growthPanel_.sliceStorey(growthHost(), -1); },
       growthSelected,
       {},
       true});
  add({"growth.slice_up",
       "Growth",
       "Slice a Storey Higher",
       "Show one storey more; past the top, no slice.",
       {},
       false,
       [this] { growthPanel_.sliceStorey(growthHost(), 1); },
       growthSelected});
  add({"growth.statistics",
       "Growth",
       "Statistics",
       "Show Table 8.1 for the model as grown.",
       {},
       false,
       [this] { growthPanel_.showTab(2); },
       growthSelected});
  add({"growth.gl_view_maps",
       "Growth",
       "GL View Maps",
       "Grow and measure growth sites on view maps rendered with OpenGL (unchecked: the exact CPU maps).",
       {},
       false,
       [this] { glViewMaps_ = !glViewMaps_; },
       [this] { return glMaps_ != nullptr; },
       [this] { return glMaps_ && glViewMaps_; }});
  add({"growth.gl_pixel_next",
       "Growth",
       "GL View Map Pixels: Next Size",
       "The next pixel size of the GL view maps (0.1, 0.25, 0.5 m, then 0.1 again); the sites regrow on it.",
       {},
       false,
       [this] {
         const auto& sizes = kEditorViewMapPixels;
         const auto at = std::find(std::begin(sizes), std::end(sizes), glPixel_);
         glPixel_ = at == std::end(sizes) || at + 1 == std::end(sizes) ? sizes[0] : *(at + 1);
       },
       [this] { return glMaps_ && glViewMaps_; }});
  add({"growth.view_maps",
       "Growth",
       "View Maps",
       "Show the four view maps (Sec. 5.2) of the model as grown, unit ids in false colour.",
       {},
       false,
       [this] { growthPanel_.toggleViewMaps(); },
       growthSelected,
       [this] { return growthPanel_.viewMapsShown(); }});
  add({"growth.freeze",
       "Growth",
       "Freeze Units",
       "Turn the selected site's grown units into unit objects to edit by hand (one undo step); the site then "
       "grows new seeds around them and keeps roofing them.",
       {},
       true,
       [this] { growthPanel_.freeze(growthHost()); },
       [this, growthSelected] { return growthSelected() && !job_ && !growthPanel_.running(); }});
  // Form completion (Ch. 7, Fig. 8.6) in a region of the selected growth site.
  add({"completion.seeds",
       "Growth",
       "Completion: Seeds From the Model",
       "Grow the selected site's model (in the background) and take the entrances its units open onto the "
       "completion region as the seeds.",
       {},
       false,
       [this] { completion_.takeSeeds(completionHost()); },
       growthSelected});
  add({"completion.generate",
       "Growth",
       "Completion: Generate Forms",
       "Generate forms of the chosen complexity range from the seeds (in the background, with Cancel).",
       {},
       false,
       [this] { completion_.generate(completionHost()); },
       [this, growthSelected] { return growthSelected() && !job_; }});
  add({"completion.fit",
       "Growth",
       "Completion: Fit to Region",
       "Fit the picked form into the completion region and size it (Fig. 8.6).",
       {},
       false,
       [this] { completion_.fit(completionHost()); },
       [this, growthSelected] { return growthSelected() && completion_.canFit(); }});
  add({"completion.extrude",
       "Growth",
       "Completion: Extrude to Units",
       "Add the fitted form's units to the model as unit objects (one undo step).",
       {},
       true,
       [this] { completion_.extrude(completionHost()); },
       [this, growthSelected] { return growthSelected() && completion_.canExtrude(); }});
  // The Town panel (Kelly & Wonka Sec. 3.7): its building list and override, for scripts.
  const auto townSelected = [this] { return selectedTown() != nullptr; };
  add({"town.next",
       "Town",
       "Select Next Building",
       "Select the next building of the selected town.",
       {},
       false,
       [this] { townPanel_.selectNext(townHost()); },
       townSelected});
  add({"town.next_type",
       "Town",
       "Override: Next Type",
       "Give the selected building the style's next building type (an undoable override).",
       {},
       false,
       [this] { townPanel_.overrideNextType(townHost()); },
       townSelected});
  add({"town.next_edge",
       "Town",
       "Pick Next Edge",
       "Pick the selected building's next edge in the Town panel's plan view.",
       {},
       false,
       [this] { townPanel_.selectNextEdge(townHost()); },
       townSelected});
  add({"town.next_edge_profile",
       "Town",
       "Override: Next Edge Profile",
       "Give the picked edge of the selected building the style's next profile (an undoable override of that edge).",
       {},
       false,
       [this] { townPanel_.overrideNextEdgeProfile(townHost()); },
       townSelected});
  add({"town.add_street",
       "Town",
       "Add Street",
       "Add a street along the selected town's south side (Fig. 26).",
       {},
       false,
       [this] { townPanel_.addStreet(townHost()); },
       townSelected});
  add({"town.bend_street",
       "Town",
       "Bend Street",
       "Move the chosen street's middle point 10 m south.",
       {},
       false,
       [this] { townPanel_.bendStreet(townHost()); },
       townSelected});
  add({"help.shortcuts",
       "Help",
       "Keyboard Shortcuts",
       "List every command and its shortcut.",
       {GLFW_KEY_F1},
       false,
       [this] { showHelp_ = true; }});
}

}  // namespace corbel::editor
