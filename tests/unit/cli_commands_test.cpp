// corbel-cli's declared command line (cli/commands.h): every subcommand the declarations hold
// answers --help and --version, refuses an unknown option and a missing value by name with exit
// 2; repeatable options take one value each time and values may be negative numbers.
#include "cli/commands.h"
#include "cli_run.h"
#include "core/project_io.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace {

using corbel::cli::Requests;
using corbel::test::cli;
using corbel::test::CliRun;
using corbel::test::TempDir;

// "render", "statics", "statics arch", ...: every subcommand, depth first.
std::vector<std::string> commandPaths(const CLI::App& app, const std::string& prefix = "") {
  std::vector<std::string> out;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    const std::string path = prefix.empty() ? sub->get_name() : prefix + " " + sub->get_name();
    out.push_back(path);
    for (const std::string& deeper : commandPaths(*sub, path)) out.push_back(deeper);
  }
  return out;
}

// The declared subcommand at `path`.
const CLI::App& commandAt(const CLI::App& app, const std::string& path) {
  const CLI::App* at = &app;
  std::istringstream words(path);
  for (std::string w; words >> w;) at = at->get_subcommand(w);
  return *at;
}

struct Declared {
  CLI::App app;
  Requests requests;
  Declared() { corbel::cli::declareCommands(app, requests); }
  // Parses `args` (after the program's name) and returns the chosen subcommand's request.
  template <class R>
  const R& parse(std::vector<std::string> args) {
    std::vector<const char*> argv{"corbel-cli"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    app.parse(int(argv.size()), argv.data());
    const corbel::cli::Request* r = requests.chosen(app);
    EXPECT_NE(r, nullptr);
    return std::get<R>(*r);
  }
};

TEST(CliCommands, EverySubcommandIsDeclared) {
  Declared d;
  const std::vector<std::string> paths = commandPaths(d.app);
  for (const char* expected : {"render", "export", "check", "extrude", "statics", "statics arch", "statics example",
                               "simulate", "kifs", "grow", "complete", "city"})
    EXPECT_NE(std::find(paths.begin(), paths.end(), expected), paths.end()) << expected;
}

// Every subcommand's --help names each of its options and positionals; --version prints the
// program's version with the project format's.
TEST(CliCommands, EverySubcommandHasHelpAndVersion) {
  TempDir dir;
  Declared d;
  const std::string version = "corbel-cli 0.1.0 (project format " + std::to_string(corbel::kProjectVersion) + ")\n";
  for (const std::string& path : commandPaths(d.app)) {
    SCOPED_TRACE(path);
    const CliRun help = cli(dir, path + " --help");
    EXPECT_EQ(help.code, 0) << help.err;
    EXPECT_EQ(help.err, "");
    for (const CLI::Option* o : commandAt(d.app, path).get_options())
      EXPECT_NE(help.out.find(o->get_name()), std::string::npos) << o->get_name() << "\n" << help.out;
    const CliRun v = cli(dir, path + " --version");
    EXPECT_EQ(v.code, 0) << v.err;
    EXPECT_EQ(v.out, version);
  }
  const CliRun top = cli(dir, "--version");
  EXPECT_EQ(top.code, 0);
  EXPECT_EQ(top.out, version);
  const CliRun help = cli(dir, "--help");
  for (const CLI::App* sub : d.app.get_subcommands([](const CLI::App*) { return true; }))
    EXPECT_NE(help.out.find(sub->get_name()), std::string::npos) << sub->get_name();
}

// An unknown option is named (before any required option that is missing), and so is an option
// given without its value; both exit 2 and print nothing on stdout.
TEST(CliCommands, UnknownOptionsAndMissingValuesExitTwoByName) {
  TempDir dir;
  Declared d;
  for (const std::string& path : commandPaths(d.app)) {
    SCOPED_TRACE(path);
    const CliRun unknown = cli(dir, path + " --frobnicate");
    EXPECT_EQ(unknown.code, 2);
    EXPECT_EQ(unknown.err.rfind("corbel-cli: " + path + ": unknown option --frobnicate\n", 0), 0u) << unknown.err;
    EXPECT_NE(unknown.err.find("corbel-cli " + path + " --help"), std::string::npos) << unknown.err;
    EXPECT_EQ(unknown.out, "");
    for (const CLI::Option* o : commandAt(d.app, path).get_options()) {
      if (o->get_positional() || o->get_expected_min() == 0) continue;  // flags take no value
      const CliRun missing = cli(dir, path + " " + o->get_name());
      EXPECT_EQ(missing.code, 2) << o->get_name();
      EXPECT_EQ(missing.err.rfind("corbel-cli: " + path + ": " + o->get_name(), 0), 0u) << missing.err;
    }
  }
  const CliRun command = cli(dir, "frobnicate x");
  EXPECT_EQ(command.code, 2);
  EXPECT_NE(command.err.find("unknown command 'frobnicate'"), std::string::npos) << command.err;
}

TEST(CliCommands, RepeatedOptionsTakeOneValueEachTime) {
  {
    Declared d;
    const auto& r = d.parse<corbel::cli::StaticsProjectRequest>(
        {"statics", "--set", "thickness=0.3", "a.corbel", "--set", "columnWidth=0.8", "--free", "x=0:1", "--optimize"});
    EXPECT_EQ(r.project, "a.corbel");
    EXPECT_EQ(r.model.sets, (std::vector<std::string>{"thickness=0.3", "columnWidth=0.8"}));
    EXPECT_EQ(r.model.frees, std::vector<std::string>{"x=0:1"});
  }
  {
    Declared d;
    const auto& r = d.parse<corbel::cli::SimulateRequest>(
        {"simulate", "--remove", "a", "--break", "b", "p.corbel", "--remove", "c"});
    EXPECT_EQ(r.project, "p.corbel");
    EXPECT_EQ(r.removes, (std::vector<std::string>{"a", "c"}));
    EXPECT_EQ(r.breaks, std::vector<std::string>{"b"});
  }
  {
    Declared d;
    const auto& r = d.parse<corbel::cli::StaticsProjectRequest>(
        {"statics", "--scene", "--structural", "column", "p.corbel", "--structural", "statue"});
    EXPECT_EQ(r.project, "p.corbel");
    EXPECT_EQ(r.structural, (std::vector<std::string>{"column", "statue"}));
  }
  // --landscape takes exactly three values, then a positional again.
  {
    Declared d;
    const auto& r = d.parse<corbel::cli::StaticsProjectRequest>({"statics", "--landscape", "a", "b", "l.png", "p.corbel"});
    EXPECT_EQ(r.model.landscape, (std::vector<std::string>{"a", "b", "l.png"}));
    EXPECT_EQ(r.project, "p.corbel");
  }
  // Any other option given twice keeps its last value, as before CLI11.
  {
    Declared d;
    const auto& r = d.parse<corbel::cli::RenderRequest>({"render", "p.corbel", "--out", "a.png", "--out", "b.png"});
    EXPECT_EQ(r.out, "b.png");
  }
}

TEST(CliCommands, ValuesMayBeNegativeNumbers) {
  {
    Declared d;
    const auto& r = d.parse<corbel::cli::StaticsArchRequest>({"statics", "arch", "--blocks", "10", "--tilt", "-10"});
    EXPECT_EQ(r.tilt, -10.0);
    EXPECT_EQ(r.blocks, 10);
  }
  {
    Declared d;
    const auto& r =
        d.parse<corbel::cli::RenderRequest>({"render", "p.corbel", "--out", "a.png", "--camera", "-60,30"});
    EXPECT_EQ(r.camera, "-60,30");
  }
  {
    Declared d;
    const auto& r = d.parse<corbel::cli::SimulateRequest>({"simulate", "--example", "tower", "--shake", "-0.5"});
    EXPECT_EQ(r.shake, "-0.5");
  }
}

// Options of one statics form are not taken by another: example has no --scene.
TEST(CliCommands, StaticsFormsKeepTheirOwnOptions) {
  Declared d;
  EXPECT_THROW(d.parse<corbel::cli::StaticsExampleRequest>({"statics", "example", "tower", "--scene"}),
               CLI::ExtrasError);
  Declared e;
  const auto& r = e.parse<corbel::cli::StaticsExampleRequest>({"statics", "example", "tower", "--kern", "0.5"});
  EXPECT_EQ(r.name, "tower");
  EXPECT_EQ(r.analysis.kern, 0.5);
}

}  // namespace
