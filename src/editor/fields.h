#pragma once
// Fields that change the document once, when they are left: Enter, Tab, or a click elsewhere
// (ImGui 1.86 reports Enter alone, so a value typed and left by a click was lost). While a
// field is being edited its draft is kept here, keyed by the field's ImGui id; each function
// returns true once, on leaving after an edit, with the value in `result`. Escape reverts.
#include <string>

namespace corbel::editor {

bool commitText(const char* label, const std::string& value, std::string& result, std::size_t maxLength);
// `count` floats (1 to 4) as one field, like ImGui::InputFloatN.
bool commitFloats(const char* label, const float* value, float* result, int count, const char* format = "%.2f");
bool commitDouble(const char* label, double value, double& result, const char* format = "%.3f");
// With + and - buttons, which commit at once.
bool commitInt(const char* label, int value, int& result, int step = 1, int fastStep = 10);

}  // namespace corbel::editor
