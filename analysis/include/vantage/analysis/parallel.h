#pragma once

/// Deterministic data parallelism on std::thread. The index range [0, n) is cut into contiguous
/// blocks, one per thread; every index is handled exactly once, so results written by index do
/// not depend on the number of threads.

#include <algorithm>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace vantage {

/// Threads to use: `requested` when positive, else std::thread::hardware_concurrency() (at least
/// 1); never more than `work_items` (and at least 1).
inline int thread_count(int requested, long work_items) {
  int threads = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(threads, 1);
  return static_cast<int>(std::max<long>(1, std::min<long>(threads, work_items)));
}

/// Calls body(begin, end) on disjoint contiguous blocks that cover [0, n), on
/// thread_count(threads, n) threads (the calling thread takes the first block, and any block
/// whose thread cannot be started). The first exception a block throws is rethrown here after
/// every thread has joined.
template <typename Body>
void parallel_blocks(long n, int threads, Body&& body) {
  if (n <= 0) return;
  const int count = thread_count(threads, n);
  std::vector<std::exception_ptr> errors(count);
  auto run = [&](int k) {
    const long begin = n * k / count;
    const long end = n * (k + 1) / count;
    try {
      body(begin, end);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(count - 1);
  std::vector<int> here = {0};  // blocks run on the calling thread
  for (int k = 1; k < count; ++k) {
    try {
      workers.emplace_back(run, k);
    } catch (const std::system_error&) {
      here.push_back(k);  // no thread available (a limit, a sandbox): same result, later
    }
  }
  for (int k : here) run(k);
  for (std::thread& worker : workers) worker.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace vantage
