// The threads every parallel loop runs on: one pool, made on first use with a thread per core (at
// most kMostThreads, the caller counting as one), kept for the life of the process. A loop called
// from inside another loop's job starts no thread: its indices are shared by the thread that
// called it and any pool thread left idle, so the cores are never oversubscribed.
#pragma once
#include <functional>
#include <vector>

namespace lowstretch {

constexpr int kMostThreads = 8;

// Runs job(i, slot) for every i < count, each index once, taking them in `order` if given (largest
// charts first, so that no thread is left with a big one at the end), on the calling thread and
// idle pool threads; returns when all are done. slot (0 .. kMostThreads - 1) is distinct among the
// threads running this loop's jobs at once, for per-thread scratch space. A job's result must
// depend on its index alone, never on the slot or the timing: then the result is the same every
// run, however the threads share the work.
void for_each_index(int count, const std::function<void(int, int)>& job, const std::vector<int>& order = {});

// The threads a loop runs on when none is busy: the pool's and the caller (1 to kMostThreads).
int loop_threads();

}  // namespace lowstretch
