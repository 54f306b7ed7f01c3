// Presets are files (assets/kifs/NAME.json, kifs/params.h): each one loads to the parameters the
// C++ table held before the move (copied below, verbatim, as the reference), and a bad file is
// refused with its path and the JSON path of the fault.
#include "core/error.h"
#include "core/kifs_json.h"
#include "kifs/distance.h"
#include "kifs/kernel.h"
#include "kifs/params.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <set>

#include <unistd.h>

namespace corbel::kifs::test {
namespace {

namespace fs = std::filesystem;

// The former kifs/presets.cpp table (commit f28817b), the reference of the move.
namespace former {
// Fig. 1b and Fig. 7 (left): c = (0.93, 0.93, 0.33) on a box. With r = 0 Algorithm 2 is the
// plain triangle wave, so each 6 m bay shows the fractal's face once, mirrored, and each 3 m
// storey the upper half of its slab (s = a2 = 1: isotropic, 3 m per fractal unit).
KifsParams boxBuilding() {
  KifsParams p;
  p.centre = {0.93, 0.93, 0.33};
  p.facade.r = {0.0, 0.0, 0.0};
  p.facade.a2 = 1.0;
  p.facade.b2 = 0.0;
  // The roof cuts the eighth storey at 0.6 of its height: a parapet, not the fractal's dusty top
  // face (the paper leaves roofs open, Sec. 4).
  p.mass.height = 22.8;
  return p;
}

KifsParams menger() {  // Fig. 1a: s = 3, c = (1, 1, 1), R1 = R2 = I on a box
  KifsParams p = boxBuilding();
  p.centre = {1.0, 1.0, 1.0};
  return p;
}

KifsParams tBuilding() {  // Fig. 8 (left): T footprint
  KifsParams p = boxBuilding();
  p.mass.footprint = Footprint::T;
  p.mass.halfWidth = 12.0;
  p.mass.halfDepth = 9.0;
  p.mass.wing = 3.5;
  p.mass.height = 18.0;
  return p;
}

// Fig. 8 (right) and Fig. 6: H footprint; r = (0.25, 0.125, 0.4) of Fig. 6 divides each bay
// into id regions, and s = a1·id + a2, t = b1·id + b2 give each its own part of the fractal.
KifsParams hBuilding() {
  KifsParams p = boxBuilding();
  p.facade.r = {0.25, 0.125, 0.4};
  p.mass.footprint = Footprint::H;
  p.mass.halfWidth = 12.0;
  p.mass.halfDepth = 10.0;
  p.mass.wing = 3.5;
  p.mass.height = 15.0;
  p.facade.a1 = 0.5;
  p.facade.a2 = 1.5;
  p.facade.b1 = 0.2;
  return p;
}

// Fig. 7 (right): curvilinear coordinates (Eq. 5-6) closing into a round tower.
KifsParams polarTower() {
  KifsParams p = boxBuilding();
  p.curvilinear.enabled = true;
  p.curvilinear.sTheta = 36.0 / std::numbers::pi;  // the circumference 2π·s_θ is 12 facade periods
  p.curvilinear.sR = 1.0;
  p.curvilinear.cR = -10.0;
  p.curvilinear.cTheta = 0.0;
  p.mass.halfWidth = 40.0;  // wider than s_θ·π: the whole ring, with no seam
  p.mass.halfDepth = 2.5;
  p.mass.shell = 1.0;
  p.mass.height = 30.0;
  return p;
}

// Fig. 7 (middle) and Fig. 6b: a curved building, an arc of a quarter turn.
KifsParams curvedBuilding() {
  KifsParams p = boxBuilding();
  p.curvilinear.enabled = true;
  p.curvilinear.sTheta = 14.0;
  p.curvilinear.cR = -16.0;
  p.mass.halfWidth = 14.0 * std::numbers::pi / 4;  // θ in [−π/4, π/4]
  p.mass.halfDepth = 4.0;
  p.mass.height = 21.0;
  return p;
}

// Fig. 2a-d on the box: s = 3.5 (sparse, disconnected), R1 = Ry(π/25) (crumbling),
// R1 = Ry(π/4), R2 = Ry(π/8) (polygonal, star-like).
KifsParams sparse() {
  KifsParams p = boxBuilding();
  p.scale = 3.5;
  return p;
}
KifsParams crumbling() {
  KifsParams p = boxBuilding();
  p.r1.yDeg = 180.0 / 25.0;
  return p;
}
KifsParams turned() {
  KifsParams p = boxBuilding();
  p.r1.yDeg = 45.0;
  return p;
}
KifsParams star() {
  KifsParams p = boxBuilding();
  p.r2.yDeg = 22.5;
  return p;
}

const std::map<std::string, std::function<KifsParams()>>& table() {
  static const std::map<std::string, std::function<KifsParams()>> t = {
      {"box", boxBuilding}, {"menger", menger}, {"t", tBuilding}, {"h", hBuilding}, {"polar", polarTower}, {"curved", curvedBuilding},
      {"sparse", sparse},   {"crumbling", crumbling}, {"turned", turned}, {"star", star}};
  return t;
}
}  // namespace former

TEST(KifsPresetFiles, EveryFormerPresetIsAFileWithTheSameNumbers) {
  // The former presets are among the files (later ones, like Fig. 9's, were files from the start).
  const std::vector<std::string> names = presetNames();
  for (const auto& [name, make] : former::table())
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  for (const auto& [name, make] : former::table()) {
    SCOPED_TRACE(name);
    const KifsParams want = make(), got = preset(name);
    // specOf holds every field but the pixel angle (set per view); == is exact on doubles.
    EXPECT_EQ(specOf(got, name), specOf(want, name));
    EXPECT_EQ(got.trace.pixelAngle, want.trace.pixelAngle);
    EXPECT_EQ(got.curvilinear.sTheta, want.curvilinear.sTheta);  // 36/π survives the text
  }
}

TEST(KifsPresetFiles, FilesAreWhatTheProjectFormatWrites) {
  // Each file is the spec the project file would hold for it (kifsToJson), key for key, so the
  // files and "kifs" objects of projects can be copied into each other.
  for (const std::string& name : presetNames()) {
    SCOPED_TRACE(name);
    std::ifstream in(fs::path(presetDir()) / (name + ".json"));
    const nlohmann::json file = nlohmann::json::parse(in);
    EXPECT_EQ(file, nlohmann::json::parse(kifsToJson(specOf(preset(name), name)).dump()));
    EXPECT_EQ(file.value("preset", ""), name);
  }
}

// The presets in the spirit of McGraw's Fig. 9 ("additional KIFS building results"; our copy of
// the paper has its caption only, so the looks are corbel's): a tower and a T-plan block of
// balconies. Unlike `box`, whose roof cuts a storey into a parapet, each is a whole number of
// storeys, so the roof lies on a floor line; and like `h`, Algorithm 2 divides each bay into
// id regions (r, a1, b1 set), so the facade is not one motif repeated.
TEST(KifsPresetFiles, TheFig9PresetsEndOnAFloorLineAndDivideTheirBays) {
  for (const auto& [name, storeys] : std::vector<std::pair<std::string, int>>{{"tower", 12}, {"balconies", 12}}) {
    SCOPED_TRACE(name);
    const KifsParams p = preset(name);
    const Building b(p);
    const double h = p.floors.height, top = p.mass.height;
    // Just under the roof is the last storey; just under its floor line, the one before.
    EXPECT_EQ(b.evaluate({0, 0, top - 1e-3}).floor, storeys - 1);
    EXPECT_EQ(b.evaluate({0, 0, top - h + 1e-3}).floor, storeys - 1);
    EXPECT_EQ(b.evaluate({0, 0, top - h - 1e-3}).floor, storeys - 2);
    EXPECT_TRUE(b.idsCut());
    // Across one bay of the front (x-)face, the ids take more than one value.
    std::set<int> ids;
    for (int i = 0; i < 600; ++i)
      ids.insert(b.evaluate({-p.mass.halfWidth + p.facade.period * (i + 0.5) / 600, -p.mass.halfDepth, h / 2}).idX);
    EXPECT_GE(ids.size(), 2u);
  }
}

class BadPresetFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("corbel-kifs-presets-" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "kifs");
  }
  void TearDown() override {
    ::unsetenv("CORBEL_ASSETS_DIR");
    fs::remove_all(dir_);
  }
  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / "kifs" / (name + ".json");
    std::ofstream(p) << text;
    return p.string();
  }
  // The message of loading `text` as a preset file.
  std::string error(const std::string& text) {
    const std::string file = write("bad", text);
    try {
      loadPreset(file);
    } catch (const Error& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind(file + ": ", 0), 0u) << m;  // begins with the file
      return m;
    }
    ADD_FAILURE() << "loaded: " << text;
    return {};
  }
  fs::path dir_;
};

TEST_F(BadPresetFile, ErrorsNameTheFileAndTheJsonPath) {
  EXPECT_NE(error("").find("file is empty"), std::string::npos);
  EXPECT_NE(error("{\"scale\": 3.0,").find("not valid JSON"), std::string::npos);
  EXPECT_NE(error("[1, 2]").find("kifs: "), std::string::npos);
  EXPECT_NE(error("{\"scale\": \"big\"}").find("kifs.scale: "), std::string::npos);
  EXPECT_NE(error("{\"centre\": [1, 2]}").find("kifs.centre: "), std::string::npos);
  EXPECT_NE(error("{\"mass\": {\"footprint\": \"L\"}}").find("kifs.mass.footprint: "), std::string::npos);
  // Values: the kernel's checks, with the same paths.
  EXPECT_NE(error("{\"scale\": 0.5}").find("kifs.scale: must be in (1, 10], got 0.5"), std::string::npos);
  EXPECT_NE(error("{\"mass\": {\"shell\": 7}}").find("kifs.mass.shell: "), std::string::npos);
  // A typo would fall back to a default silently: refused.
  EXPECT_NE(error("{\"mass\": {\"hieght\": 7}}").find("kifs.mass.hieght: unknown key"), std::string::npos);
  // An empty object is the defaults of core/kifs_spec.h.
  const std::string file = write("defaults", "{}");
  EXPECT_EQ(specOf(loadPreset(file)), specOf(KifsParams{}));
}

TEST_F(BadPresetFile, NamesComeFromTheAssetsFolder) {
  write("tower", "{\"mass\": {\"height\": 40.0}}");
  write("bad", "{\"scale\": 0.5}");
  std::ofstream(dir_ / "kifs" / "notes.txt") << "not a preset";
  ::setenv("CORBEL_ASSETS_DIR", dir_.c_str(), 1);
  EXPECT_EQ(presetNames(), (std::vector<std::string>{"bad", "tower"}));
  EXPECT_EQ(preset("tower").mass.height, 40.0);
  try {
    preset("box");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no KIFS preset named 'box'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("presets: bad, tower"), std::string::npos) << e.what();
  }
  EXPECT_THROW(preset("../kifs/tower"), Error);
  try {
    preset("bad");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json: kifs.scale: "), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace corbel::kifs::test
