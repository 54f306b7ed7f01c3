#pragma once
// Loops of the statics kernel shared between the calling thread and one helper thread, for the
// large models (thousands of blocks) where starting a thread (tens of microseconds) is repaid.
// Each f(j) must write only its own j's data; the results are then the one-thread results bit
// for bit. Small loops, and `threads` = 1 (IpmOptions::threads), stay on the calling thread.
#include <thread>

namespace corbel::statics {

inline constexpr int kParallelLoop = 20000;  // iterations of a loop worth a second thread

inline bool twoThreads(int n, int threads, int least = kParallelLoop) {
  return n >= least && threads != 1 && (threads >= 2 || std::thread::hardware_concurrency() >= 2);
}

// f(j) for j in [0, n): the halves on two threads where twoThreads(n, threads, least).
template <typename F>
void forEachIndex(int n, int threads, F f, int least = kParallelLoop) {
  if (!twoThreads(n, threads, least)) {
    for (int j = 0; j < n; ++j) f(j);
    return;
  }
  std::thread helper([&] {
    for (int j = n / 2; j < n; ++j) f(j);
  });
  for (int j = 0; j < n / 2; ++j) f(j);
  helper.join();
}

}  // namespace corbel::statics
