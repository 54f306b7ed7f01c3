#include "editor/test_log.h"

#include "core/error.h"

#include <nlohmann/json.hpp>

namespace corbel::editor {

namespace {

nlohmann::ordered_json stateOf(const SettledFrame& s) {
  nlohmann::ordered_json j;
  j["selection"] = s.selection;
  j["active"] = s.active.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.active);
  j["hover"] = s.hover.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.hover);
  const render::OrbitCamera& c = s.camera;
  j["camera"] = {{"target", {c.target[0], c.target[1], c.target[2]}},
                 {"azimuth", c.azimuth_deg},
                 {"elevation", c.elevation_deg},
                 {"distance", c.distance},
                 {"orthographic", c.orthographic}};
  j["last_action"] = s.lastAction;
  j["actions_run"] = s.actionsRun;
  j["objects"] = s.objects;
  j["dirty"] = s.dirty;
  j["undo"] = s.undo;
  if (!s.planCorners.empty()) j["plan_corners"] = s.planCorners;
  if (!s.profilePoints.empty()) j["profile_points"] = s.profilePoints;
  if (!s.profile.empty()) j["profile"] = s.profile;
  if (!s.planEdges.empty()) j["plan_edges"] = s.planEdges;
  j["view"] = s.view;
  if (!s.failed.empty()) j["failed"] = s.failed;
  if (s.activeInView) j["active_in_view"] = *s.activeInView;
  if (s.search) j["search"] = *s.search;
  if (s.tape)
    j["tape"] = {{"from", s.tape->from}, {"to", s.tape->to}, {"from_snap", s.tape->fromSnap},
                 {"to_snap", s.tape->toSnap}, {"length", s.tape->length}};
  if (!s.widgets.empty()) j["widgets"] = s.widgets;
  return j;
}

}  // namespace

std::string testLogLine(const SettledFrame& s) {
  nlohmann::ordered_json j;
  j["frame"] = s.frame;
  const nlohmann::ordered_json state = stateOf(s);
  for (const auto& [key, value] : state.items()) j[key] = value;
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

TestLog::TestLog(const std::string& path) : out_(path, std::ios::trunc) {
  if (!out_) throw Error("--test-log: cannot write " + path);
}

void TestLog::write(const SettledFrame& s) {
  const std::string state = stateOf(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (state == last_) return;
  last_ = state;
  out_ << testLogLine(s) << "\n" << std::flush;
}

}  // namespace corbel::editor
