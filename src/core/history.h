#pragma once
// Undo/redo on the Document by snapshots. A Document is a small value (specs, not geometry),
// so a snapshot per edit is cheap and makes every command undoable without inverse code.
#include "core/document.h"

#include <cstdint>
#include <string>
#include <vector>

namespace corbel {

class History {
 public:
  explicit History(Document initial = {}, std::size_t capacity = 512);

  const Document& current() const { return states_[index_].doc; }
  // Records `next` as a new state. Consecutive commits with the same non-empty `mergeKey`
  // (one slider drag, one typed name) collapse into one undo step.
  void commit(Document next, std::string label, std::string mergeKey = {});
  // Ends the current merge run: the next commit starts a new undo step.
  void closeMerge() { mergeKey_.clear(); }

  bool canUndo() const { return index_ > 0; }
  bool canRedo() const { return index_ + 1 < states_.size(); }
  bool undo();
  bool redo();
  const std::string& undoLabel() const;  // label of the step undo would revert
  const std::string& redoLabel() const;

  // Replaces the whole history (New, Open): a fresh start that is clean.
  void reset(Document doc);
  // Saving marks the current state clean; the history is kept.
  void markSaved() { savedId_ = states_[index_].id; }
  bool dirty() const { return states_[index_].id != savedId_; }
  // Unique id of the current state; changes whenever current() changes.
  std::uint64_t stateId() const { return states_[index_].id; }
  std::size_t size() const { return states_.size(); }

 private:
  struct State {
    Document doc;
    std::string label;
    std::uint64_t id;
  };
  std::vector<State> states_;
  std::size_t index_ = 0;
  std::size_t capacity_;
  std::uint64_t nextId_ = 1;
  std::uint64_t savedId_ = 0;
  std::string mergeKey_;
};

}  // namespace corbel
