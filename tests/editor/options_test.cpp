// The editor's command line (editor/options.h): every option keeps its name and meaning, bad
// values are refused by CLI11 naming the option.
#include "editor/options.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace corbel::editor {
namespace {

// The options `args` (after the program's name) give; throws CLI::ParseError on a bad line.
EditorOptions parsed(std::vector<std::string> args) {
  EditorOptions o;
  CLI::App app;
  declareEditorOptions(app, o);
  std::vector<const char*> argv{"corbel"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  app.parse(int(argv.size()), argv.data());
  return o;
}

TEST(EditorOptions, EveryOptionKeepsItsMeaning) {
  const EditorOptions o = parsed({"--size", "800x600", "--screenshot", "s.png", "--quit-after-frames", "8",
                                  "--actions", "object.add_box,,edit.undo", "--script", "a.jsonl", "--script-shots",
                                  "shots", "--autosave-seconds", "0", "--recover", "yes", "--state-dir", "state",
                                  "--select", "Arch on columns", "house.corbel"});
  EXPECT_EQ(o.window.width, 800);
  EXPECT_EQ(o.window.height, 600);
  EXPECT_EQ(o.screenshot, "s.png");
  EXPECT_EQ(o.quitAfterFrames, 8);
  EXPECT_EQ(o.actions, (std::vector<std::string>{"object.add_box", "edit.undo"}));
  EXPECT_EQ(o.script, "a.jsonl");
  EXPECT_EQ(o.scriptShots, "shots");
  EXPECT_EQ(o.autosaveSeconds, 0.0);
  EXPECT_EQ(o.recover, EditorOptions::Recover::Yes);
  EXPECT_EQ(o.stateDir, "state");
  EXPECT_EQ(o.select, "Arch on columns");
  EXPECT_EQ(o.project, "house.corbel");
}

TEST(EditorOptions, DefaultsWithoutArguments) {
  const EditorOptions o = parsed({});
  EXPECT_EQ(o.window.width, 1440);
  EXPECT_EQ(o.window.height, 900);
  EXPECT_EQ(o.quitAfterFrames, -1);
  EXPECT_EQ(o.recover, EditorOptions::Recover::Ask);
  EXPECT_EQ(o.autosaveSeconds, 60.0);
  EXPECT_EQ(o.project, "");
}

TEST(EditorOptions, BadValuesAreRefusedByName) {
  for (const auto& args : std::vector<std::vector<std::string>>{{"--size", "100x100"},
                                                                {"--size", "800"},
                                                                {"--size", "9000x600"},
                                                                {"--quit-after-frames", "0"},
                                                                {"--recover", "maybe"},
                                                                {"--autosave-seconds", "soon"}}) {
    try {
      parsed(args);
      ADD_FAILURE() << args[0] << " " << args[1] << " was accepted";
    } catch (const CLI::ValidationError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(args[0] + ": ", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(parsed({"a.corbel", "b.corbel"}), CLI::ExtrasError);  // one project at a time
  EXPECT_THROW(parsed({"--bogus"}), CLI::ExtrasError);
  EXPECT_THROW(parsed({"--screenshot"}), CLI::ArgumentMismatch);
}

}  // namespace
}  // namespace corbel::editor
