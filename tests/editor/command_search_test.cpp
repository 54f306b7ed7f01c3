// editor/command_search.h: which commands a typed query finds, and in what order, by hand.
#include "editor/command_search.h"

#include <gtest/gtest.h>

namespace corbel::editor {
namespace {

const std::vector<CommandEntry> kEntries = {
    {"file.save", "File", "Save", "Save the project."},
    {"view.top", "View", "Top", "Look straight down, orthographic."},
    {"view.orthographic", "View", "Orthographic", "Switch between orthographic and perspective projection."},
    {"object.add_box", "Object > Add", "Box", "Add a mass-model box."},
    {"object.add_courtyard", "Object > Add > Extrusion", "Courtyard", "A square plan with a square hole."},
    {"statics.make_stand", "Statics", "Make It Stand", "Search the free parameters for a structure that stands."},
};

TEST(CommandSearch, EveryWordMustMatchAndTheLabelCountsMost) {
  // "orth": begins the label of Orthographic (5), only in Top's help (1).
  EXPECT_EQ(searchCommands(kEntries, "orth"), (std::vector<std::size_t>{2, 1}));
  // "add box": Box has "box" beginning its label (5) and "add" in its path (2); Courtyard has
  // "add" in its path but no "box" anywhere.
  EXPECT_EQ(searchCommands(kEntries, "add box"), (std::vector<std::size_t>{3}));
  // "stand": begins a word of "Make It Stand" (4).
  EXPECT_EQ(searchCommands(kEntries, "STAND"), (std::vector<std::size_t>{5}));
  // "extrusion": in Courtyard's path only.
  EXPECT_EQ(searchCommands(kEntries, "extrusion"), (std::vector<std::size_t>{4}));
  // By id: "make_stand".
  EXPECT_EQ(searchCommands(kEntries, "make_stand"), (std::vector<std::size_t>{5}));
  EXPECT_TRUE(searchCommands(kEntries, "nothing like this").empty());
}

TEST(CommandSearch, AnEmptyQueryListsEverythingInOrder) {
  EXPECT_EQ(searchCommands(kEntries, "  "), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
}

TEST(CommandSearch, TiesKeepTheRegistryOrder) {
  // "s": Save (label start, 5) and Statics' "Make It Stand" (word start, 4); Top's help has an
  // "s" (1), as do the others'.
  const auto r = searchCommands(kEntries, "s");
  ASSERT_EQ(r.size(), 6u);
  EXPECT_EQ(r[0], 0u);  // Save
  EXPECT_EQ(r[1], 5u);  // Make It Stand
  EXPECT_EQ(r[2], 4u);  // Courtyard: "s" in its path (extrusion), 2
  // Top, Orthographic and Box have an "s" only in their help (1 each): the registry's order.
  EXPECT_EQ((std::vector<std::size_t>{r[3], r[4], r[5]}), (std::vector<std::size_t>{1, 2, 3}));
}

}  // namespace
}  // namespace corbel::editor
