#pragma once
// Loops over a lattice's nodes (or any array) shared among threads in fixed chunks, owner computes:
// every index is done by exactly one chunk with the same arithmetic as in a single pass (the hot
// kernels round identically in every clone, hot_kernel.hpp), so the results are bit-identical at any
// thread count. Below `parallel_chunks_from` indices a loop runs in one pass on the calling thread:
// there the threads' start-up costs more than they save.
#include <cstdint>

namespace frictionlab {

/// The fewest indices a loop must have to be shared among threads (measured, share/docs/lattice-resolution.md).
inline constexpr std::int64_t parallel_chunks_from = 16384;

/// How many threads loops share their work among from now on (1 or more).
void set_worker_threads(int threads);
int worker_threads();
/// The threads this machine offers this process (its CPU affinity), at least 1.
int available_threads();

namespace detail {
using ChunkBody = void (*)(void* body, std::int64_t begin, std::int64_t end);
void run_chunks(std::int64_t n, int chunks, ChunkBody call, void* body);
}  // namespace detail

/// body(begin, end) over [0, n) in consecutive chunks (a few per thread), each starting at a
/// multiple of 8 (so every chunk's vector loops see the same alignment as one pass would).
template <class Body>
void for_each_chunk(std::int64_t n, Body&& body) {
    const int threads = worker_threads();
    if (threads <= 1 || n < parallel_chunks_from) return body(std::int64_t{0}, n);
    detail::run_chunks(
        n, threads, [](void* b, std::int64_t begin, std::int64_t end) { (*static_cast<Body*>(b))(begin, end); }, &body);
}

}  // namespace frictionlab
