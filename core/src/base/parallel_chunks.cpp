#include "frictionlab/base/parallel_chunks.hpp"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

namespace frictionlab {

// oneTBB rather than OpenMP: the calling thread takes part, and chunks no thread has taken yet are
// done by the others, so a loop never waits for a thread the system has not scheduled. (OpenMP's
// join waits for every thread of the team: on a machine busy with other work, a run with two
// threads took 55 times as long as with one.)

namespace {

std::atomic<int> configured{1};

/// The arena loops run in, made again for another thread count. (A campaign forks its cases from a
/// process that has run no loop in threads: oneTBB does not survive a fork once it has started.)
tbb::task_arena& arena(int threads) {
    static std::mutex guard;
    static std::unique_ptr<tbb::task_arena> made;
    const std::lock_guard lock(guard);
    if (!made || made->max_concurrency() != threads) made = std::make_unique<tbb::task_arena>(threads);
    return *made;
}

}  // namespace

void set_worker_threads(int threads) { configured = std::max(threads, 1); }

int worker_threads() { return configured; }

int available_threads() {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
    return std::max(CPU_COUNT(&set), 1);
}

namespace detail {

void run_chunks(std::int64_t n, int threads, ChunkBody call, void* body) {
    // Four chunks a thread, so that a thread the system holds back delays the loop by a quarter of
    // its share at most; chunk c is [c n / chunks, (c + 1) n / chunks), each bound rounded down to
    // a multiple of 8.
    const int chunks = 4 * threads;
    auto bound = [&](int c) { return c == chunks ? n : (n * c / chunks) / 8 * 8; };
    arena(threads).execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<int>(0, chunks, 1),
            [&](const tbb::blocked_range<int>& r) {
                for (int c = r.begin(); c != r.end(); ++c) call(body, bound(c), bound(c + 1));
            },
            tbb::simple_partitioner());
    });
}

}  // namespace detail

}  // namespace frictionlab
