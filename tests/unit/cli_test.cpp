// corbel-cli: exit codes and messages for bad project files and bad command lines, and the
// output of check, export and render on the example.
#include "core/project_io.h"
#include "cli_run.h"
#include "render/image.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include <set>
#include <sstream>

namespace {

using corbel::test::cli;
using corbel::test::CliRun;
using corbel::test::quote;
using corbel::test::readText;
using corbel::test::TempDir;
using corbel::test::writeText;

const std::string kVillage = corbel::test::sourcePath("assets/examples/village.corbel");

std::string withBox(const std::string& box) {
  return R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "A", "box": {)" + box + "}}]}";
}

struct BadFile {
  std::string name, text, expected;  // expected: a part of stderr after the file's path
};

std::vector<BadFile> badFiles() {
  const std::string village = readText(kVillage);
  return {
      {"truncated.corbel", village.substr(0, village.size() / 2), "not valid JSON: "},
      {"notjson.corbel", "corbel project, version one\n", "not valid JSON: "},
      {"empty.corbel", "", "file is empty"},
      {"array.corbel", "[1, 2]", "a project file must hold a JSON object"},
      {"wrongtype.corbel", withBox(R"("size": "10")"), "objects[0].box.size: expected [x, y, z] numbers"},
      {"nan.corbel", withBox(R"("size": [NaN, 1, 1])"), "not valid JSON: "},
      {"overflow.corbel", withBox(R"("size": [1, 1e999, 1])"), "objects[0].box.size[1]: number is not finite"},
      {"hugecount.corbel", withBox(R"("size": [1, 1, 1], "repeat": {"count": [1000000, 1000000]})"),
       "objects[0].box.repeat.count[0]: 1000000 is larger than 10000"},
      {"future.corbel", R"({"format": "corbel", "version": 99})",
       "version: this file was written by a newer corbel (format version 99)"},
      {"negative.corbel", withBox(R"("size": [1, -1, 1])"), "objects[0].box.size: each extent must be between"},
  };
}

TEST(Cli, BadProjectFilesExitOneWithPathAndReason) {
  TempDir dir;
  for (const BadFile& bad : badFiles()) {
    SCOPED_TRACE(bad.name);
    const std::string path = dir.file(bad.name);
    writeText(path, bad.text);
    const CliRun r = cli(dir, "check " + quote(path));
    EXPECT_EQ(r.code, 1) << r.err;
    // "corbel-cli: error: <path>: <where>: <reason>"
    EXPECT_NE(r.err.find("corbel-cli: error: " + path + ": " + bad.expected), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
}

TEST(Cli, BadProjectFilesFailEveryCommand) {
  TempDir dir;
  const std::string path = dir.file("wrongtype.corbel");
  writeText(path, withBox(R"("size": "10")"));
  for (const std::string& args : {"export " + quote(path) + " --out " + quote(dir.file("x.glb")),
                                  "render " + quote(path) + " --out " + quote(dir.file("x.png")) + " --size 32x24"}) {
    const CliRun r = cli(dir, args);
    EXPECT_EQ(r.code, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(path + ": objects[0].box.size: expected [x, y, z] numbers"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.glb")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

TEST(Cli, MissingFileAndFolder) {
  TempDir dir;
  const CliRun missing = cli(dir, "check " + quote(dir.file("nothing.corbel")));
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find(dir.file("nothing.corbel")), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("no such file"), std::string::npos) << missing.err;
  const CliRun folder = cli(dir, "check " + quote(dir.path()));
  EXPECT_EQ(folder.code, 1);
  EXPECT_NE(folder.err.find("is a folder"), std::string::npos) << folder.err;
}

TEST(Cli, BadCommandLinesExitTwo) {
  TempDir dir;
  const std::string v = quote(kVillage);
  const std::vector<std::string> bad = {
      "",
      "frobnicate " + v,
      "check",
      "check " + v + " " + v,
      "check " + v + " --out x",
      "export " + v,
      "export " + v + " --out",
      "export " + v + " --out " + quote(dir.file("model.stl")),
      "export --out " + quote(dir.file("a.obj")),
      "render " + v,
      "render " + v + " --out " + quote(dir.file("a.png")) + " --size 0x10",
      "render " + v + " --out " + quote(dir.file("a.png")) + " --size 10",
      "render " + v + " --out " + quote(dir.file("a.png")) + " --size 10.5x10",
      "render " + v + " --out " + quote(dir.file("a.png")) + " --size axb",
      "render " + v + " --out " + quote(dir.file("a.png")) + " --camera 10",
      "render " + v + " --out " + quote(dir.file("a.png")) + " --camera 10,20,-5",
      "render " + v + " --out " + quote(dir.file("a.png")) + " --bogus",
      "render " + v + " --out " + quote(dir.file("a.png")) + " --textures maybe",
  };
  for (const std::string& args : bad) {
    const CliRun r = cli(dir, args);
    EXPECT_EQ(r.code, 2) << "args: " << args << "\nstderr: " << r.err;
    if (!args.empty()) {
      EXPECT_EQ(r.err.rfind("corbel-cli: ", 0), 0u) << args << "\n" << r.err;
    }
  }
  // Nothing was written by any of them.
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Cli, HelpAndVersion) {
  TempDir dir;
  const CliRun help = cli(dir, "--help");
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("Usage: corbel-cli"), std::string::npos) << help.out;
  const CliRun none = cli(dir, "");  // the same usage, as a bad command line
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(none.out, help.out);
  const CliRun version = cli(dir, "--version");
  EXPECT_EQ(version.code, 0);
  EXPECT_NE(version.out.find("project format " + std::to_string(corbel::kProjectVersion)), std::string::npos)
      << version.out;
}

TEST(Cli, CheckPrintsOneJsonLinePerObject) {
  TempDir dir;
  const CliRun r = cli(dir, "check " + quote(kVillage));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const corbel::Document doc = corbel::loadProject(kVillage).document;
  std::istringstream lines(r.out);
  std::vector<nlohmann::json> rows;
  for (std::string line; std::getline(lines, line);) rows.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(rows.size(), doc.objects.size() + 1);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const nlohmann::json& row = rows[i];
    const auto& spec = std::get<corbel::BoxSpec>(doc.objects[i].spec);
    SCOPED_TRACE(doc.objects[i].name);
    EXPECT_EQ(row["object"], doc.objects[i].name);
    EXPECT_EQ(row["watertight"], true);
    EXPECT_EQ(row["manifold"], true);
    EXPECT_EQ(row["consistent"], true);
    EXPECT_TRUE(row["problems"].empty());
    // Each copy is a box: 6 faces, Euler characteristic 2 per component, volume w * d * h.
    const int copies = spec.repeat_x * spec.repeat_y;
    EXPECT_EQ(row["faces"], 6 * copies);
    EXPECT_EQ(row["components"], copies);
    EXPECT_EQ(row["euler"], 2 * copies);
    const double volume = copies * spec.size[0] * spec.size[1] * spec.size[2];
    EXPECT_NEAR(row["volume"].get<double>(), volume, 1e-9 * volume);
  }
  EXPECT_EQ(rows.back(), (nlohmann::json{{"objects", doc.objects.size()}, {"failed", 0}}));
}

TEST(Cli, UnknownKeysAreWarningsNotErrors) {
  TempDir dir;
  const std::string path = dir.file("extra.corbel");
  writeText(path, R"({"format": "corbel", "version": 1, "weather": "fine",
                      "objects": [{"id": 1, "name": "A", "box": {"size": [1, 1, 1], "roof": "flat"}}]})");
  const CliRun r = cli(dir, "check " + quote(path));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + path + ": weather: unknown key kept"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("warning: " + path + ": objects[0].box.roof: unknown key kept"), std::string::npos) << r.err;
}

tinygltf::Model loadGlb(const std::string& path) {
  tinygltf::Model model;
  std::string err, warn;
  tinygltf::TinyGLTF loader;
  EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, path)) << err;
  return model;
}

std::set<std::string> nodeNames(const tinygltf::Model& m) {
  std::set<std::string> out;
  for (const auto& n : m.nodes) out.insert(n.name);
  return out;
}

TEST(Cli, ExportGlbLoads) {
  TempDir dir;
  const std::string out = dir.file("village.glb");
  const CliRun r = cli(dir, "export " + quote(kVillage) + " --out " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, out + "\n");
  const tinygltf::Model m = loadGlb(out);
  EXPECT_EQ(nodeNames(m), (std::set<std::string>{"Hall", "Tower", "Terrace", "Barn", "Green"}));
  std::set<std::string> materials;
  for (const auto& mat : m.materials) materials.insert(mat.name);
  EXPECT_EQ(materials, (std::set<std::string>{"stone", "brick", "plaster", "timber", "grass"}));

  const CliRun one =
      cli(dir, "export " + quote(kVillage) + " --out " + quote(dir.file("tower.glb")) + " --object Tower");
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(nodeNames(loadGlb(dir.file("tower.glb"))), std::set<std::string>{"Tower"});

  const CliRun unknown =
      cli(dir, "export " + quote(kVillage) + " --out " + quote(dir.file("x.glb")) + " --object Castle");
  EXPECT_EQ(unknown.code, 1);
  EXPECT_NE(unknown.err.find("no object named \"Castle\""), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("\"Tower\""), std::string::npos) << unknown.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.glb")));
}

TEST(Cli, ExportSkipsHiddenObjects) {
  TempDir dir;
  corbel::Document doc = corbel::loadProject(kVillage).document;
  ASSERT_NE(doc.findByName("Barn"), nullptr);
  for (auto& o : doc.objects)
    if (o.name == "Barn" || o.name == "Green") o.visible = false;
  const std::string path = dir.file("hidden.corbel");
  corbel::saveProject(doc, path);
  const CliRun r = cli(dir, "export " + quote(path) + " --out " + quote(dir.file("v.glb")));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nodeNames(loadGlb(dir.file("v.glb"))), (std::set<std::string>{"Hall", "Tower", "Terrace"}));
}

TEST(Cli, ExportWritesEveryFormat) {
  TempDir dir;
  for (const char* name : {"v.obj", "v.ply", "v.off"}) {
    const CliRun r = cli(dir, "export " + quote(kVillage) + " --out " + quote(dir.file(name)));
    EXPECT_EQ(r.code, 0) << name << ": " << r.err;
    EXPECT_GT(std::filesystem::file_size(dir.file(name)), 0u) << name;
  }
  EXPECT_TRUE(std::filesystem::exists(dir.file("v.mtl")));
}

TEST(Cli, RenderWritesAPng) {
  TempDir dir;
  const std::string out = dir.file("village.png");
  const CliRun r = cli(dir, "render " + quote(kVillage) + " --out " + quote(out) + " --size 64x48");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string png = readText(out);
  ASSERT_GE(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

// render --textures: off is the default (the same bytes), on draws the textures (the old town's
// walls, roofs and ground change colour pixel by pixel, not only at edges).
TEST(Cli, RenderTexturesAreOptIn) {
  TempDir dir;
  const std::string town = quote(corbel::test::sourcePath("assets/examples/town-oldtown.corbel"));
  for (const char* mode : {"", " --textures off", " --textures on"}) {
    const std::string name = std::string("t") + (mode[0] ? mode + 12 : "default") + ".png";
    const CliRun r = cli(dir, "render " + town + " --out " + quote(dir.file(name)) + " --size 320x240" + mode);
    ASSERT_EQ(r.code, 0) << mode << ": " << r.err;
  }
  EXPECT_EQ(readText(dir.file("tdefault.png")), readText(dir.file("toff.png")));
  const corbel::render::Image off = corbel::render::readPng(dir.file("toff.png"));
  const corbel::render::Image on = corbel::render::readPng(dir.file("ton.png"));
  ASSERT_EQ(off.rgba.size(), on.rgba.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < off.rgba.size(); i += 4)
    differ += std::abs(int(off.rgba[i]) - int(on.rgba[i])) + std::abs(int(off.rgba[i + 1]) - int(on.rgba[i + 1])) > 6;
  EXPECT_GT(differ, off.rgba.size() / 4 / 10) << "pixels that changed: " << differ;
  const CliRun bad = cli(dir, "render " + town + " --out " + quote(dir.file("bad.png")) + " --textures yes");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--textures: expected on or off, not 'yes'"), std::string::npos) << bad.err;
}

// statics PROJECT --render / --landscape: the editor's statics pictures, headless.
const std::string kMasonryArch = corbel::test::sourcePath("assets/examples/masonry-arch.corbel");

struct Pixels {
  std::size_t count = 0;
  double meanY = 0;  // 0 at the top row
};

// The pixels of an image that a predicate picks, and where they lie.
template <class Pick>
Pixels pixels(const corbel::render::Image& image, Pick pick) {
  Pixels p;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* c = image.at(x, y);
      if (!pick(int(c[0]), int(c[1]), int(c[2]))) continue;
      ++p.count;
      p.meanY += y;
    }
  if (p.count) p.meanY /= double(p.count);
  return p;
}

// Tension blue (arrows and the blocks that carry the most tension), far from the pale sky.
bool tensionBlue(int r, int g, int b) { return b >= 190 && b - r >= 120 && b - g >= 60; }
// Ground reactions green.
bool reactionGreen(int r, int g, int b) { return g >= 110 && g - r >= 50 && g - b >= 40; }
// Compression red.
bool compressionRed(int r, int g, int b) { return r >= 150 && r - g >= 60 && r - b >= 60; }

TEST(Cli, StaticsRenderShowsTensionBlueOnlyWhereTheArchNeedsIt) {
  TempDir dir;
  // As set, the example's arch is too thin for its columns: it needs tension (glue).
  const std::string thin = dir.file("thin.png");
  CliRun r = cli(dir, "statics " + quote(kMasonryArch) + " --render " + quote(thin) + " --size 320x240 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["stands"].get<bool>());
  EXPECT_EQ(j["render"], thin);
  const corbel::render::Image a = corbel::render::readPng(thin);
  EXPECT_EQ(a.width, 320);
  EXPECT_EQ(a.height, 240);
  const Pixels blue = pixels(a, tensionBlue), green = pixels(a, reactionGreen), red = pixels(a, compressionRed);
  EXPECT_GT(blue.count, 200u);
  EXPECT_GT(green.count, 20u);
  EXPECT_GT(red.count, 50u);
  // The reactions stand on the ground, below the arch and its tension.
  EXPECT_GT(green.meanY, 0.55 * a.height);
  EXPECT_LT(blue.meanY, green.meanY);
  EXPECT_LT(red.meanY, green.meanY);

  // Made to stand first (--optimize), it needs none: no blue, the reactions still there.
  const std::string stands = dir.file("stands.png");
  r = cli(dir, "statics " + quote(kMasonryArch) + " --optimize --render " + quote(stands) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["stands"].get<bool>());
  const corbel::render::Image b = corbel::render::readPng(stands);
  EXPECT_EQ(b.width, 1200);  // the default size
  EXPECT_EQ(b.height, 800);
  EXPECT_EQ(pixels(b, tensionBlue).count, 0u);
  EXPECT_GT(pixels(b, reactionGreen).count, 50u);
  EXPECT_GT(pixels(b, compressionRed).count, 100u);
  // A thick arch on wide columns set by hand stands too, and shows no blue.
  const std::string set = dir.file("set.png");
  r = cli(dir, "statics " + quote(kMasonryArch) + " --set thickness=0.25 --set columnWidth=0.9 --render " + quote(set) +
                   " --size 160x120");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("render: " + set), std::string::npos) << r.out;
  EXPECT_EQ(pixels(corbel::render::readPng(set), tensionBlue).count, 0u);
}

TEST(Cli, StaticsLandscapeMarksWhereTheArchStands) {
  TempDir dir;
  const std::string png = dir.file("landscape.png");
  const CliRun r = cli(dir, "statics " + quote(kMasonryArch) + " --landscape thickness columnWidth " + quote(png) +
                                " --samples 9 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json l = nlohmann::json::parse(r.out)["landscape"];
  EXPECT_EQ(l["x"]["parameter"], "thickness");
  EXPECT_EQ(l["y"]["parameter"], "columnWidth");
  // The project's free bounds.
  EXPECT_EQ(l["x"]["lo"].get<double>(), 0.05);
  EXPECT_EQ(l["x"]["hi"].get<double>(), 0.5);
  EXPECT_EQ(l["y"]["lo"].get<double>(), 0.1);
  EXPECT_EQ(l["y"]["hi"].get<double>(), 1.5);
  const std::size_t standing = l["standing"];
  EXPECT_GT(standing, 0u);
  EXPECT_LT(standing, 81u);
  EXPECT_LE(l["minimum"]["measure"].get<double>(), 1e-10);
  const corbel::render::Image image = corbel::render::readPng(png);
  EXPECT_EQ(image.width, image.height);
  EXPECT_EQ(image.width % 9, 0);
  const int cell = image.width / 9;
  // Standing samples are red and none other is: the count of red cells is the count standing.
  std::size_t redCells = 0;
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 9; ++i) {
      const std::uint8_t* c = image.at(i * cell + cell / 2, (8 - j) * cell + cell / 2);
      redCells += c[0] > 200 && c[1] < 60 && c[2] < 60;
    }
  EXPECT_EQ(redCells, standing);
  // Thick arch on wide columns (top right) stands; the thinnest arch (left column) never does.
  const std::uint8_t* topRight = image.at(image.width - 1, 0);
  EXPECT_TRUE(topRight[0] > 200 && topRight[1] < 60) << int(topRight[0]) << " " << int(topRight[1]);
  for (int j = 0; j < 9; ++j) {
    const std::uint8_t* c = image.at(cell / 2, j * cell + cell / 2);
    EXPECT_FALSE(c[0] > 200 && c[1] < 60) << "row " << j;
  }
}

// With --optimize the search's path over the landscape (Fig. 8): from the project's values to
// the result, drawn in white.
TEST(Cli, StaticsLandscapeDrawsTheSearchPath) {
  TempDir dir;
  const std::string png = dir.file("path.png");
  const CliRun r = cli(dir, "statics " + quote(kMasonryArch) + " --optimize --landscape thickness columnWidth " +
                                quote(png) + " --samples 9 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& path = j["landscape"]["path"];
  ASSERT_GE(path.size(), 2u) << r.out;
  EXPECT_EQ(path[0][0].get<double>(), 0.12);  // thickness as saved
  EXPECT_EQ(path[0][1].get<double>(), 0.3);   // columnWidth as saved
  EXPECT_NEAR(path.back()[0].get<double>(), j["parameters"]["thickness"].get<double>(), 1e-12);
  EXPECT_NEAR(path.back()[1].get<double>(), j["parameters"]["columnWidth"].get<double>(), 1e-12);
  const corbel::render::Image image = corbel::render::readPng(png);
  EXPECT_GT(pixels(image, [](int r, int g, int b) { return r == 255 && g == 255 && b == 255; }).count, 20u);
}

TEST(Cli, StaticsPicturesRefuseBadArgumentsAndWriteNothing) {
  TempDir dir;
  const std::string arch = quote(kMasonryArch), png = quote(dir.file("a.png"));
  for (const std::string& args : {
           "statics " + arch + " --render " + png + " --size 0x10",
           "statics " + arch + " --render " + png + " --size 10",
           "statics " + arch + " --render " + png + " --size 640x",
           "statics " + arch + " --render " + png + " --size 12.5x40",
           "statics " + arch + " --render " + png + " --size 99999x100",
           "statics " + arch + " --render " + quote(dir.file("a.jpg")),
           "statics " + arch + " --render",
           "statics " + arch + " --size 64x64",
           "statics " + arch + " --landscape thickness " + png,
           "statics " + arch + " --landscape thickness columnWidth " + quote(dir.file("a.txt")),
           "statics " + arch + " --samples 9",
           "statics " + arch + " --landscape thickness columnWidth " + png + " --samples 1",
           "statics " + arch + " --landscape thickness columnWidth " + png + " --samples 2.5",
           "statics arch --blocks 10 --thickness 0.2 --render " + png,
       }) {
    const CliRun r = cli(dir, args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("corbel-cli: ", 0), 0u) << args << "\n" << r.err;
  }
  // Bad input: exit 1 with the reason.
  const CliRun missing = cli(dir, "statics " + quote(dir.file("nothing.corbel")) + " --render " + png);
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("no such file"), std::string::npos) << missing.err;
  // Checked before any work: the render is not written either.
  const CliRun unknown =
      cli(dir, "statics " + arch + " --render " + quote(dir.file("b.png")) + " --landscape radius columnWidth " + png);
  EXPECT_EQ(unknown.code, 1);
  EXPECT_NE(unknown.err.find("radius"), std::string::npos) << unknown.err;
  const CliRun twice = cli(dir, "statics " + arch + " --landscape thickness thickness " + png);
  EXPECT_EQ(twice.code, 1);
  const CliRun count = cli(dir, "statics " + arch + " --landscape voussoirs thickness " + png);
  EXPECT_EQ(count.code, 1);
  EXPECT_NE(count.err.find("count"), std::string::npos) << count.err;
  EXPECT_TRUE(dir.entries().empty());
  // A folder that does not exist: the atomic write fails naming the path, and leaves nothing.
  const std::string nowhere = dir.file("no/such/folder/a.png");
  const CliRun folder = cli(dir, "statics " + arch + " --render " + quote(nowhere));
  EXPECT_EQ(folder.code, 1);
  EXPECT_NE(folder.err.find(nowhere), std::string::npos) << folder.err;
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace

namespace {

std::vector<nlohmann::json> jsonLines(const std::string& text) {
  std::istringstream lines(text);
  std::vector<nlohmann::json> rows;
  for (std::string line; std::getline(lines, line);) rows.push_back(nlohmann::json::parse(line));
  return rows;
}

}  // namespace

// extrude --stats: one line per building with its measures and mesh anchors, then a summary.
TEST(Cli, ExtrudeStatsReportTheShellAndItsAnchors) {
  TempDir dir;
  const CliRun r = cli(dir, "extrude " + quote(corbel::test::sourcePath("assets/examples/house.corbel")) + " --stats");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = jsonLines(r.out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["id"], "House");
  EXPECT_EQ(rows[0]["watertight"], true);
  EXPECT_EQ(rows[0]["manifold"], true);
  // The door, 4 + 4 windows in two grids, one over the bay, 2 roof windows, 2 chimney pots.
  ASSERT_EQ(rows[0]["anchors"].size(), 14u);
  EXPECT_EQ(rows[0]["anchors"][2]["name"], "gable windows (2 of 4)");
  EXPECT_EQ(rows[0]["anchors"][2]["position"], nlohmann::json::array({12.0, 6.4, 0.9}));
  const auto& door = rows[0]["anchors"][0];
  EXPECT_EQ(door["name"], "front door");
  EXPECT_EQ(door["instanced"], true);
  // Halfway along the right wall (12, 0) → (12, 8), on the ground, facing +x.
  EXPECT_EQ(door["position"], nlohmann::json::array({12.0, 4.0, 0.0}));
  EXPECT_EQ(door["normal"], nlohmann::json::array({1.0, 0.0, 0.0}));
  EXPECT_EQ(rows[1]["summary"], true);
  EXPECT_EQ(rows[1]["failed"], 0);
}

// A bad building in a GeoJSON batch is reported with its reason; the rest are built and the
// exit code says that one failed.
TEST(Cli, ExtrudeBatchKeepsGoingPastABadFootprint) {
  TempDir dir;
  const std::string geo = dir.file("two.geojson");
  writeText(geo, R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"id": "square"}, "geometry": {"type": "Polygon",
      "coordinates": [[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]]}},
    {"type": "Feature", "properties": {"id": "bowtie"}, "geometry": {"type": "Polygon",
      "coordinates": [[[20, 0], [30, 0], [30, 10], [25, -5], [20, 10], [20, 0]]]}}]})");
  const CliRun r = cli(dir, "extrude " + quote(geo) + " --stats --pitch 45");
  EXPECT_EQ(r.code, 1) << r.err;
  const auto rows = jsonLines(r.out);
  ASSERT_EQ(rows.size(), 3u);
  int failed = 0;
  for (int i = 0; i < 2; ++i) {
    if (rows[i].contains("error")) {
      ++failed;
      EXPECT_NE(rows[i]["error"].get<std::string>().find("intersect"), std::string::npos) << rows[i];
    } else {
      EXPECT_NEAR(rows[i]["volume"].get<double>(), 100.0 * 5 / 3, 1e-9);  // a square pyramid
    }
  }
  EXPECT_EQ(failed, 1);
  EXPECT_EQ(rows[2]["failed"], 1);
}
