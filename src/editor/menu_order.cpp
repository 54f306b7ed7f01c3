#include "editor/menu_order.h"

#include <algorithm>
#include <array>

namespace corbel::editor {

std::vector<std::string> menuBarOrder(const std::vector<Action>& actions) {
  std::vector<std::string> named;
  auto has = [](const std::vector<std::string>& v, const std::string& m) {
    return std::find(v.begin(), v.end(), m) != v.end();
  };
  for (const Action& a : actions) {
    const std::string top = a.menu.substr(0, a.menu.find('/'));
    if (!top.empty() && !has(named, top)) named.push_back(top);
  }
  static const std::array<const char*, 5> first = {"File", "Edit", "View", "Select", "Object"};
  std::vector<std::string> out;
  for (const char* m : first)
    if (has(named, m)) out.push_back(m);
  for (const std::string& m : named)
    if (m != "Help" && !has(out, m)) out.push_back(m);
  if (has(named, "Help")) out.push_back("Help");
  return out;
}

}  // namespace corbel::editor
