// corbel-cli statics arch: the numbers it prints and its refusals.
#include <gtest/gtest.h>

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

}  // namespace
