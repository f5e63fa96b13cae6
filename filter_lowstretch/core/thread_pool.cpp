#include "core/thread_pool.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <system_error>
#include <thread>

namespace lowstretch {

namespace {

// One call of for_each_index: its indices, each taken by whichever of its threads is free next.
struct Loop {
  int count = 0;
  const std::function<void(int, int)>* job = nullptr;
  const std::vector<int>* order = nullptr;
  std::atomic<int> next{0}, done{0};
  int slots = 1;    // slots handed out, the caller's 0 first (under the pool's mutex)
  int helpers = 0;  // pool threads running its jobs now (under the pool's mutex)
};

class Pool {
 public:
  static Pool& instance() {
    static Pool pool;
    return pool;
  }
  int threads() const { return int(threads_.size()) + 1; }
  Pool(const Pool&) = delete;
  Pool& operator=(const Pool&) = delete;
  ~Pool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    work_.notify_all();
    for (std::thread& t : threads_) t.join();
  }

  // The loop's indices on this thread and the pool threads that are idle or become so; returns
  // once every index is done and no pool thread still holds the loop.
  void run(Loop& loop) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      open_.push_back(&loop);
    }
    work_.notify_all();
    run_indices(loop, 0);
    std::unique_lock<std::mutex> lock(mutex_);
    open_.erase(std::find(open_.begin(), open_.end(), &loop));
    finished_.wait(lock, [&] { return loop.done == loop.count && loop.helpers == 0; });
  }

 private:
  Pool() {
    const int cores = std::max(1, int(std::thread::hardware_concurrency()));
    for (int t = 1; t < std::min(cores, kMostThreads); ++t) {
      try {
        threads_.emplace_back([this] { serve(); });
      } catch (const std::system_error&) {  // no more threads to be had: the loops run on fewer
        break;
      }
    }
  }

  void run_indices(Loop& loop, int slot) {
    for (int k = loop.next++; k < loop.count; k = loop.next++) {
      (*loop.job)(loop.order ? (*loop.order)[size_t(k)] : k, slot);
      if (++loop.done == loop.count) {
        { std::lock_guard<std::mutex> lock(mutex_); }  // the caller waits on the mutex, or checks after this
        finished_.notify_all();
      }
    }
  }

  // The latest loop with indices left (a nested loop first: its caller's job waits on it).
  Loop* open_loop() const {
    for (auto at = open_.rbegin(); at != open_.rend(); ++at)
      if ((*at)->next < (*at)->count) return *at;
    return nullptr;
  }

  // A pool thread: helps any loop with indices left, until the pool is destroyed. It joins each
  // loop at most once (it leaves when no index is left), so a loop never has more slots than threads.
  void serve() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      Loop* loop = nullptr;
      work_.wait(lock, [&] { return stop_ || (loop = open_loop()) != nullptr; });
      if (stop_) return;
      const int slot = loop->slots++;
      ++loop->helpers;
      lock.unlock();
      run_indices(*loop, slot);
      lock.lock();
      --loop->helpers;
      finished_.notify_all();
    }
  }

  std::mutex mutex_;
  std::condition_variable work_, finished_;
  std::vector<Loop*> open_;
  std::vector<std::thread> threads_;
  bool stop_ = false;
};

}  // namespace

void for_each_index(int count, const std::function<void(int, int)>& job, const std::vector<int>& order) {
  if (count <= 0) return;
  Loop loop;
  loop.count = count;
  loop.job = &job;
  loop.order = order.empty() ? nullptr : &order;
  if (count == 1) {  // nothing to share
    job(loop.order ? order[0] : 0, 0);
    return;
  }
  Pool::instance().run(loop);
}

int loop_threads() { return Pool::instance().threads(); }

}  // namespace lowstretch
