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
  std::string slot;          // the recovery slot it lies in
};

// Autosaved work, one slot per open document, in the state folder's recovery/: per slot the
// document (SLOT.corbel), what it belongs to (SLOT.json) and a lock (SLOT.lock) that its
// editor holds with flock(2) while it runs. The lock frees itself when the editor dies, so a
// starting editor offers exactly the work of editors that are gone, and two editors never
// write one slot.
class Recovery {
 public:
  explicit Recovery(std::string stateDir);
  ~Recovery();  // lets go of the slot (its lock file goes too when no work is left in it)
  Recovery(const Recovery&) = delete;
  Recovery& operator=(const Recovery&) = delete;

  // Takes the slot of `originalPath` ("" = a new document), letting go of the one held before
  // (whose files must have been written or discarded by then). When another running editor
  // holds that document's slot, this one takes a slot of its own and the other's process id
  // is returned: the two then autosave apart instead of over each other.
  std::optional<long> claim(const std::string& originalPath);
  // Atomic write of the document and what it belongs to, into this editor's slot (claimed
  // first for a new document if none is held). Throws corbel::Error.
  void write(const Document& doc, const std::string& originalPath);
  void discard();  // this slot's files; the slot stays held
  std::string documentPath() const;
  const std::string& slot() const { return slot_; }

  // The work of editors that are gone: every slot with a document and a free lock, newest
  // first. A slot that cannot be read is named in `problems` and left alone.
  std::vector<RecoveredWork> orphans(std::vector<std::string>* problems = nullptr) const;
  // Takes an orphan's slot over: this editor autosaves there from now on. Throws corbel::Error
  // when another editor took it first.
  void adopt(const RecoveredWork& work);
  // Removes an orphan's files (the user chose to drop that work).
  void discardOrphan(const RecoveredWork& work) const;

 private:
  std::string path(const std::string& slot, const char* ext) const;
  void release();
  std::string dir_;      // <state>/recovery
  std::string legacy_;   // <state>, where older versions kept one recovery.corbel
  std::string slot_;     // "" = none held
  int lockFd_ = -1;
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
