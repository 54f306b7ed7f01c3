#pragma once
// State the application keeps between runs: the autosave/recovery file and the recent-files
// list. Plain files in the user's state and config folders; no GL, so it is tested headless.
#include "core/document.h"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace corbel {

// $CORBEL_STATE_DIR, else $XDG_STATE_HOME/corbel, else ~/.local/state/corbel.
std::string defaultStateDir();

struct RecoveredWork {
  Document document;
  std::string originalPath;  // "" for a never-saved document
  std::string savedAt;       // local time, for the recovery prompt
};

class Recovery {
 public:
  explicit Recovery(std::string dir);
  // Atomic write of the document and what it belongs to. Throws corbel::Error.
  void write(const Document& doc, const std::string& originalPath);
  // The recovery file if there is a readable one; a damaged one is reported in *problem.
  std::optional<RecoveredWork> find(std::string* problem = nullptr) const;
  void discard();
  std::string documentPath() const;

 private:
  std::string dir_;
};

class RecentFiles {
 public:
  explicit RecentFiles(std::string file, std::size_t capacity = 10);
  const std::vector<std::string>& paths() const { return paths_; }
  void add(const std::string& path);  // most recent first, no duplicates; saved at once
  void remove(const std::string& path);

 private:
  void save() const;
  std::string file_;
  std::size_t capacity_;
  std::vector<std::string> paths_;
};

}  // namespace corbel
