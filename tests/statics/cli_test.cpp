// corbel-cli statics arch: the numbers it prints and its refusals.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct CliRun {
  int code = -1;
  std::string out;
};

CliRun cli(const std::string& args) {
  const std::string command = std::string("'") + CORBEL_CLI + "' statics " + args + " 2>/dev/null";
  CliRun r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buf[256];
  while (std::fgets(buf, sizeof buf, pipe)) r.out += buf;
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

TEST(StaticsCli, PrintsTheMinimumThicknessTheCriticalTiltAndTheMeasure) {
  CliRun r = cli("arch --blocks 100 --min-thickness");
  ASSERT_EQ(r.code, 0);
  EXPECT_NEAR(std::stod(r.out), 0.1075, 2e-4);
  r = cli("arch --blocks 100 --thickness 0.2 --critical-tilt");
  ASSERT_EQ(r.code, 0);
  EXPECT_NEAR(std::stod(r.out), 15.84, 0.05);
  r = cli("arch --blocks 100 --thickness 0.1");
  ASSERT_EQ(r.code, 0);
  EXPECT_NEAR(std::stod(r.out), 1.0966e-3, 0.001e-3);
  r = cli("arch --blocks 100 --thickness 0.2 --tilt 10");
  ASSERT_EQ(r.code, 0);
  EXPECT_EQ(std::stod(r.out), 0.0);
}

TEST(StaticsCli, RefusesBadCommandLines) {
  EXPECT_EQ(cli("arch --blocks 0 --thickness 0.2").code, 2);
  EXPECT_EQ(cli("arch --blocks 10 --thickness nan").code, 2);
  EXPECT_EQ(cli("arch --blocks 10").code, 2);
  EXPECT_EQ(cli("arch --blocks 10 --thickness 0.2 --min-thickness --critical-tilt").code, 2);
  EXPECT_EQ(cli("dome --blocks 10 --thickness 0.2").code, 2);
  // A sliding-prone arch (no friction) that does not stand untilted: the bisection says so.
  EXPECT_EQ(cli("arch --blocks 10 --thickness 0.2 --friction 0 --critical-tilt").code, 1);
}

// The examples through the CLI: the search ends standing, and the strict LP test agrees.
TEST(StaticsCli, ExampleSearchPrintsAFeasibleResultAsJson) {
  const CliRun r = cli("example arch-on-columns --optimize --free thickness=0.05:0.5 --free columnWidth=0.05:1.5 --json");
  ASSERT_EQ(r.code, 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "feasible");
  EXPECT_TRUE(j["stands_strictly"].get<bool>());
  EXPECT_GT(j["initial_measure"].get<double>(), 1e-4);
  EXPECT_LE(j["measure"].get<double>(), 1e-10);
  EXPECT_GE(j["iterations"].get<int>(), 1);
  EXPECT_GE(j["parameters"]["thickness"].get<double>(), 0.05);
  EXPECT_LE(j["parameters"]["columnWidth"].get<double>(), 1.5);
  EXPECT_EQ(j["blocks"].get<int>(), 11);
  // Without --optimize: the measure at the defaults, which do not stand.
  const CliRun plain = cli("example arch-on-columns --json");
  ASSERT_EQ(plain.code, 0);
  const nlohmann::json pj = nlohmann::json::parse(plain.out);
  EXPECT_FALSE(pj["stands"].get<bool>());
  EXPECT_GT(pj["tension_sites"].get<int>(), 0);
}

TEST(StaticsCli, ExampleRefusesBadNamesAndBounds) {
  EXPECT_EQ(cli("example cathedral").code, 1);
  EXPECT_EQ(cli("example").code, 2);
  EXPECT_EQ(cli("example tower --free x1=-0.1:0.1").code, 2);  // --free without --optimize
  EXPECT_EQ(cli("example tower --optimize --free z1=-0.1:0.1").code, 1);
  EXPECT_EQ(cli("example tower --optimize --free x1=0.1:-0.1").code, 1);
  EXPECT_EQ(cli("example tower --optimize --free x1=nan:0.1").code, 1);
  EXPECT_EQ(cli("example tower --set x1=0.9").code, 1);  // outside its valid range
  EXPECT_EQ(cli("example tower --set x1").code, 2);
  EXPECT_EQ(cli("example tower --friction-sides 6").code, 2);
}

}  // namespace

namespace {

// statics PROJECT: the masonry object of the example project, with its own parameters and free
// bounds. As set it does not stand (its 0.12 m arch is under the arch's own limit); the search
// over its two free parameters makes it stand within their bounds.
TEST(StaticsCli, AProjectsMasonryObjectIsAnalysedAndMadeToStand) {
  const std::string project = std::string("'") + CORBEL_SOURCE_DIR + "/assets/examples/masonry-arch.corbel'";
  CliRun r = cli(project + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["object"], "Arch on columns");
  EXPECT_FALSE(j["stands"].get<bool>());
  EXPECT_GT(j["measure"].get<double>(), 1e-6);
  r = cli(project + " --optimize --json");
  ASSERT_EQ(r.code, 0) << r.out;
  j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["stands"].get<bool>()) << r.out;
  const double thickness = j["parameters"]["thickness"], width = j["parameters"]["columnWidth"];
  EXPECT_GE(thickness, 0.05);
  EXPECT_LE(thickness, 0.5);
  EXPECT_GE(width, 0.1);
  EXPECT_LE(width, 1.5);
  EXPECT_EQ(cli(project + " --object 'No such'").code, 1);
}

}  // namespace
