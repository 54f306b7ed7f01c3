#include "core/live_sync.h"

#include <thread>

namespace corbel {

LiveSync::LiveSync(SceneSync& sync, Options options) : sync_(sync), options_(options) {}

LiveSync::~LiveSync() {
  if (!running_) return;
  running_->progress->cancel();
  running_->done.wait();
}

double LiveSync::fraction() const { return running_ ? running_->progress->fraction() : 1.0; }

// Plans the change from what the Scene shows to `doc` and starts building it; false when there
// is nothing to build (the Scene already shows `state`).
bool LiveSync::start(const Document& doc, std::uint64_t state, Scene& scene) {
  auto job = std::make_shared<SceneSync::Job>(sync_.plan(doc, scene));
  if (job->build.empty()) {
    sync_.apply(*job, scene);  // removals and renames are cheap: done at once
    shown_ = state;
    return false;
  }
  auto r = std::make_unique<Running>();
  r->state = state;
  r->job = job;
  r->progress = std::make_shared<Progress>();
  r->since = std::chrono::steady_clock::now();
  const SceneSync* sync = &sync_;
  std::shared_ptr<Progress> progress = r->progress;
  r->done = std::async(std::launch::async, [sync, job, progress] { sync->run(*job, progress.get()); });
  running_ = std::move(r);
  ++started_;
  return true;
}

bool LiveSync::finishIfDone(Scene& scene, double waitSeconds) {
  if (!running_) return false;
  if (running_->done.wait_for(std::chrono::duration<double>(waitSeconds)) != std::future_status::ready) return false;
  running_->done.get();
  sync_.apply(*running_->job, scene);
  const bool complete = !running_->progress->cancelled();
  if (complete) shown_ = running_->state;
  running_.reset();
  return true;
}

bool LiveSync::update(const Document& doc, std::uint64_t state, Scene& scene) {
  wanted_ = state;
  bool applied = finishIfDone(scene, 0.0);
  if (running_) {
    const double age = std::chrono::duration<double>(std::chrono::steady_clock::now() - running_->since).count();
    if (running_->state != wanted_ && age > options_.cancelAfterSeconds) running_->progress->cancel();
    return applied;
  }
  if (shown_ == wanted_ || abandoned_ == wanted_) return applied;
  if (!start(doc, state, scene)) return true;
  return finishIfDone(scene, options_.waitSeconds) || applied;
}

void LiveSync::cancel() {
  if (!running_) return;
  abandoned_ = running_->state;
  running_->progress->cancel();
}

void LiveSync::settle(const Document& doc, std::uint64_t state, Scene& scene) {
  abandoned_.reset();
  for (;;) {
    update(doc, state, scene);
    if (current()) return;
    if (running_) {
      if (running_->state != state) running_->progress->cancel();
      running_->done.wait();
    }
  }
}

}  // namespace corbel
