#include "core/progress.h"

#include <algorithm>

namespace corbel {

void Progress::report(double fraction, std::string_view stage) {
  // The stage is written first and the fraction published with release order, so whoever
  // sees the new fraction also sees its stage (the UI shows both side by side).
  {
    std::lock_guard lock(mutex_);
    if (stage_ != stage) stage_ = stage;
  }
  fraction_.store(std::clamp(fraction, 0.0, 1.0), std::memory_order_release);
}

std::string Progress::stage() const {
  std::lock_guard lock(mutex_);
  return stage_;
}

BackgroundJob::BackgroundJob(std::string title, Work work) : title_(std::move(title)) {
  thread_ = std::thread([this, w = std::move(work)] {
    try {
      w(progress_);
    } catch (...) {
      error_ = std::current_exception();
    }
    finished_.store(true, std::memory_order_release);
  });
}

BackgroundJob::~BackgroundJob() {
  progress_.cancel();
  wait();
}

void BackgroundJob::wait() {
  if (thread_.joinable()) thread_.join();
}

void BackgroundJob::rethrow() const {
  if (finished() && error_) std::rethrow_exception(error_);
}

}  // namespace corbel
