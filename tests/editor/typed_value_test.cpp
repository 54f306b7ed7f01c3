// The value typed during a drag (editor/typed_value.h), against what the keys spell.
#include "editor/typed_value.h"

#include <gtest/gtest.h>

#include <string>

namespace corbel::editor {
namespace {

TypedValue typed(const std::string& keys) {
  TypedValue v;
  for (char c : keys) v.type(c);
  return v;
}

TEST(TypedValue, ReadsWhatTheKeysSpell) {
  EXPECT_EQ(typed("3.5").value(), 3.5);
  EXPECT_EQ(typed("-2").value(), -2.0);
  EXPECT_EQ(typed("2-").value(), -2.0);   // '-' turns the sign wherever it is typed
  EXPECT_EQ(typed("2--").value(), 2.0);   // and back
  EXPECT_EQ(typed("1.2.5").value(), 1.25);  // a second point is ignored
  EXPECT_EQ(typed(".5").value(), 0.5);
}

// Nothing is typed until a digit is: a lone sign or point must not move anything to 0.
TEST(TypedValue, NoNumberBeforeADigit) {
  for (const char* keys : {"", "-", ".", "-."}) EXPECT_FALSE(typed(keys).value().has_value()) << keys;
}

TEST(TypedValue, OtherKeysAreNotTakenAndBackspaceUndoesOne) {
  TypedValue v = typed("12");
  EXPECT_FALSE(v.type('x'));
  EXPECT_FALSE(v.type(' '));
  v.backspace();
  EXPECT_EQ(v.value(), 1.0);
  v.backspace();
  v.backspace();  // on nothing: stays empty
  EXPECT_EQ(v.text(), "");
}

}  // namespace
}  // namespace corbel::editor
