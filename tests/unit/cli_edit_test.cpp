// corbel-cli edit: the editor's edit scripts without a window. The oracles are the editor's own
// outcome for the Fig. 4 script (one closed shell, tests/editor/editor_test.sh), the writer's
// bytes for a re-save, and the file system for "nothing written".
#include "cli_run.h"
#include "core/project_io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace {

using corbel::test::cli;
using corbel::test::quote;
using corbel::test::readText;
using corbel::test::sourcePath;
using corbel::test::TempDir;
using corbel::test::writeText;

const char* const kEmpty = R"({"format": "corbel", "version": 1, "name": "untitled", "objects": []})";

TEST(CliEdit, TheFigureFourScriptBuildsTheHouseAsTheEditorDoes) {
  TempDir dir;
  writeText(dir.file("empty.corbel"), kEmpty);
  const auto r = cli(dir, "edit " + quote(dir.file("empty.corbel")) + " --script " +
                              quote(sourcePath("assets/scripts/fig4-house.jsonl")) + " --out " +
                              quote(dir.file("house.corbel")));
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  EXPECT_GT(summary["edits"].get<int>(), 5);
  EXPECT_EQ(summary["objects"], 1);
  const auto check = cli(dir, "check " + quote(dir.file("house.corbel")));
  EXPECT_EQ(check.code, 0) << check.out << check.err;
  EXPECT_NE(check.out.find(R"({"objects":1,"failed":0})"), std::string::npos) << check.out;
}

// With nothing to apply, edit is a re-save: the file the writer makes of the project, its paths
// relative to where it is saved (this is how the examples are re-saved when the format changes).
TEST(CliEdit, AnEmptyScriptResavesEachExampleByTheWriter) {
  TempDir dir;
  writeText(dir.file("none.jsonl"), "\n");
  for (const std::string& example : corbel::test::exampleProjects()) {
    SCOPED_TRACE(example);
    const std::string out = dir.file("out.corbel");
    const auto r = cli(dir, "edit " + quote(example) + " --script " + quote(dir.file("none.jsonl")) + " --out " + quote(out));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(readText(out), corbel::serializeProject(corbel::loadProject(example).document, dir.path()));
  }
}

TEST(CliEdit, ABadLineIsRefusedWithItsNumberAndNothingIsWritten) {
  TempDir dir;
  writeText(dir.file("empty.corbel"), kEmpty);
  const std::string good =
      R"({"op": "new_extrusion", "name": "A", "profile": "hip", "points": [[0, 0], [10, 0], [10, 6], [0, 6]]})";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {good + "\n\n{\"op\": \"move_corner\", \"object\": \"A\"", "script.jsonl:3: not valid JSON"},
      {good + "\n{\"op\": \"delete_corner\", \"object\": \"A\", \"loop\": 0, \"corner\": 9}",
       "script.jsonl:2: corner: no corner 9"},
      {good + "\n{\"op\": \"fly\", \"object\": \"A\"}", "script.jsonl:2: "},
      {"{\"op\": \"insert_corner\", \"object\": \"B\", \"loop\": 0, \"edge\": 0, \"at\": [1, 0]}",
       "script.jsonl:1: object: no object called \"B\""},
  };
  for (const auto& [script, expected] : bad) {
    SCOPED_TRACE(script);
    writeText(dir.file("script.jsonl"), script);
    const auto r = cli(dir, "edit " + quote(dir.file("empty.corbel")) + " --script " + quote(dir.file("script.jsonl")) +
                                " --out " + quote(dir.file("out.corbel")));
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.corbel")));
  }
  // A bad command line is exit 2, as for every command.
  EXPECT_EQ(cli(dir, "edit " + quote(dir.file("empty.corbel")) + " --script x.jsonl").code, 2);
  EXPECT_EQ(cli(dir, "edit " + quote(dir.file("empty.corbel")) + " --script x.jsonl --out a.obj").code, 2);
  EXPECT_EQ(cli(dir, "edit " + quote(dir.file("empty.corbel")) + " --script " + quote(dir.file("none.jsonl")) +
                         " --out " + quote(dir.file("out.corbel")))
                .code,
            1);  // a missing script is bad input
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.corbel")));
}

// A corner deleted between two walls takes the other wall's feature with it: the edit says so.
TEST(CliEdit, WhatAnEditRemovesIsNamed) {
  TempDir dir;
  writeText(dir.file("empty.corbel"), kEmpty);
  writeText(dir.file("script.jsonl"),
            R"({"op": "new_extrusion", "name": "A", "profile": "hip", "points": [[0, 0], [12, 0], [12, 8], [0, 8]]})"
            "\n"
            R"({"op": "add_feature", "object": "A", "name": "side door", "feature": "door", "anchor": {"loop": 0, "edge": 1, "fraction": 0.5, "height": 0}})"
            "\n"
            R"({"op": "delete_corner", "object": "A", "loop": 0, "corner": 1})"
            "\n");
  const auto r = cli(dir, "edit " + quote(dir.file("empty.corbel")) + " --script " + quote(dir.file("script.jsonl")) +
                              " --out " + quote(dir.file("out.corbel")));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("script.jsonl:3: removed feature \"side door\""), std::string::npos) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  ASSERT_EQ(summary["removed"].size(), 1u);
  const corbel::Document d = corbel::loadProject(dir.file("out.corbel")).document;
  EXPECT_TRUE(std::get<corbel::ExtrusionSpec>(d.objects[0].spec).anchors.empty());
}

}  // namespace
