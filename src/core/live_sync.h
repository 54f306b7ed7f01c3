#pragma once
// Keeps a Scene in step with an edited Document without freezing the UI: the editor calls
// update() once a frame. A changed document is built off the UI thread; when the build ends
// within a small wait (the usual case: an extrusion takes well under a millisecond) its result
// shows in the same frame, otherwise the Scene keeps its last result while the build runs and
// the UI says so (current() is false). Builds never overlap: edits made meanwhile wait, and
// only the latest of them is built next (intermediate states are skipped), so the newest
// result always wins and nothing older replaces it. A superseded build that runs long is
// cancelled (kernels honour Progress) so the latest edit is not kept waiting.
#include "core/scene_sync.h"

#include <chrono>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>

namespace corbel {

class LiveSync {
 public:
  struct Options {
    double waitSeconds = 0.008;        // how long update() waits for a build it starts
    double cancelAfterSeconds = 0.25;  // a build older than the wanted state runs this long at most
  };
  explicit LiveSync(SceneSync& sync) : LiveSync(sync, Options{}) {}
  LiveSync(SceneSync& sync, Options options);
  ~LiveSync();  // cancels a running build and waits for it
  LiveSync(const LiveSync&) = delete;
  LiveSync& operator=(const LiveSync&) = delete;

  // Once a frame, with the document and its state id (History::stateId()). Returns true when
  // a result reached the Scene during this call.
  bool update(const Document& doc, std::uint64_t state, Scene& scene);
  // Blocks until the Scene shows `state` (file operations, scripted runs, screenshots).
  void settle(const Document& doc, std::uint64_t state, Scene& scene);

  // Stops the running build (the Scene keeps what it showed; a kernel may keep what it finished,
  // as the town kernel does); the state it was building is not built again until retry() or
  // an edit makes a newer one.
  void cancel();
  void retry() { abandoned_.reset(); }
  // Forgets that the Scene shows the latest state, so the next update() plans again and builds
  // what SceneSync::invalidate(id) marked. Call it when no build runs (building() is false): a
  // running build would be taken as showing the state.
  void refresh() { shown_.reset(); }
  bool cancelled() const { return abandoned_ && *abandoned_ == wanted_ && !running_; }
  bool current() const { return !running_ && shown_ == wanted_; }  // the Scene shows the latest state given
  bool building() const { return static_cast<bool>(running_); }
  double fraction() const;       // of the running build
  std::optional<std::uint64_t> shownState() const { return shown_; }
  std::size_t buildsStarted() const { return started_; }

 private:
  struct Running {
    std::uint64_t state = 0;
    std::shared_ptr<SceneSync::Job> job;
    std::shared_ptr<Progress> progress;
    std::future<void> done;
    std::chrono::steady_clock::time_point since;
  };
  bool start(const Document& doc, std::uint64_t state, Scene& scene);
  bool finishIfDone(Scene& scene, double waitSeconds);

  SceneSync& sync_;
  Options options_;
  std::unique_ptr<Running> running_;
  std::uint64_t wanted_ = 0;
  std::optional<std::uint64_t> shown_;  // the state the Scene shows (none before the first)
  std::size_t started_ = 0;
  std::optional<std::uint64_t> abandoned_;  // cancelled by the user
};

}  // namespace corbel
