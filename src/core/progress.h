#pragma once
// Progress and cancellation for long work. Kernels take a Progress* (may be null), report a
// fraction and a stage, and stop early when cancelled() turns true. A BackgroundJob runs such
// work off the UI thread so the window never freezes.
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace corbel {

class Progress {
 public:
  virtual ~Progress() = default;
  void report(double fraction, std::string_view stage);
  bool cancelled() const { return cancel_.load(std::memory_order_relaxed); }
  void cancel() { cancel_.store(true, std::memory_order_relaxed); }
  double fraction() const { return fraction_.load(std::memory_order_acquire); }
  std::string stage() const;

 private:
  std::atomic<bool> cancel_{false};
  std::atomic<double> fraction_{0.0};
  mutable std::mutex mutex_;
  std::string stage_;
};

// Thrown by kernels that honour cancellation mid-way.
struct Cancelled : std::exception {
  const char* what() const noexcept override { return "cancelled"; }
};

class BackgroundJob {
 public:
  using Work = std::function<void(Progress&)>;
  BackgroundJob(std::string title, Work work);
  ~BackgroundJob();  // cancels and joins
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  const std::string& title() const { return title_; }
  Progress& progress() { return progress_; }
  bool finished() const { return finished_.load(std::memory_order_acquire); }
  // After finished(): rethrows the work's exception, if any.
  void rethrow() const;
  void wait();

 private:
  std::string title_;
  Progress progress_;
  std::atomic<bool> finished_{false};
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace corbel
