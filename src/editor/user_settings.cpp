#include "editor/user_settings.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace corbel::editor {

namespace {

float clampedWidth(double w) { return float(std::clamp(w, double(kMinPanelWidth), 4000.0)); }

}  // namespace

UserSettings loadUserSettings(const std::string& path, std::string* problem) {
  UserSettings s;
  if (problem) problem->clear();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return s;
  try {
    const nlohmann::json j = nlohmann::json::parse(readFile(path, 1 << 20));
    if (!j.is_object()) throw std::runtime_error("expected a JSON object");
    if (j.contains("panels")) {
      const nlohmann::json& p = j.at("panels");
      const auto number = [&](const char* key, double fallback) {
        if (!p.contains(key)) return fallback;
        const double v = p.at(key).get<double>();
        if (!std::isfinite(v)) throw std::runtime_error(std::string("panels.") + key + " is not a number");
        return v;
      };
      s.panels.left = clampedWidth(number("left", s.panels.left));
      s.panels.right = clampedWidth(number("right", s.panels.right));
      s.panels.leftShown = p.value("left_shown", true);
      s.panels.rightShown = p.value("right_shown", true);
    }
    if (j.contains("ui_scale") && !j.at("ui_scale").is_null()) {
      const double v = j.at("ui_scale").get<double>();
      if (!std::isfinite(v)) throw std::runtime_error("ui_scale is not a number");
      s.uiScale = float(std::clamp(v, double(kMinUiScale), double(kMaxUiScale)));
    }
  } catch (const std::exception& e) {
    if (problem) *problem = path + ": " + e.what() + " (the default layout is used)";
    return UserSettings{};
  }
  return s;
}

void saveUserSettings(const UserSettings& s, const std::string& path) {
  nlohmann::ordered_json j;
  j["panels"] = {{"left", s.panels.left},
                 {"right", s.panels.right},
                 {"left_shown", s.panels.leftShown},
                 {"right_shown", s.panels.rightShown}};
  j["ui_scale"] = s.uiScale ? nlohmann::ordered_json(*s.uiScale) : nlohmann::ordered_json(nullptr);
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  writeFileAtomic(path, j.dump(2) + "\n");
}

}  // namespace corbel::editor
