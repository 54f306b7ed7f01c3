#include "cli/commands.h"

#include <cstdio>

namespace corbel::cli {
namespace {

const char* const kProgram = "corbel-cli";
const char* const kExportTypes = "FILE.{obj,ply,off,glb}";

std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// A subcommand of `parent` with --help (inherited) and --version; `footer` is the long
// explanation printed after its options.
CLI::App* command(CLI::App& parent, const std::string& name, const std::string& description,
                  const std::string& footer = "") {
  CLI::App* c = parent.add_subcommand(name, description);
  c->footer(footer);
  addVersionFlag(*c, kProgram);
  return c;
}

CLI::Option* positional(CLI::App& c, const std::string& name, std::string& value, const std::string& description) {
  return c.add_option(name, value, description)->type_name("");
}

CLI::Option* text(CLI::App& c, const std::string& name, std::string& value, const std::string& type,
                  const std::string& description) {
  return c.add_option(name, value, description)->type_name(type);
}

// A number in [lo, hi]; the field's value on entry is the default shown.
template <class Number>
CLI::Option* number(CLI::App& c, const std::string& name, Number& value, double lo, double hi,
                    const std::string& type, const std::string& description) {
  return c.add_option(name, value, description)->check(numberIn(lo, hi))->type_name(type)->default_str(shortNumber(double(value)));
}

// A number in [lo, hi] without a default (the command works one out when it is not given).
CLI::Option* number(CLI::App& c, const std::string& name, std::optional<double>& value, double lo, double hi,
                    const std::string& type, const std::string& description) {
  return c.add_option(name, value, description)->check(numberIn(lo, hi))->type_name(type);
}

template <class Whole>
CLI::Option* whole(CLI::App& c, const std::string& name, Whole& value, long long lo, long long hi,
                   const std::string& type, const std::string& description) {
  return c.add_option(name, value, description)->check(wholeIn(lo, hi))->type_name(type)->default_str(std::to_string(value));
}

CLI::Option* whole(CLI::App& c, const std::string& name, std::optional<int>& value, long long lo, long long hi,
                   const std::string& type, const std::string& description) {
  return c.add_option(name, value, description)->check(wholeIn(lo, hi))->type_name(type);
}
CLI::Option* whole(CLI::App& c, const std::string& name, std::optional<long long>& value, long long lo, long long hi,
                   const std::string& type, const std::string& description) {
  return c.add_option(name, value, description)->check(wholeIn(lo, hi))->type_name(type);
}

// One of `words`; the field's value on entry is the default shown.
CLI::Option* choice(CLI::App& c, const std::string& name, std::string& value, const std::vector<std::string>& words,
                    const std::string& description, const std::vector<std::string>& hidden = {}) {
  return c.add_option(name, value, description)->check(oneOf(words, hidden))->type_name(choices(words))->default_str(value);
}

void declareRender(CLI::App& app, Requests& requests) {
  CLI::App* c = command(app, "render", "Render a project to a PNG, headless (OSMesa).");
  RenderRequest& r = requests.add<RenderRequest>(c);
  positional(*c, "PROJECT", r.project, "The project file (.corbel).")->required();
  text(*c, "--out", r.out, "PNG", "The image to write.")->required();
  addSize(*c, "--size", r.size, 1, 8192, "The image's width and height in pixels.");
  text(*c, "--camera", r.camera, "AZ,EL[,DIST]",
       "Azimuth and elevation in degrees, distance in meters (default: the visible objects framed).");
  text(*c, "--object", r.object, "NAME", "Draw only this object.");
  c->add_flag("--no-grid", r.noGrid, "Leave out the ground grid.");
  c->add_flag("--no-edges", r.noEdges, "Leave out the edge lines.");
  c->add_flag("--wireframe", r.wireframe, "Draw the edges only.");
  choice(*c, "--textures", r.textures, {"on", "off"},
         "on: the built-in textures (docs/city.md) instead of plain colours.");
}

void declareExport(CLI::App& app, Requests& requests) {
  CLI::App* c = command(app, "export", "Export a project's visible objects to a mesh file.");
  ExportRequest& r = requests.add<ExportRequest>(c);
  positional(*c, "PROJECT", r.project, "The project file (.corbel).")->required();
  text(*c, "--out", r.out, kExportTypes, "The file to write; its extension names the format.")->required();
  text(*c, "--object", r.object, "NAME", "Export only this object.");
  c->add_option("--up", r.up,
                "The axis that points up in an OBJ, PLY or OFF file (default: y for OBJ, z for PLY and OFF; "
                "glb is always y).")
      ->check(oneOf({"y", "z"}))
      ->type_name("y|z");
  whole(*c, "--kifs-resolution", r.kifsResolution, 1, 1024, "N",
        "Cells along the longest side of a ray-marched KIFS building, meshed for the file.");
  c->add_flag("--compress", r.compress, "glb: compress the geometry with meshoptimizer (EXT_meshopt_compression).");
}

void declareCheck(CLI::App& app, Requests& requests) {
  CLI::App* c = command(app, "check", "Validate a project file and every object's shell (JSON lines).",
                        "One JSON line per object (faces, Euler characteristic, watertight, manifold, area, volume, "
                        "problems), then a summary line. Exits 1 when a shell is not a closed manifold.");
  CheckRequest& r = requests.add<CheckRequest>(c);
  positional(*c, "PROJECT", r.project, "The project file (.corbel).")->required();
}

void declareEdit(CLI::App& app, Requests& requests) {
  CLI::App* c = command(
      app, "edit", "Apply an edit script to a project, as the editor applies it, and save the result.",
      "The script is JSON lines, one edit each (the operations of docs/user-guide.md: corners, loops,\n"
      "profiles, steps, features, backgrounds). Each line is applied in turn as the editor commits it;\n"
      "a bad line is refused with its number and nothing is written. What an edit removed (a feature\n"
      "whose wall went with a corner) is named on stderr. Prints one JSON line: edits, objects, out.\n"
      "With an empty script, re-saves the project by this version's writer.");
  EditRequest& r = requests.add<EditRequest>(c);
  positional(*c, "PROJECT", r.project, "The project file (.corbel).")->required();
  text(*c, "--script", r.script, "EDITS.jsonl", "The edits, one JSON object a line.")->required();
  text(*c, "--out", r.out, "OUT.corbel", "Where to save the edited project (atomically; may be PROJECT).")->required();
}

// --crs, --layer and --where: how footprints are read (city/import.h).
void footprintOptions(CLI::App& c, std::string& crs, std::string& layer, std::string& where) {
  text(c, "--crs", crs, "CRS",
       "The footprints' CRS when the file names none or a wrong one: EPSG:32632, a WKT or a PROJ string; "
       "`local` for metres about a local origin.");
  text(c, "--layer", layer, "NAME", "The layer of a source with several (GeoPackage, a folder of Shapefiles).");
  text(c, "--where", where, "SQL", "Only the features this OGR SQL attribute filter keeps, e.g. \"height > 3\".");
}

void declareExtrude(CLI::App& app, Requests& requests) {
  CLI::App* c = command(
      app, "extrude", "Procedural extrusion of a project's extrusion objects or of footprints.",
      "Footprints are read as by city (any GDAL/OGR vector source, reprojected to a local metric frame; see\n"
      "docs/city.md); a feature may name a profile of the --library project in its property \"profile\".\n"
      "A building whose shell fails is rebuilt with 10-10000x tolerances and kept only where three rebuilds agree\n"
      "(a warning says so); --no-retry does not. Without --stats, failures and the summary go to stderr.\n"
      "See docs/extrude.md.");
  ExtrudeRequest& r = requests.add<ExtrudeRequest>(c);
  positional(*c, "INPUT", r.input, "A project (its extrusion objects) or footprints (GeoJSON, Shapefile, GeoPackage, ...).")
      ->required();
  number(*c, "--pitch", r.pitch, 0.5, 89.5, "DEG",
         "One roof slope for every edge (default 45 for GeoJSON; a project's objects keep their profiles "
         "unless --pitch or --wall-height is given).");
  number(*c, "--wall-height", r.wallHeight, 0, 1000, "M", "The walls under that roof (default 0).");
  text(*c, "--out", r.out, kExportTypes, "Write the shells that built to one file.");
  c->add_flag("--stats", r.stats, "Print one JSON line per building (measures, mesh anchors), then the summary.");
  whole(*c, "--jobs", r.jobs, 0, 1024, "N", "Worker threads (0: one per core).");
  text(*c, "--library", r.library, "PROJECT", "A project whose extrusion profiles the GeoJSON features may name.");
  c->add_flag("--merge-coplanar", r.mergeCoplanar, "Write neighbouring faces in one plane as one face.");
  c->add_flag("--no-retry", r.noRetry, "Keep a failed shell failed (no rebuilds with larger tolerances).");
  c->add_flag("--winding-rule", r.windingRule,
              "Rebuild a plan that overlaps itself after an event by the winding rule (Sec. 4.4) instead of warning.");
  footprintOptions(*c, r.crs, r.layer, r.where);
}

// --friction, --conservative-friction, --kern and --friction-sides, for every statics form.
void declareAnalysis(CLI::App& c, StaticsAnalysis& a) {
  number(c, "--friction", a.friction, 0, 100, "A", "The friction coefficient at the joints (default: the model's; 0.7).");
  number(c, "--kern", a.kern, 0, 0.99, "S",
         "Shrink each contact face by S towards its centre: forces must pass within it (0.667: the middle third; "
         "default: the model's; 0).");
  c.add_flag("--conservative-friction", a.conservativeFriction,
             "Use friction A/sqrt(2), so the friction pyramid lies inside the friction cone (Sec. 3.1).");
  c.add_option("--friction-sides", a.frictionSides, "The sides of the friction pyramid.")
      ->check(oneOf({"4", "8"}))
      ->type_name("4|8")
      ->default_str("4");
}

// The parameters, the search and the pictures of statics example NAME and statics PROJECT.
void declareModelOptions(CLI::App& c, StaticsModelOptions& m) {
  addRepeated(c, "--set", m.sets, "Set a parameter of the model before the analysis.")->type_name("NAME=V");
  CLI::Option* optimize =
      c.add_flag("--optimize", m.optimize, "Search the free parameters until the model stands (Sec. 4).");
  addRepeated(c, "--free", m.frees, "A parameter the search may move, within [LO, HI] (default: the model's own).")
      ->type_name("NAME=LO:HI")
      ->needs(optimize);
  choice(c, "--algorithm", m.algorithm, {"mma", "slsqp", "lbfgs"}, "The search's NLopt algorithm.");
  whole(c, "--max-evaluations", m.maxEvaluations, 1, 1000000, "N", "The most analyses the search runs.");
  number(c, "--max-seconds", m.maxSeconds, 0, 1e6, "S", "The search's time limit (0: none).");
  c.add_flag("--json", m.json, "Print one JSON line instead of text.");
  CLI::Option* render = text(c, "--render", m.render, "PNG",
                             "Draw the model after the analysis or search: blocks by their share of tension "
                             "(compression red, tension blue), ground reactions green.");
  addSize(c, "--size", m.size, 16, 8192, "The --render image's size.")->needs(render);
  CLI::Option* landscape =
      c.add_option("--landscape", m.landscape,
                   "Sample y/W² on a grid of two parameters into a PNG (Fig. 8): red stands. NAME=LO:HI sets an "
                   "axis's range (default: its free bounds, else the model's suggested ones).")
          ->expected(3)
          ->allow_extra_args(false)
          ->type_name("NAME1 NAME2 PNG");
  whole(c, "--samples", m.samples, 2, 1024, "N", "Samples along each axis of the landscape.")->needs(landscape);
}

void declareStatics(CLI::App& app, Requests& requests) {
  CLI::App* c = command(
      app, "statics",
      "Masonry statics (docs/statics.md): does a model stand in compression and friction alone?",
      "statics PROJECT.corbel analyses each masonry object of the project with its own parameters and bounds,\n"
      "as 'statics example' does an example, and each extrusion with a masonry section as its walls coursed in\n"
      "stone carrying its roof (free by default: thickness). With --scene it analyses the project as built: every connected\n"
      "piece of its block objects (or of the objects --structural names, any kind) a rigid block, convex or\n"
      "not, weighing by its material; pieces tagged \"ground\" fixed, else a ground plane under the lowest\n"
      "point; --nonstructural objects carried as loads.");
  c->require_subcommand(0, 1);
  StaticsProjectRequest& r = requests.add<StaticsProjectRequest>(c);
  positional(*c, "PROJECT", r.project, "A project (.corbel): its masonry objects, or with --scene its geometry.");
  text(*c, "--object", r.object, "NAME", "Only this masonry object or stone extrusion (--render and --landscape draw one).");
  declareModelOptions(*c, r.model);
  declareAnalysis(*c, r.analysis);
  CLI::Option* save = c->add_flag(
      "--save", r.save,
      "Write the values the run ends with (--set, and --optimize's when the object then stands) back into the "
      "project, atomically.");
  CLI::Option* scene = c->add_flag("--scene", r.scene, "Analyse the built geometry instead of the masonry objects.");
  scene->excludes(save);
  CLI::Option* together = c->add_flag(
      "--together", r.together,
      "Analyse every masonry object as one structure: blocks of different objects carry one another where their "
      "faces meet; --optimize searches the free parameters of all of them (named OBJECT/PARAMETER).");
  together->excludes(scene);
  number(*c, "--contact-tolerance", r.contactTolerance, 0, 0.1, "M",
         "With --together: faces of different objects this close (and opposite) touch (default 0.001 m).")
      ->needs(together);
  addRepeated(*c, "--structural", r.structural, "With --scene: an object whose pieces are blocks, any kind.")
      ->type_name("NAME")
      ->needs(scene);
  addRepeated(*c, "--nonstructural", r.nonstructural, "With --scene: an object carried as a load.")
      ->type_name("NAME")
      ->needs(scene);
  addRepeated(*c, "--density", r.densities, "With --scene: the density of a material.")
      ->type_name("MATERIAL=KG_PER_M3")
      ->needs(scene);

  CLI::App* arch = command(
      *c, "arch", "A semicircular arch of N voussoirs on tilted ground.",
      "The arch's centreline has radius 1, its joints are radial, the ground is rigid and tilted by --tilt.\n"
      "Prints the measure of infeasibility y/W² (0 when it stands); --min-thickness the least t/R that\n"
      "stands (--thickness ignored); --critical-tilt the ground tilt in degrees at which it stops standing.");
  StaticsArchRequest& a = requests.add<StaticsArchRequest>(arch);
  whole(*arch, "--blocks", a.blocks, 1, 100000, "N", "The number of voussoirs.")->required()->default_str("");
  number(*arch, "--thickness", a.thickness, 1e-6, 1.999, "T", "The thickness t/R (required unless --min-thickness).");
  number(*arch, "--tilt", a.tilt, -89, 89, "DEG", "The ground's tilt.");
  declareAnalysis(*arch, a.analysis);
  CLI::Option* least = arch->add_flag("--min-thickness", a.minThickness, "Print the least thickness that stands.");
  arch->add_flag("--critical-tilt", a.criticalTilt, "Print the tilt at which the arch stops standing.")
      ->excludes(least);

  CLI::App* example = command(
      *c, "example", "One of the paper's examples, analysed or made to stand.",
      "NAME: tower (Fig. 11), arch-on-columns (Fig. 8), barrel-vault (Fig. 13), flying-buttresses (Fig. 13\n"
      "with flyers), bezier-arch (Fig. 12), chapel (Fig. 9, 480 blocks), abbey (Fig. 1, 988 blocks), mosque\n"
      "(Fig. 10 c, a windowed drum with flyers, 296), mosque-hall (Fig. 10 a, d, on a square hall, 336),\n"
      "groin-vault (a groin vault on four corner piers, 80); or a template alone: semicircular-arch,\n"
      "pointed-arch, column, wall, buttress, dome, dome-on-drum.\n"
      "Prints y/W² and the solver's status; with --optimize, the search's status (feasible or local\n"
      "minimum), its iterations and the values it found.");
  StaticsExampleRequest& e = requests.add<StaticsExampleRequest>(example);
  positional(*example, "NAME", e.name, "The example's name.")->required();
  declareModelOptions(*example, e.model);
  declareAnalysis(*example, e.analysis);
}

void declareSimulate(CLI::App& app, Requests& requests) {
  CLI::App* c = command(
      app, "simulate", "Rigid-body simulation of a masonry model (Bullet; docs/sim.md).",
      "At time --at: a ground shake of V m/s along x within 1/60 s (\"paper\": the paper's 4 m/s on 10 m,\n"
      "scaled to the model), blocks removed or broken along a 45° crack, a stone dropped on a block.\n"
      "Prints a JSON summary (largest displacement per block, fallen blocks); --frames writes PNGs.");
  SimulateRequest& r = requests.add<SimulateRequest>(c);
  CLI::Option* project = positional(*c, "PROJECT", r.project, "A project with one masonry object or stone extrusion (or --object).");
  CLI::Option* example = text(*c, "--example", r.example, "NAME", "One of the statics examples instead of a project.");
  example->excludes(project);
  text(*c, "--object", r.object, "NAME", "The project's masonry object or stone extrusion to simulate.")->excludes(example);
  addRepeated(*c, "--set", r.sets, "Set a parameter of the model.")->type_name("NAME=V");
  number(*c, "--seconds", r.seconds, 0, 1e5, "S", "How long to simulate.");
  text(*c, "--shake", r.shake, "V|paper", "A ground shake of V m/s along x, or the paper's.");
  addRepeated(*c, "--remove", r.removes, "Remove a block.")->type_name("BLOCK");
  addRepeated(*c, "--break", r.breaks, "Break a block along a 45° crack.")->type_name("BLOCK");
  CLI::Option* drop = text(*c, "--drop", r.drop, "BLOCK", "Drop a stone on this block.");
  number(*c, "--drop-mass", r.dropMass, 1e-6, 1e9, "KG", "The dropped stone's mass.")->needs(drop);
  number(*c, "--drop-height", r.dropHeight, 0, 1e4, "M", "The height it falls from.")->needs(drop);
  number(*c, "--at", r.at, 0, 1e5, "T", "When the shake, removals, breaks and drop happen (seconds).");
  number(*c, "--friction", r.friction, 0, 100, "A", "The friction coefficient (default: the model's).");
  choice(*c, "--solver", r.solver, {"impulses", "qp"},
         "The contact solver: Bullet's sequential impulses, or a QP per step solved to optimality\n"
         "(what the statics analysis calls standing stays still; slower).");
  text(*c, "--frames", r.frames, "DIR", "Write a PNG per frame into DIR.");
  number(*c, "--fps", r.fps, 1, 240, "N", "Frames per second for --frames.");
  addSize(*c, "--size", r.size, 16, 4096, "The frames' size.");
}

void declareKifs(CLI::App& app, Requests& requests) {
  CLI::App* c = command(
      app, "kifs", "A KIFS building (McGraw) raymarched headless, meshed, or its distance evaluated.",
      "Presets: the files assets/kifs/NAME.json (box, menger, t, h, polar, curved, sparse, crumbling, turned,\n"
      "star, tower, balconies; default box). A project gives its first KIFS object.\n"
      "--out renders a PNG; --frames N renders N times after one untimed frame (the first draw compiles the\n"
      "shader) and prints the mean milliseconds per frame. --mode preview shades without soft shadow and\n"
      "occlusion, as the editor's coarse frames do; --mode cost writes a heat map of distance evaluations per\n"
      "pixel and prints their means (JSON).\n"
      "--mesh meshes the building (marching tetrahedra, --resolution cells along the longest side) and\n"
      "exports it; prints one JSON line (faces, closed, seconds).\n"
      "--eval prints the CPU distance bound and estimate (\"bound surface\") of each point \"x y z\" (one a\n"
      "line, world coordinates, Z up) of the file POINTS.");
  KifsRequest& r = requests.add<KifsRequest>(c);
  CLI::Option* source = positional(*c, "SOURCE", r.source,
                                   "A preset's name, a preset file (NAME.json) or a project (.corbel).");
  text(*c, "--preset", r.preset, "NAME", "A preset's name (as SOURCE).")->excludes(source);
  text(*c, "--out", r.out, "PNG", "Render the building to this image.");
  addSize(*c, "--size", r.size, 1, 8192, "The image's size.");
  choice(*c, "--mode", r.mode, {"shaded", "preview", "facades", "floors", "bare", "cost"},
         "What the image shows (bare: the fractal without the inner shell, McGraw's Fig. 3c).", {"ids"});
  text(*c, "--camera", r.camera, "AZ,EL", "Azimuth and elevation in degrees (default -60,22; EL in [-89, 89]).");
  whole(*c, "--frames", r.frames, 1, 1000, "N", "Time N frames.");
  text(*c, "--eval", r.eval, "POINTS", "Evaluate the distance at the points of this file.");
  text(*c, "--mesh", r.mesh, kExportTypes, "Mesh the building into this file.");
  whole(*c, "--resolution", r.resolution, 1, 1024, "N", "The mesh's cells along the longest side.");
}

void declareGrow(CLI::App& app, Requests& requests) {
  CLI::App* c = command(app, "grow", "Grow housing units on a site (docs/growth.md); prints one JSON line.");
  GrowRequest& r = requests.add<GrowRequest>(c);
  positional(*c, "SITE", r.site, "The site file (.json), or a project (.corbel) with a growth object.")->required();
  text(*c, "--object", r.object, "NAME", "The project's growth object (when it has several).");
  whole(*c, "--seed", r.seed, 0, 1ll << 62, "N", "The random seed (default 1, or the growth object's).");
  whole(*c, "--steps", r.steps, 0, 100000000, "K",
        "The most growth steps (default 100000, or the growth object's: all when it has -1).");
  c->add_flag("--stats", r.stats, "Add the statistics of Table 8.1.");
  text(*c, "--out", r.out, kExportTypes, "Write the grown model.");
  text(*c, "--render", r.render, "PNG", "Render the grown model.");
  choice(*c, "--view-maps", r.viewMaps, {"exact", "raster", "gl"},
         "How views are measured: exactly, on the CPU rasterizer or in GL (OSMesa).");
  number(*c, "--pixel", r.pixel, 0.01, 10, "M", "The pixel size of raster and gl view maps.");
}

void declareComplete(CLI::App& app, Requests& requests) {
  CLI::App* c = command(
      app, "complete", "Complete forms from seed units (Ch. 7, docs/growth.md); prints one JSON line.",
      "Completes forms from N seed units with the complexity F_q in [LO, HI], fits and sizes them into the\n"
      "region and realizes the entrances. With --from, the seeds are a grown model's units that open onto\n"
      "its gap (the region, by default the most enclosed one of the storey) and their entrances.");
  CompleteRequest& r = requests.add<CompleteRequest>(c);
  CLI::Option* from = text(*c, "--from", r.from, "PROJECT", "Complete a gap of this project's grown model.");
  whole(*c, "--seeds", r.seeds, 1, 12, "N", "The number of seed units (without --from).")->excludes(from);
  addRepeated(*c, "--entrance", r.entrances, "An entrance point for a seed (without --from).")
      ->type_name("X,Y")
      ->excludes(from);
  text(*c, "--object", r.object, "NAME", "The project's growth object.")->needs(from);
  whole(*c, "--storey", r.storey, 0, 1000, "K", "The storey to complete (default 0).")->needs(from);
  text(*c, "--complexity", r.complexity, "LO:HI", "The range of F_q, 0 <= LO <= HI < 0.5.")->required();
  whole(*c, "--count", r.count, 1, 64, "K", "How many forms.");
  text(*c, "--region", r.region, "X0,Y0,X1,Y1", "The region in meters (default 0,0,24,16; with --from, the gap).");
  whole(*c, "--seed", r.seed, 0, 1ll << 62, "S", "The random seed.");
  text(*c, "--out", r.out, kExportTypes, "Write the forms.");
  text(*c, "--render", r.render, "PNG", "Render the forms.");
}

void declareCity(CLI::App& app, Requests& requests) {
  CLI::App* c = command(
      app, "city", "A styled town from footprints or along a street (docs/city.md).",
      "Prints one JSON line; skipped buildings on stderr. Give at least one of --out, --tiles, --tileset and --render.\n"
      "--street builds town houses along a spline; --plots skeleton grows its plots from seeds (Fig. 26).");
  CityRequest& r = requests.add<CityRequest>(c);
  CLI::Option* footprints = positional(*c, "FOOTPRINTS", r.footprints,
                                      "Footprints: GeoJSON or any GDAL/OGR vector source (or --street).");
  CLI::Option* street =
      text(*c, "--street", r.street, "X,Y;X,Y;...", "Town houses along this spline instead of footprints.");
  street->excludes(footprints);
  text(*c, "--style", r.style, "STYLE.json", "The town's style.")->required();
  whole(*c, "--seed", r.seed, 0, 9007199254740992ll, "N", "The random seed.");
  whole(*c, "--jobs", r.jobs, 0, 1024, "N", "Worker threads (0: one per core).");
  text(*c, "--out", r.out, kExportTypes, "Write the whole town.");
  CLI::Option* tiles = text(*c, "--tiles", r.tiles, "DIR", "Write one glb per tile into DIR.");
  number(*c, "--tile-size", r.tileSize, 1, 1e6, "M",
         "The tiles' side. Without --tileset the buildings are built and written tile by tile, a glb --out's too.");
  CLI::Option* tileset = text(*c, "--tileset", r.tileset, "DIR",
       "Write a 3D Tiles 1.1 tileset into DIR (new or empty): tileset.json, and blocks and buildings per tile "
       "(docs/city.md).")
      ->excludes(tiles);
  whole(*c, "--tile-buildings", r.tileBuildings, 1, 1000000, "N", "At most N buildings in a tileset's tile.")
      ->needs(tileset);
  number(*c, "--ground", r.ground, -1e4, 1e4, "M", "The tileset's ground at the town's origin, above the WGS 84 ellipsoid.")
      ->needs(tileset);
  whole(*c, "--stream-buildings", r.streamBuildings, 0, 100000000, "N",
        "With --tiles, --tileset or a glb --out, and no --render, read the footprints about N "
        "buildings (whole tiles) at a time; 0: read it whole (docs/city.md, \"Memory\").");
  text(*c, "--render", r.render, "PNG", "Render the town.");
  text(*c, "--around", r.around, "X,Y,R", "Only the buildings within R meters of (X, Y).");
  choice(*c, "--coordinates", r.coordinates, {"auto", "lonlat", "metric"},
         "How to read the footprints' coordinates (lonlat: as --crs EPSG:4326; metric: as --crs local).");
  footprintOptions(*c, r.crs, r.layer, r.where);
  text(*c, "--report", r.report, "FILE.jsonl",
       "One JSON line per building: type, notes, warnings, error, and the footprint's `area` (m²) and `depth` (m, "
       "`docs/city.md`) for every building the clean-up kept.");
  choice(*c, "--detail", r.detail, {"massing", "steps", "full"}, "How much of each building to build.");
  choice(*c, "--textures", r.textures, {"on", "off"}, "Textures in the glb files.");
  choice(*c, "--render-textures", r.renderTextures, {"on", "off"}, "Textures in the --render image.");
  c->add_flag("--instances", r.instances,
              "glb: each window, sill, door, roof window and chimney pot shape written once and placed by "
              "EXT_mesh_gpu_instancing (docs/export.md).");
  c->add_flag("--compress", r.compress, "glb: compress the geometry with meshoptimizer (EXT_meshopt_compression).");
  CLI::Option* plots = c->add_option("--plots", r.plots, "How the street's plots are cut.")
                           ->check(oneOf({"normals", "skeleton"}))
                           ->type_name("normals|skeleton")
                           ->default_str("normals");
  plots->needs(street);
}

void declareCitySplit(CLI::App& app, Requests& requests) {
  CLI::App* c = command(
      app, "city-split", "Cut footprints into square tiles for separate city builds (docs/city.md).",
      "Writes OUT/sources/X_Y.geojson per tile that owns a building (the one holding the mean of its outer\n"
      "ring's corners), with the buildings and streets within --margin of them marked \"corbel_margin\" (city\n"
      "labels them but does not build them), and OUT/tiles.txt, one tile name a line, for a job runner:\n"
      "  parallel -j 2 corbel-cli city OUT/sources/{}.geojson --style S --tileset OUT/tilesets/{} :::: OUT/tiles.txt\n"
      "then city-merge OUT. Prints one JSON line.");
  CitySplitRequest& r = requests.add<CitySplitRequest>(c);
  positional(*c, "SOURCE", r.source, "Footprints: GeoJSON or any GDAL/OGR vector source.")->required();
  number(*c, "--grid", r.grid, 0.01, 1000, "KM", "The tiles' side, km.")->required();
  text(*c, "--out", r.out, "DIR", "A new or empty folder for the tiles' sources.")->required();
  number(*c, "--margin", r.margin, 0, 10000, "M", "Neighbours within this of a tile's buildings go with them, for labels.");
  choice(*c, "--coordinates", r.coordinates, {"auto", "lonlat", "metric"},
         "How to read the footprints' coordinates (lonlat: as --crs EPSG:4326; metric: as --crs local).");
  footprintOptions(*c, r.crs, r.layer, r.where);
}

void declareCityMerge(CLI::App& app, Requests& requests) {
  CLI::App* c = command(app, "city-merge", "Write one 3D Tiles tileset over the tiles of a city-split folder (docs/city.md).",
                        "Reads DIR/tilesets/NAME/tileset.json for every NAME of DIR/tiles.txt and writes DIR/tileset.json\n"
                        "with their roots as children. Prints one JSON line.");
  CityMergeRequest& r = requests.add<CityMergeRequest>(c);
  positional(*c, "DIR", r.dir, "The folder city-split wrote, its tiles built into DIR/tilesets/NAME.")->required();
}

}  // namespace

const Request* Requests::chosen(const CLI::App& app) const {
  const CLI::App& at = chosenCommand(app);
  const auto it = byCommand_.find(&at);
  return it == byCommand_.end() ? nullptr : it->second.get();
}

void declareCommands(CLI::App& app, Requests& requests) {
  app.name(kProgram);
  app.description("corbel-cli: the headless tools of corbel, one subcommand each.");
  // A repeated single option keeps its last value, as before CLI11; one subcommand per run.
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.require_subcommand(0, 1);
  addVersionFlag(app, kProgram);
  declareRender(app, requests);
  declareExport(app, requests);
  declareCheck(app, requests);
  declareEdit(app, requests);
  declareExtrude(app, requests);
  declareStatics(app, requests);
  declareSimulate(app, requests);
  declareKifs(app, requests);
  declareGrow(app, requests);
  declareComplete(app, requests);
  declareCity(app, requests);
  declareCitySplit(app, requests);
  declareCityMerge(app, requests);
  app.footer("'corbel-cli SUBCOMMAND --help' gives a subcommand's options; docs/cli.md all of them.\n"
             "Exit codes: 0 success, 1 bad input or failed check, 2 bad command line.");
}

}  // namespace corbel::cli
