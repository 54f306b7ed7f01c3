// The editor's window-free rooms: selection.h, layout.h, script_runner.h, test_log.h.
#include "editor/layout.h"
#include "editor/script_runner.h"
#include "editor/selection.h"
#include "editor/test_log.h"

#include "core/error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <random>

namespace corbel::editor {
namespace {

TEST(Selection, ActiveIsTheLastAddedAndPruneDropsDeletedObjects) {
  Document d;
  const ObjectId a = d.add("A", BoxSpec{}), b = d.add("B", BoxSpec{}), c = d.add("C", BoxSpec{});
  Selection s;
  EXPECT_FALSE(s.active());
  s.select(a);
  s.add(b);
  s.add(c);
  EXPECT_EQ(s.active(), c);
  EXPECT_EQ(s.ids(), (std::vector<ObjectId>{a, b, c}));
  s.toggle(c);
  EXPECT_EQ(s.active(), b);
  s.hover = b;
  d.remove(b);
  s.prune(d);
  EXPECT_EQ(s.ids(), std::vector<ObjectId>{a});
  EXPECT_EQ(s.active(), a);
  EXPECT_FALSE(s.hover);
  s.select(c);
  EXPECT_EQ(s.ids(), std::vector<ObjectId>{c});
  s.clear();
  EXPECT_TRUE(s.empty());
  EXPECT_FALSE(s.active());
}

// The panels and the view tile the window below the menu bar: no gap, no overlap.
TEST(Layout, PanelsAndViewTileTheWindow) {
  std::mt19937 rng(7);
  for (int i = 0; i < 200; ++i) {
    const float w = std::uniform_real_distribution<float>(900, 4000)(rng),
                h = std::uniform_real_distribution<float>(500, 3000)(rng), menu = 20;
    for (bool want : {false, true}) {
      const Layout l = layoutWindow(w, h, menu, want);
      EXPECT_EQ(l.rightPaneShown, want && w > kLeftPanelWidth + kRightPaneWidth + kMinViewWidth);
      const float right = l.rightPaneShown ? l.rightPane.w : 0;
      EXPECT_FLOAT_EQ(l.leftPanel.w + l.view.w + right, w);
      EXPECT_FLOAT_EQ(l.view.x, l.leftPanel.x + l.leftPanel.w);
      if (l.rightPaneShown) {
        EXPECT_FLOAT_EQ(l.rightPane.x, l.view.x + l.view.w);
      }
      EXPECT_FLOAT_EQ(l.view.y, menu);
      EXPECT_FLOAT_EQ(menu + l.view.h + l.statusBar.h, h);
      EXPECT_FLOAT_EQ(l.statusBar.y, l.view.y + l.view.h);
      EXPECT_GE(l.view.w, l.rightPaneShown ? kMinViewWidth : 1.0f);
    }
  }
  EXPECT_FALSE(layoutWindow(900, 700, 20, true).rightPaneShown);  // 320 + 460 + 200 > 900
}

struct ScriptLog {
  std::vector<std::string> triggered, edited, lines;
  int reframes = 0;
  ScriptHost host() {
    ScriptHost h;
    h.trigger = [this](const std::string& id) {
      triggered.push_back(id);
      return id != "no.such";
    };
    h.edit = [this](const nlohmann::json& op) {
      if (op.value("op", "") == "bad") throw std::runtime_error("bad edit");
      edited.push_back(op.value("stage", ""));
    };
    h.log = [this](const std::string& line, bool) { lines.push_back(line); };
    h.reframe = [this] { ++reframes; };
    return h;
  }
};

TEST(ScriptRunner, ActionsRunOnePerFrameFromTheThirdFrame) {
  ScriptOptions o;
  o.actions = {"a.one", "no.such", "a.two"};
  ScriptRunner r(o);
  ScriptLog log;
  ScriptHost host = log.host();
  EXPECT_TRUE(r.scripted());
  for (int frame = 0; frame < 6; ++frame) r.startFrame(frame, host);
  EXPECT_EQ(log.triggered, (std::vector<std::string>{"a.one", "no.such", "a.two"}));
  ASSERT_EQ(log.lines.size(), 1u);
  EXPECT_NE(log.lines[0].find("'no.such' is unknown or disabled"), std::string::npos);
  EXPECT_TRUE(r.idle());
}

TEST(ScriptRunner, AStageEndsWithAScreenshotThreeFramesOnAndABadLineFailsTheRun) {
  const auto dir = std::filesystem::temp_directory_path() / "corbel-script-runner-test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    std::ofstream s(dir / "s.jsonl");
    s << R"({"stage": "walls", "op": "x"})" << "\n\n"
      << R"({"stage": "walls", "op": "y"})" << "\n"
      << R"({"stage": "roof top", "op": "bad"})" << "\n";
  }
  ScriptOptions o;
  o.script = (dir / "s.jsonl").string();
  o.scriptShots = (dir / "shots").string();
  ScriptRunner r(o);
  ScriptLog log;
  ScriptHost host = log.host();
  int frame = 2;
  r.startFrame(frame++, host);  // walls x
  r.startFrame(frame++, host);  // the blank line
  EXPECT_FALSE(r.dueShot(frame));
  r.startFrame(frame, host);  // walls y: the stage ends
  const int ended = frame++;
  EXPECT_EQ(log.reframes, 1);
  EXPECT_FALSE(r.dueShot(ended + 2));
  ASSERT_TRUE(r.dueShot(ended + 3));
  EXPECT_EQ(*r.dueShot(ended + 3), (dir / "shots" / "01-walls.png").string());
  r.startFrame(frame++, host);  // waits for the shot
  EXPECT_EQ(log.edited.size(), 2u);
  r.shotDone(true);
  r.startFrame(frame++, host);  // the bad line
  EXPECT_TRUE(r.idle());
  EXPECT_NE(r.incomplete().find("a line failed"), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "shots"));
  std::filesystem::remove_all(dir);
}

TEST(ScriptRunner, AMissingScriptIsAProblemAndNothingRuns) {
  ScriptOptions o;
  o.script = "/no/such/script.jsonl";
  ScriptRunner r(o);
  EXPECT_NE(r.problem().find("/no/such/script.jsonl"), std::string::npos);
  EXPECT_FALSE(r.scripted());  // as before the split: no lines, nothing to wait for
}

TEST(TestLog, ALineForEachChangeOfState) {
  const auto path = std::filesystem::temp_directory_path() / "corbel-test-log-test.jsonl";
  {
    TestLog log(path.string());
    SettledFrame s;
    s.frame = 3;
    s.selection = {"Hall", "Barn"};
    s.active = "Barn";
    s.camera.target = Vec3(1, 2, 3);
    s.lastAction = "edit.undo";
    s.actionsRun = 4;
    s.objects = 2;
    log.write(s);
    s.frame = 4;
    log.write(s);  // the same state: no line
    s.actionsRun = 5;
    s.frame = 5;
    log.write(s);
  }
  std::ifstream in(path);
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0]["frame"], 3);
  EXPECT_EQ(lines[0]["selection"], nlohmann::json::parse(R"(["Hall", "Barn"])"));
  EXPECT_EQ(lines[0]["active"], "Barn");
  EXPECT_EQ(lines[0]["camera"]["target"], nlohmann::json::parse("[1.0, 2.0, 3.0]"));
  EXPECT_EQ(lines[0]["last_action"], "edit.undo");
  EXPECT_EQ(lines[1]["frame"], 5);
  EXPECT_EQ(lines[1]["actions_run"], 5);
  std::filesystem::remove(path);
  EXPECT_THROW(TestLog("/no/such/folder/log.jsonl"), Error);
}

}  // namespace
}  // namespace corbel::editor
