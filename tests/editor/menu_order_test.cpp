// The menu bar's order (editor/menu_order.h).
#include "editor/menu_order.h"

#include <gtest/gtest.h>

namespace corbel::editor {
namespace {

std::vector<Action> naming(const std::vector<std::string>& menus) {
  std::vector<Action> r;
  int n = 0;
  for (const std::string& m : menus) {
    Action a;
    a.id = "a" + std::to_string(n++);
    a.menu = m;
    a.label = "x";
    a.run = [] {};
    r.push_back(std::move(a));
  }
  return r;
}

// Where a program registers its commands must not decide where its menus stand: File comes
// first and Help last in every desktop program an artist knows (Blender, SketchUp, CityEngine),
// with Edit, View, Select and Object after File; the others keep the order they were named in.
TEST(MenuOrder, TheMenuBarStartsWithFileAndEndsWithHelpWhateverRegisteredFirst) {
  const std::vector<Action> r =
      naming({"View", "Select", "Help", "Statics", "Object/Add", "File", "", "Town", "Edit", "Object", "Tools"});
  const std::vector<std::string> expected = {"File", "Edit", "View", "Select", "Object", "Statics", "Town", "Tools", "Help"};
  EXPECT_EQ(menuBarOrder(r), expected);
}

TEST(MenuOrder, MenusNoActionNamesAreLeftOut) {
  const std::vector<Action> r = naming({"Growth", "", "Edit"});
  const std::vector<std::string> expected = {"Edit", "Growth"};
  EXPECT_EQ(menuBarOrder(r), expected);
}

}  // namespace
}  // namespace corbel::editor
