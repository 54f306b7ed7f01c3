#pragma once
// The user's settings that outlive a session (`settings.json` in the editor's state folder,
// beside the recent files): the side panels' widths and whether they are shown, and the UI
// scale when the user chose one (none: the monitor's content scale). A missing file gives the
// defaults; a damaged one too, with a message naming it. Saves are atomic. No GL.
#include "editor/layout.h"

#include <optional>
#include <string>

namespace corbel::editor {

inline constexpr float kMinUiScale = 0.5f, kMaxUiScale = 3.0f;

struct UserSettings {
  PanelSizes panels;               // panels.scale is not saved: it is uiScale or the monitor's
  std::optional<float> uiScale;    // the user's choice, kMinUiScale..kMaxUiScale
  bool operator==(const UserSettings&) const = default;
};

// Reads `path`; `problem` (when given) gets a sentence naming the file and what is wrong with
// it, or is cleared. Out-of-range numbers are clamped.
UserSettings loadUserSettings(const std::string& path, std::string* problem = nullptr);
// Writes `path` atomically (its folder is made); throws corbel::Error naming it on failure.
void saveUserSettings(const UserSettings& settings, const std::string& path);

}  // namespace corbel::editor
