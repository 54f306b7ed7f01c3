#include "editor/command_search.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace corbel::editor {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// How well one (lower-case) word matches an entry: 0 = not at all.
int wordScore(const std::string& word, const std::string& label, const std::string& path, const std::string& rest) {
  const std::size_t at = label.find(word);
  if (at == 0) return 5;
  if (at != std::string::npos) {
    for (std::size_t p = at; p != std::string::npos; p = label.find(word, p + 1))
      if (!std::isalnum(static_cast<unsigned char>(label[p - 1]))) return 4;
    return 3;
  }
  if (path.find(word) != std::string::npos) return 2;
  if (rest.find(word) != std::string::npos) return 1;
  return 0;
}

}  // namespace

std::vector<std::size_t> searchCommands(const std::vector<CommandEntry>& entries, const std::string& query) {
  std::vector<std::string> words;
  std::istringstream in(lower(query));
  for (std::string w; in >> w;) words.push_back(w);
  std::vector<std::pair<int, std::size_t>> found;  // (−score, index): sorted best first, stable by index
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const CommandEntry& e = entries[i];
    const std::string label = lower(e.label), path = lower(e.path), rest = lower(e.help + " " + e.id);
    int score = 0;
    bool all = true;
    for (const std::string& w : words) {
      const int s = wordScore(w, label, path, rest);
      if (s == 0) {
        all = false;
        break;
      }
      score += s;
    }
    if (all) found.push_back({-score, i});
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::size_t> out;
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

}  // namespace corbel::editor
