// The editor's window-free rooms: selection.h, layout.h, script_runner.h, test_log.h.
#include "editor/layout.h"
#include "editor/script_runner.h"
#include "editor/selection.h"
#include "editor/test_log.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// The panels, splitters, toolbar and view tile the window below the menu bar: no gap, no
// overlap, at any panel widths, collapsed or not, and any UI scale.
TEST(Layout, PanelsAndViewTileTheWindow) {
  std::mt19937 rng(7);
  auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
  for (int i = 0; i < 400; ++i) {
    const float w = uniform(900, 4000), h = uniform(500, 3000), menu = 20;
    PanelSizes s;
    s.left = uniform(kMinPanelWidth, 500), s.right = uniform(kMinPanelWidth, 700);
    s.leftShown = i % 3 != 0, s.rightShown = i % 5 != 0;
    s.scale = i % 2 ? 1.0f : uniform(0.75f, 2.0f);
    for (bool want : {false, true}) {
      const Layout l = layoutWindow(w, h, menu, want, s);
      const float split = kSplitterWidth * s.scale;
      const float left = std::min(s.leftShown ? s.left * s.scale : 0.0f, w - split - kMinViewWidth * s.scale);
      EXPECT_EQ(l.rightPaneShown,
                want && s.rightShown && w > left + s.right * s.scale + (2 * kSplitterWidth + kMinViewWidth) * s.scale);
      EXPECT_FLOAT_EQ(l.leftPanel.w, left);
      EXPECT_FLOAT_EQ(l.leftSplitter.x, l.leftPanel.x + l.leftPanel.w);
      EXPECT_FLOAT_EQ(l.view.x, l.leftSplitter.x + split);
      const float right = l.rightPaneShown ? l.rightPane.w + l.rightSplitter.w : l.rightSplitter.w;
      EXPECT_FLOAT_EQ(l.leftPanel.w + split + l.view.w + right, w);
      if (l.rightPaneShown) {
        EXPECT_FLOAT_EQ(l.rightSplitter.x, l.view.x + l.view.w);
        EXPECT_FLOAT_EQ(l.rightPane.x, l.rightSplitter.x + l.rightSplitter.w);
      }
      // A collapsed right pane that is wanted keeps its splitter at the window's edge.
      EXPECT_EQ(l.rightSplitter.w > 0, want && (l.rightPaneShown || !s.rightShown));
      EXPECT_FLOAT_EQ(l.toolbar.x, l.view.x);
      EXPECT_FLOAT_EQ(l.toolbar.w, l.view.w);
      EXPECT_FLOAT_EQ(l.toolbar.y, menu);
      EXPECT_FLOAT_EQ(l.view.y, l.toolbar.y + l.toolbar.h);
      EXPECT_FLOAT_EQ(menu + l.toolbar.h + l.view.h + l.statusBar.h, h);
      EXPECT_FLOAT_EQ(l.statusBar.y, l.view.y + l.view.h);
      EXPECT_GE(l.view.w, l.rightPaneShown ? kMinViewWidth * s.scale : 1.0f);
    }
  }
  // 320 + 6 + 460 + 6 + 200 = 992 px at scale 1.
  EXPECT_FALSE(layoutWindow(990, 700, 20, true).rightPaneShown);
  EXPECT_TRUE(layoutWindow(994, 700, 20, true).rightPaneShown);
}

TEST(Layout, ASplitterDragResizesWithinLimits) {
  PanelSizes s;  // 320 left, 460 right, scale 1, in a 1280 px window
  EXPECT_FLOAT_EQ(draggedWidth(320, 100, true, 1280, s), 420);
  EXPECT_FLOAT_EQ(draggedWidth(460, 100, false, 1280, s), 360);  // the right splitter moved right
  EXPECT_FLOAT_EQ(draggedWidth(320, -300, true, 1280, s), kMinPanelWidth);
  // At most what leaves 200 px of view: 1280 − (460 + 6) − (6 + 6 + 200) = 602.
  EXPECT_FLOAT_EQ(draggedWidth(320, 900, true, 1280, s), 602);
  s.scale = 2;  // pixels are halved into scale-1 widths
  EXPECT_FLOAT_EQ(draggedWidth(200, 100, true, 4000, s), 250);
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
