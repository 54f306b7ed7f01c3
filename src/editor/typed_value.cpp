#include "editor/typed_value.h"

#include <cstdlib>

namespace corbel::editor {

bool TypedValue::type(char c) {
  if (!((c >= '0' && c <= '9') || c == '.' || c == '-')) return false;
  if (c == '-') {
    text_ = !text_.empty() && text_[0] == '-' ? text_.substr(1) : "-" + text_;
    return true;
  }
  if (c == '.' && text_.find('.') != std::string::npos) return true;
  text_ += c;
  return true;
}

void TypedValue::backspace() {
  if (!text_.empty()) text_.pop_back();
}

std::optional<double> TypedValue::value() const {
  if (text_.find_first_of("0123456789") == std::string::npos) return std::nullopt;
  return std::strtod(text_.c_str(), nullptr);
}

}  // namespace corbel::editor
