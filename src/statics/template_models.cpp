#include "statics/template_models.h"

#include "statics/arch.h"
#include "statics/builder.h"
#include "statics/buttress.h"
#include "statics/column.h"
#include "statics/dome.h"
#include "statics/wall.h"

#include <cmath>

namespace corbel::statics {
namespace {

// Shared by both arches: voussoirs, centreline radius, thickness and depth.
void addArchParameters(ParametricModel& m, int voussoirs) {
  m.parameters.add(makeParameter("voussoirs", voussoirs, 2, 400, "voussoirs of the arch", false));
  m.parameters.add(makeParameter("radius", 1.0, 0.05, 50.0, "half the span of the centreline, m"));
  m.parameters.add(makeParameter("thickness", 0.2, 0.005, 10.0, "thickness of the ring, m"));
  m.parameters.add(makeParameter("depth", 0.5, 0.01, 20.0, "depth along the arch's axis, m"));
  m.suggestedFree = {{"thickness", 0.02, 0.6}};
}

ParametricModel semicircularArchModel() {
  ParametricModel m;
  m.name = "semicircular-arch";
  m.description = "A semicircular arch of voussoirs with radial joints on the ground (Fig. 4)";
  addArchParameters(m, 12);
  m.build = [](const ParameterSet& p) {
    ArchSpec s;
    s.blocks = countOf(p, "voussoirs");
    s.radius = p["radius"];
    s.thickness = p["thickness"];
    s.depth = p["depth"];
    return semicircularArch(s);
  };
  return m;
}

ParametricModel pointedArchModel() {
  ParametricModel m;
  m.name = "pointed-arch";
  m.description = "A pointed (gothic) arch: two arcs of radius ratio × half the span meeting at the crown (Fig. 4)";
  addArchParameters(m, 12);
  m.parameters.add(makeParameter("radiusRatio", 2.0, 1.0, 10.0, "arc radius over half the span (1 round, 2 equilateral)"));
  m.build = [](const ParameterSet& p) {
    PointedArchSpec s;
    s.blocks = countOf(p, "voussoirs");
    s.radius = p["radius"];
    s.radiusRatio = p["radiusRatio"];
    s.thickness = p["thickness"];
    s.depth = p["depth"];
    return pointedArch(s);
  };
  return m;
}

ParametricModel columnModel() {
  ParametricModel m;
  m.name = "column";
  m.description = "A column of drums, its section a regular polygon (4 sides: a square pier), on the ground";
  m.parameters.add(makeParameter("drums", 4, 1, 100, "drums (courses) of the column", false));
  m.parameters.add(makeParameter("sides", 8, 3, 64, "sides of the section", false));
  m.parameters.add(makeParameter("radius", 0.3, 0.02, 10.0, "circumradius of the section, m"));
  m.parameters.add(makeParameter("height", 3.0, 0.05, 100.0, "height of the column, m"));
  m.suggestedFree = {{"radius", 0.05, 1.5}};
  m.build = [](const ParameterSet& p) {
    ColumnSpec s;
    s.drums = countOf(p, "drums");
    s.sides = countOf(p, "sides");
    s.radius = p["radius"];
    s.height = p["height"];
    StructureBuilder b;
    b.add("column", columnBlocks(s));
    b.groundUnder(1.0);
    return b.build();
  };
  return m;
}

ParametricModel wallModel() {
  ParametricModel m;
  m.name = "wall";
  m.description = "A wall of courses in running bond with windows under lintels (Fig. 3), on the ground";
  m.parameters.add(makeParameter("length", 4.0, 0.2, 200.0, "length of the wall, m"));
  m.parameters.add(makeParameter("thickness", 0.4, 0.02, 10.0, "thickness of the wall, m"));
  m.parameters.add(makeParameter("height", 3.0, 0.1, 100.0, "height of the wall, m"));
  m.parameters.add(makeParameter("courses", 6, 1, 200, "courses of the wall", false));
  m.parameters.add(makeParameter("blockLength", 0.5, 0.05, 20.0, "length of a block (odd courses shifted by half), m"));
  m.parameters.add(makeParameter("windows", 1, 0, 50, "windows, evenly spaced along the wall", false));
  m.parameters.add(makeParameter("windowWidth", 1.0, 0.05, 50.0, "width of each window, m"));
  m.parameters.add(makeParameter("sill", 1, 0, 199, "first open course of the windows (0: doors)", false));
  m.parameters.add(makeParameter("head", 3, 1, 199, "the course over the windows, holding their lintels", false));
  m.suggestedFree = {{"thickness", 0.1, 1.2}};
  m.build = [](const ParameterSet& p) {
    WallSpec s;
    s.length = p["length"];
    s.thickness = p["thickness"];
    s.height = p["height"];
    s.courses = countOf(p, "courses");
    s.blockLength = p["blockLength"];
    const int n = countOf(p, "windows");
    for (int k = 0; k < n; ++k) {
      WindowSpec w;
      w.width = p["windowWidth"];
      w.x = (k + 0.5) * s.length / n - w.width / 2;  // centred in its n-th of the wall
      w.sill = countOf(p, "sill");
      w.head = countOf(p, "head");
      s.windows.push_back(w);
    }
    StructureBuilder b;
    b.add("wall", wallBlocks(s));
    b.groundUnder(1.0);
    return b.build();
  };
  return m;
}

ParametricModel buttressModel() {
  ParametricModel m;
  m.name = "buttress";
  m.description = "A buttress of courses tapering from its base to its top (Fig. 4), on the ground";
  m.parameters.add(makeParameter("height", 3.0, 0.1, 100.0, "height, m"));
  m.parameters.add(makeParameter("baseWidth", 1.0, 0.05, 20.0, "width of the lowest course, m"));
  m.parameters.add(makeParameter("topWidth", 0.6, 0.05, 20.0, "width of the highest course, m"));
  m.parameters.add(makeParameter("depth", 1.0, 0.05, 20.0, "depth, m"));
  m.parameters.add(makeParameter("courses", 6, 1, 200, "courses", false));
  m.suggestedFree = {{"baseWidth", 0.2, 3.0}};
  m.build = [](const ParameterSet& p) {
    ButtressSpec s;
    s.height = p["height"];
    s.baseWidth = p["baseWidth"];
    s.topWidth = p["topWidth"];
    s.depth = p["depth"];
    s.courses = countOf(p, "courses");
    StructureBuilder b;
    b.add("buttress", buttressBlocks(s));
    b.groundUnder(1.0);
    return b.build();
  };
  return m;
}

// The dome's own parameters, shared by the dome alone and the dome on a drum.
void addDomeParameters(ParametricModel& m) {
  m.parameters.add(makeParameter("rings", 8, 1, 100, "rings of voussoirs from the springing to the oculus", false));
  m.parameters.add(makeParameter("segments", 16, 3, 256, "voussoirs per ring", false));
  m.parameters.add(makeParameter("radius", 2.0, 0.1, 50.0, "radius of the dome's middle surface, m"));
  m.parameters.add(makeParameter("thickness", 0.2, 0.01, 10.0, "thickness of the dome, m"));
  m.parameters.add(makeParameter("oculus", 10.0, 1.0, 80.0, "angle of the oculus from the pole, degrees"));
}

DomeSpec domeOf(const ParameterSet& p) {
  DomeSpec s;
  s.rings = countOf(p, "rings");
  s.segments = countOf(p, "segments");
  s.radius = p["radius"];
  s.thickness = p["thickness"];
  s.oculusDeg = p["oculus"];
  return s;
}

ParametricModel domeModel() {
  ParametricModel m;
  m.name = "dome";
  m.description = "A hemispherical dome of rings of voussoirs up to an oculus (Fig. 4, Fig. 10), on the ground";
  addDomeParameters(m);
  m.suggestedFree = {{"thickness", 0.02, 0.6}};
  m.build = [](const ParameterSet& p) {
    StructureBuilder b;
    b.add("dome", domeBlocks(domeOf(p)));
    b.groundUnder(1.0);
    return b.build();
  };
  return m;
}

ParametricModel domeOnDrumModel() {
  ParametricModel m;
  m.name = "dome-on-drum";
  m.description = "A dome on a round drum of courses in running bond (Fig. 10), on the ground";
  addDomeParameters(m);
  m.parameters.add(makeParameter("drumHeight", 2.0, 0.1, 50.0, "height of the drum, m"));
  m.parameters.add(makeParameter("drumThickness", 0.3, 0.02, 10.0, "thickness of the drum, m"));
  m.parameters.add(makeParameter("drumCourses", 4, 1, 100, "courses of the drum", false));
  m.suggestedFree = {{"drumThickness", 0.1, 1.5}};
  m.build = [](const ParameterSet& p) {
    const DomeSpec dome = domeOf(p);
    DrumSpec drum;
    drum.courses = countOf(p, "drumCourses");
    drum.segments = dome.segments;  // face to face with the dome's springing ring
    drum.radius = dome.radius;
    drum.thickness = p["drumThickness"];
    drum.height = p["drumHeight"];
    StructureBuilder b;
    b.add("drum", drumBlocks(drum));
    b.add("dome", domeBlocks(dome), Vec3(0.0, 0.0, drum.height));
    b.groundUnder(1.0);
    return b.build();
  };
  return m;
}

}  // namespace

std::vector<std::string> templateModelNames() {
  return {"semicircular-arch", "pointed-arch", "column", "wall", "buttress", "dome", "dome-on-drum"};
}

std::optional<ParametricModel> templateModelByName(const std::string& name) {
  if (name == "semicircular-arch") return semicircularArchModel();
  if (name == "pointed-arch") return pointedArchModel();
  if (name == "column") return columnModel();
  if (name == "wall") return wallModel();
  if (name == "buttress") return buttressModel();
  if (name == "dome") return domeModel();
  if (name == "dome-on-drum") return domeOnDrumModel();
  return std::nullopt;
}

}  // namespace corbel::statics
