#include "editor/fields.h"

#include "editor/symbols.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <vector>

namespace corbel::editor {

namespace {

// The drafts of the fields being edited, by ImGui id; a field's draft goes when it is left.
template <class T>
std::map<ImGuiID, T>& drafts() {
  static std::map<ImGuiID, T> m;
  return m;
}

// Runs `edit` on the field's draft (made from `value` when the field is not being edited) and
// says whether the field was just left after an edit; the draft is dropped once it is left.
template <class T, class Edit>
bool withDraft(const char* label, const T& value, T& result, Edit&& edit) {
  auto& all = drafts<T>();
  const ImGuiID id = ImGui::GetID(label);
  auto it = all.find(id);
  T draft = it != all.end() ? it->second : value;
  const bool changedNow = edit(draft);
  const bool active = ImGui::IsItemActive();
  const bool left = ImGui::IsItemDeactivatedAfterEdit();
  if (active) all[id] = draft;
  else all.erase(id);
  if (left || (changedNow && !active)) {  // left after typing, or a +/- button
    result = draft;
    return !(draft == value);
  }
  return false;
}

}  // namespace

bool commitText(const char* label, const std::string& value, std::string& result, std::size_t maxLength) {
  return withDraft(label, value, result, [&](std::string& draft) {
    std::vector<char> buf(maxLength + 1, '\0');
    std::memcpy(buf.data(), draft.data(), std::min(draft.size(), maxLength));
    const bool changed = ImGui::InputText(label, buf.data(), buf.size());
    draft = buf.data();
    return changed;
  });
}

bool commitFloats(const char* label, const float* value, float* result, int count, const char* format) {
  std::array<float, 4> v{}, r{};
  std::copy(value, value + count, v.begin());
  const bool left = withDraft(label, v, r, [&](std::array<float, 4>& draft) {
    return ImGui::InputScalarN(label, ImGuiDataType_Float, draft.data(), count, nullptr, nullptr, format);
  });
  if (left) std::copy(r.begin(), r.begin() + count, result);
  return left;
}

bool commitDouble(const char* label, double value, double& result, const char* format) {
  return withDraft(label, value, result,
                   [&](double& draft) { return ImGui::InputDouble(label, &draft, 0, 0, format); });
}

bool commitInt(const char* label, int value, int& result, int step, int fastStep) {
  return withDraft(label, value, result, [&](int& draft) { return ImGui::InputInt(label, &draft, step, fastStep); });
}

// symbols.h: the tooltip of a control labelled with a paper's symbol.
void explainSymbol(std::string_view label) {
  if (const char* words = symbolWords(label); words && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", words);
}

}  // namespace corbel::editor
