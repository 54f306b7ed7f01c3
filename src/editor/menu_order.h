#pragma once
// The menu bar's order: where a menu stands does not depend on which room registered its
// commands first.
#include "editor/actions.h"

#include <string>
#include <vector>

namespace corbel::editor {

// The top-level menus `actions` name (the part of Action::menu before any '/'): File, Edit,
// View, Select and Object first, where desktop programs put them; then the others in the order
// they are first named; Help last. Menus no action names are left out.
std::vector<std::string> menuBarOrder(const std::vector<Action>& actions);

}  // namespace corbel::editor
