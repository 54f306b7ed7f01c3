#pragma once
// The papers' symbols that panel controls show as their labels ("r.x", "a1", "LO", "y/W²"),
// each with what it is in words, for the control's tooltip: an artist who has not read the
// paper still knows what a slider does. One table for every panel. No GL.
#include <string_view>

namespace corbel::editor {

// The words for a control labelled `label`, or nullptr when the label is words already.
const char* symbolWords(std::string_view label);

// Shows symbolWords(label) as the tooltip of the last ImGui item when it is hovered (in the
// editor's panels; defined with them, since this header stays free of ImGui).
void explainSymbol(std::string_view label);

}  // namespace corbel::editor
