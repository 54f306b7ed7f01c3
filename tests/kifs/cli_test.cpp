// corbel-cli kifs: --eval prints the CPU distance function (for checking it from outside), a
// render writes a PNG of the requested size, and bad command lines are refused by exit code.
#include "core/project_io.h"
#include "kifs/distance.h"
#include "kifs/kernel.h"
#include "render/image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace corbel::kifs::test {
namespace {

namespace fs = std::filesystem;

struct CliRun {
  int code;
  std::string out;
};

CliRun cli(const std::string& args) {
  // One file per process: ctest may run these tests side by side.
  const fs::path out = fs::temp_directory_path() / ("corbel_kifs_cli_" + std::to_string(getpid()) + ".txt");
  const int status = std::system((std::string(CORBEL_CLI) + " " + args + " > " + out.string() + " 2>&1").c_str());
  std::ifstream in(out);
  std::stringstream ss;
  ss << in.rdbuf();
  return {WEXITSTATUS(status), ss.str()};
}

TEST(KifsCli, EvalPrintsTheCpuDistance) {
  const fs::path points = fs::temp_directory_path() / ("corbel_kifs_points_" + std::to_string(getpid()) + ".txt");
  std::vector<glm::dvec3> ps;
  std::mt19937_64 rng(8);
  const Building b(preset("h"));
  {
    std::ofstream f(points);
    f << "# x y z\n";
    for (int i = 0; i < 50; ++i) {
      ps.push_back(uniformIn(rng, b.worldBounds().lo, b.worldBounds().hi));
      f.precision(17);
      f << ps.back().x << " " << ps.back().y << " " << ps.back().z << "\n";
    }
  }
  const CliRun r = cli("kifs --preset h --eval " + points.string());
  ASSERT_EQ(r.code, 0) << r.out;
  std::istringstream in(r.out);
  for (const auto& p : ps) {
    double bound = 0, surface = 0;
    ASSERT_TRUE(in >> bound >> surface);
    const Sample s = b.evaluate(p);
    EXPECT_DOUBLE_EQ(bound, s.bound);
    EXPECT_DOUBLE_EQ(surface, s.surface);
  }
}

TEST(KifsCli, RendersAPngOfTheRequestedSize) {
  const fs::path png = fs::temp_directory_path() / ("corbel_kifs_cli_" + std::to_string(getpid()) + ".png");
  const CliRun r = cli("kifs --preset menger --size 40x30 --mode floors --out " + png.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const render::Image img = render::readPng(png.string());
  EXPECT_EQ(img.width, 40);
  EXPECT_EQ(img.height, 30);
}

TEST(KifsCli, MeshesAClosedManifoldToAFile) {
  const fs::path ply = fs::temp_directory_path() / ("corbel_kifs_cli_" + std::to_string(getpid()) + ".ply");
  const CliRun r = cli("kifs --preset t --resolution 24 --mesh " + ply.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("\"closed_manifold\": true"), std::string::npos) << r.out;
  EXPECT_GT(fs::file_size(ply), 1000u);
  EXPECT_EQ(cli("kifs --mesh x.stl").code, 1);                  // unknown format
  EXPECT_EQ(cli("kifs --mesh x.ply --resolution 0").code, 2);   // bad resolution
}

// The first argument may name a preset or a project: a project's KIFS object evaluates as its
// parameters do (the H example holds the h preset's values), and a project with none is refused.
TEST(KifsCli, TakesAPresetOrAProjectAsItsFirstArgument) {
  const fs::path points = fs::temp_directory_path() / ("corbel_kifs_points2_" + std::to_string(getpid()) + ".txt");
  {
    std::ofstream f(points);
    f << "3 -11 7\n-12.5 4 1\n0 0 14\n";
  }
  const CliRun byPreset = cli("kifs --preset h --eval " + points.string());
  const CliRun positional = cli("kifs h --eval " + points.string());
  const CliRun project = cli(std::string("kifs '") + CORBEL_SOURCE_DIR + "/assets/examples/kifs-h.corbel' --eval " + points.string());
  ASSERT_EQ(byPreset.code, 0) << byPreset.out;
  EXPECT_EQ(positional.out, byPreset.out);
  ASSERT_EQ(project.code, 0) << project.out;
  EXPECT_EQ(project.out, byPreset.out);
  const CliRun none = cli(std::string("kifs '") + CORBEL_SOURCE_DIR + "/assets/examples/house.corbel' --out x.png");
  EXPECT_EQ(none.code, 1);
  EXPECT_NE(none.out.find("no KIFS object"), std::string::npos) << none.out;
  EXPECT_EQ(cli("kifs h --preset box --out x.png").code, 2);  // both
}

// A preset file's path evaluates as the preset's name does; a missing or malformed file exits 1
// naming its path.
TEST(KifsCli, TakesAPresetFilesPath) {
  const fs::path points = fs::temp_directory_path() / ("corbel_kifs_points3_" + std::to_string(getpid()) + ".txt");
  const fs::path bad = fs::temp_directory_path() / ("corbel_kifs_bad_" + std::to_string(getpid()) + ".json");
  {
    std::ofstream(points) << "1 2 5\n5.5 -5.5 20\n2.9 5.9 13\n";  // the last two near the facades
    std::ofstream(bad) << "{\"scale\": ";
  }
  const CliRun byName = cli("kifs turned --eval " + points.string());
  const CliRun byPath = cli(std::string("kifs '") + CORBEL_SOURCE_DIR + "/assets/kifs/turned.json' --eval " + points.string());
  ASSERT_EQ(byName.code, 0) << byName.out;
  ASSERT_EQ(byPath.code, 0) << byPath.out;
  EXPECT_EQ(byPath.out, byName.out);
  EXPECT_NE(byName.out, cli("kifs box --eval " + points.string()).out);  // the preset matters
  const CliRun missing = cli("kifs /nonexistent/turned.json --eval " + points.string());
  EXPECT_EQ(missing.code, 1);
  EXPECT_EQ(missing.out, "corbel-cli: error: /nonexistent/turned.json: no such file\n");
  const CliRun malformed = cli("kifs " + bad.string() + " --eval " + points.string());
  EXPECT_EQ(malformed.code, 1);
  EXPECT_EQ(malformed.out.rfind("corbel-cli: error: " + bad.string() + ": ", 0), 0u) << malformed.out;
}

TEST(KifsCli, BadCommandLinesAreRefused) {
  EXPECT_EQ(cli("kifs").code, 2);                                  // no --out
  EXPECT_EQ(cli("kifs --out x.png --mode glossy").code, 2);        // unknown mode
  EXPECT_EQ(cli("kifs --out x.png --size 0x10").code, 2);          // bad size
  EXPECT_EQ(cli("kifs --out x.png --frobnicate 1").code, 2);       // unknown option
  const CliRun unknown = cli("kifs --out x.png --preset gothic");     // unknown preset: bad input
  EXPECT_EQ(unknown.code, 1);
  EXPECT_NE(unknown.out.find("box"), std::string::npos) << unknown.out;
}

// A project whose KIFS object follows a box of the `box` preset's size: --eval builds the
// project's Scene, bakes the box and prints the follower's values, which lie within one cell
// diagonal below the preset's own (docs/kifs.md); and it renders.
TEST(KifsCli, AProjectsFollowerIsEvaluatedOnItsMass) {
  Document d;
  BoxSpec box;
  box.size = Vec3(12.0, 12.0, 22.8);
  d.add("Mass", box);
  KifsSpec k = specOf(preset("box"), "box");
  k.mass.footprint = "object";
  k.mass.object = "Mass";
  k.mass.resolution = 32;
  d.add("Ornament", k);
  const std::string tag = std::to_string(getpid());
  const fs::path project = fs::temp_directory_path() / ("corbel_kifs_follow_" + tag + ".corbel");
  saveProject(d, project.string());
  const fs::path points = fs::temp_directory_path() / ("corbel_kifs_follow_points_" + tag + ".txt");
  std::vector<glm::dvec3> ps;
  std::mt19937_64 rng(4);
  {
    std::ofstream f(points);
    f.precision(17);
    for (int i = 0; i < 200; ++i) {
      // 6 m above the follower's inset bottom, where its inner shell is the preset's
      // (KifsFollow.OnTheBoxItIsTheBoxPresetWithinOneCell).
      ps.push_back(uniformIn(rng, {-8, -8, 1.2 + 6.0}, {8, 8, 25}));
      f << ps.back().x << " " << ps.back().y << " " << ps.back().z << "\n";
    }
  }
  const CliRun r = cli("kifs " + project.string() + " --eval " + points.string());
  ASSERT_EQ(r.code, 0) << r.out;
  std::istringstream in(r.out);
  const Building ref(preset("box"));
  const double diagonal = std::sqrt(3.0) * 22.8 / 32, ulp = std::ldexp(40.0, -23);
  for (const auto& p : ps) {
    double bound = 0, surface = 0;
    ASSERT_TRUE(in >> bound >> surface);
    const Sample s = ref.evaluate(p);
    EXPECT_LE(bound, s.bound + ulp);
    EXPECT_GE(bound, s.bound - diagonal - ulp);
    EXPECT_LE(surface, s.surface + ulp);
    EXPECT_GE(surface, s.surface - diagonal - ulp);
  }
  const fs::path png = fs::temp_directory_path() / ("corbel_kifs_follow_" + tag + ".png");
  const CliRun drawn = cli("kifs " + project.string() + " --out " + png.string() + " --size 64x48");
  EXPECT_EQ(drawn.code, 0) << drawn.out;
  EXPECT_EQ(render::readPng(png.string()).width, 64);
  // A follower of a missing object: the render names it and fails.
  k.mass.object = "Nobody";
  d.objects.back().spec = k;
  saveProject(d, project.string());
  const CliRun missing = cli("render " + project.string() + " --out " + png.string());
  EXPECT_EQ(missing.code, 1) << missing.out;
  EXPECT_NE(missing.out.find("kifs.mass.object: no object named \"Nobody\""), std::string::npos) << missing.out;
}

}  // namespace
}  // namespace corbel::kifs::test
