#pragma once
// The command search (F3): the action registry's commands filtered and ranked by what the user
// types, as Blender's menu search and VS Code's command palette do. Pure: tests give it entries.
#include <cstddef>
#include <string>
#include <vector>

namespace corbel::editor {

struct CommandEntry {
  std::string id;     // "view.top"
  std::string path;   // where it is in the menus: "View", "Object > Add"
  std::string label;  // "Top"
  std::string help;   // its one sentence
};

// The entries every word of `query` occurs in (case-insensitive; in the label, path, help or
// id), best first: a word that begins the label counts most, then one that begins a word of the
// label, then one inside the label, then one in the path, then one only in the help or id; ties
// keep the registry's order. An empty query matches every entry in order.
std::vector<std::size_t> searchCommands(const std::vector<CommandEntry>& entries, const std::string& query);

}  // namespace corbel::editor
