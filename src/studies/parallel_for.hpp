// Runs work(i) for i = 0..count-1 on a pool of std::threads taking chunks of
// indices from an atomic counter (the parameter studies: sweep, map). The
// results land where work(i) writes them, so they do not depend on the
// number of threads. progress(done, count) is called from the calling thread
// about every 100 ms and once at the end. An exception thrown by a worker
// stops the others after their current index and is rethrown here.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace frictionref::detail {

// threads == 0: std::thread::hardware_concurrency() (1 if unknown); never
// more than count.
inline unsigned worker_count(unsigned threads, std::size_t count) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(count, 1)));
}

template <class Work>
void parallel_for(std::size_t count, unsigned threads, const Work& work,
                  const std::function<void(std::size_t, std::size_t)>& progress = {}) {
  const unsigned workers = worker_count(threads, count);
  // Chunks small enough to balance the load at the end, large enough that
  // the counter is touched rarely.
  const std::size_t chunk =
      std::clamp<std::size_t>(count / (static_cast<std::size_t>(workers) * 64), 1, 64);

  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished;
  unsigned running = workers;

  const auto worker = [&] {
    try {
      while (!failed.load(std::memory_order_relaxed)) {
        const std::size_t begin = next.fetch_add(chunk, std::memory_order_relaxed);
        if (begin >= count) break;
        const std::size_t end = std::min(count, begin + chunk);
        for (std::size_t i = begin; i < end && !failed.load(std::memory_order_relaxed); ++i)
          work(i);
        done.fetch_add(end - begin, std::memory_order_relaxed);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
      failed = true;
    }
    std::lock_guard<std::mutex> lock(mutex);
    --running;
    finished.notify_all();
  };

  std::vector<std::thread> pool;
  pool.reserve(workers);
  try {
    for (unsigned i = 0; i < workers; ++i) pool.emplace_back(worker);
    std::unique_lock<std::mutex> lock(mutex);
    while (running > 0) {
      finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return running == 0; });
      if (running > 0 && progress && !failed) {
        lock.unlock();
        progress(done.load(std::memory_order_relaxed), count);
        lock.lock();
      }
    }
  } catch (...) {
    // A thread that could not start, or a progress callback that threw: stop
    // the workers after their current index and pass the error on.
    failed = true;
    for (std::thread& thread : pool) thread.join();
    throw;
  }
  for (std::thread& thread : pool) thread.join();
  if (error) std::rethrow_exception(error);
  if (progress) progress(count, count);
}

}  // namespace frictionref::detail
