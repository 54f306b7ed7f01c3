#pragma once
// The number an artist types while a drag runs (3.5 Enter, as SketchUp and Blender take it):
// digits and one decimal point, '-' turning the sign either side of them. Shared by the
// transform (G, R, the gizmo) and Push/Pull.
#include <optional>
#include <string>

namespace corbel::editor {

class TypedValue {
 public:
  // Takes a typed character; false if it is not one of '0'-'9', '.', '-' (a second point is
  // taken and ignored).
  bool type(char c);
  void backspace();
  void clear() { text_.clear(); }
  const std::string& text() const { return text_; }
  // The number typed so far; none while there is none yet ("", "-", ".", "-.").
  std::optional<double> value() const;

 private:
  std::string text_;
};

}  // namespace corbel::editor
