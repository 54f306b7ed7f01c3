#include "editor/script_runner.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace corbel::editor {

namespace {
bool blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }
}  // namespace

ScriptRunner::ScriptRunner(ScriptOptions options) : options_(std::move(options)) {
  if (options_.script.empty()) return;
  std::ifstream in(options_.script);
  if (!in) {
    problem_ = "cannot read the edit script " + options_.script;
    failed_ = true;
  }
  for (std::string line; std::getline(in, line);) lines_.push_back(line);
  if (!options_.scriptShots.empty()) std::filesystem::create_directories(options_.scriptShots);
}

bool ScriptRunner::scripted() const {
  return !lines_.empty() || !options_.actions.empty() || options_.quitAfterFrames > 0 || !options_.screenshot.empty();
}

bool ScriptRunner::idle() const {
  return nextAction_ >= options_.actions.size() && nextLine_ >= lines_.size() && shotAtFrame_ < 0;
}

void ScriptRunner::startFrame(int frame, ScriptHost& host) {
  if (frame < 2) return;  // the first frames lay the window out
  if (nextAction_ < options_.actions.size()) {
    const std::string& id = options_.actions[nextAction_++];
    if (!host.trigger(id)) host.log("script: action '" + id + "' is unknown or disabled", true);
    return;
  }
  runScriptLine(frame, host);
}

// One line of the edit script; at the end of a stage, a screenshot once the preview has caught
// up (three frames on, the view framed on the new state).
void ScriptRunner::runScriptLine(int frame, ScriptHost& host) {
  if (nextLine_ >= lines_.size() || shotAtFrame_ >= 0) return;
  const std::string& line = lines_[nextLine_++];
  if (blank(line)) return;
  try {
    const nlohmann::json op = nlohmann::json::parse(line);
    host.edit(op);
    const std::string stage = op.value("stage", "");
    std::string nextStage;
    for (std::size_t k = nextLine_; k < lines_.size(); ++k)
      if (!blank(lines_[k])) {
        nextStage = nlohmann::json::parse(lines_[k]).value("stage", "");
        break;
      }
    if (!options_.scriptShots.empty() && !stage.empty() && stage != nextStage) {
      std::string file = stage;
      std::replace(file.begin(), file.end(), ' ', '-');
      char prefix[16];
      std::snprintf(prefix, sizeof prefix, "%02d-", ++shots_);
      shotPath_ = (std::filesystem::path(options_.scriptShots) / (prefix + file + ".png")).string();
      shotAtFrame_ = frame + 3;
      if (host.reframe) host.reframe();
    }
  } catch (const std::exception& e) {
    host.log("script line " + std::to_string(nextLine_) + ": " + e.what(), true);
    failed_ = true;
  }
}

std::optional<std::string> ScriptRunner::dueShot(int frame) const {
  if (shotAtFrame_ < 0 || frame < shotAtFrame_) return std::nullopt;
  return shotPath_;
}

void ScriptRunner::shotDone(bool ok) {
  shotAtFrame_ = -1;
  if (!ok) failed_ = true;
}

std::string ScriptRunner::incomplete() const {
  if (lines_.empty() || (!failed_ && nextLine_ >= lines_.size())) return {};
  return "the edit script did not complete (" + std::to_string(nextLine_) + " of " + std::to_string(lines_.size()) +
         " lines)" + (failed_ ? " and a line failed" : "");
}

}  // namespace corbel::editor
