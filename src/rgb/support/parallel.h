#pragma once
// Layer rgb/support (threads, prefaulting, vectors, sorting, progress, small predicates): knows no
// mesh; includes only the standard library and GLM. docs/architecture.md draws the layers.
// Data-parallel loops for the linear passes over a whole mesh (loading a saved file checks millions
// of faces). The range is cut into one contiguous block per hardware thread; each block runs on its
// own thread, the first on the caller's (and any whose thread cannot start, on the caller's too). Results must not depend on the cut: the body writes only
// to its own elements, and an exception from the lowest block that threw is the one rethrown, which
// is the one a plain loop would have met first when blocks stop at their first problem.
#include <algorithm>
#include <cstddef>
#include <exception>
#include <functional>
#include <thread>
#include <vector>

namespace rgb {

// Blocks at most; more would only add start-up cost on the machines rgbsub runs on.
inline constexpr std::size_t kMaxParallelBlocks = 8;

// How many blocks a loop over n elements gets: one per hardware thread, none smaller than min_block.
inline std::size_t parallel_blocks(std::size_t n, std::size_t min_block) {
    const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, kMaxParallelBlocks);
    return std::clamp<std::size_t>(n / std::max<std::size_t>(min_block, 1), 1, threads);
}

// Calls body(block, begin, end) for `blocks` contiguous blocks covering [0, n), in parallel.
template <class Body>
void parallel_blocks_for(std::size_t n, std::size_t blocks, const Body& body) {
    blocks = std::max<std::size_t>(blocks, 1);
    auto run = [&](std::size_t b, std::exception_ptr& error) {
        try {
            body(b, n * b / blocks, n * (b + 1) / blocks);
        } catch (...) {
            error = std::current_exception();
        }
    };
    std::vector<std::exception_ptr> errors(blocks);
    std::vector<std::thread> threads;
    threads.reserve(blocks - 1);
    std::size_t started = 1;
    for (; started < blocks; ++started) {
        // A thread that cannot start (no memory left for its stack, a process limit) leaves its
        // blocks to this one: slower, never a failure of its own (nor, with threads running, a
        // std::terminate).
        try {
            threads.emplace_back(run, started, std::ref(errors[started]));
        } catch (...) {
            break;
        }
    }
    run(0, errors[0]);
    for (std::size_t b = started; b < blocks; ++b) run(b, errors[b]);
    for (std::thread& t : threads) t.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

// Calls body(begin, end) on blocks of [0, n), in parallel when n is at least two blocks of min_block.
template <class Body>
void parallel_for(std::size_t n, std::size_t min_block, const Body& body) {
    parallel_blocks_for(n, parallel_blocks(n, min_block), [&](std::size_t, std::size_t begin, std::size_t end) { body(begin, end); });
}

// Runs a() on this thread and b() on another, and waits for both; rethrows a's exception if it threw,
// else b's (the order in which a plain a(); b(); would have met them).
template <class A, class B>
void parallel_invoke(const A& a, const B& b) {
    std::exception_ptr b_error;
    auto run_b = [&] {
        try {
            b();
        } catch (...) {
            b_error = std::current_exception();
        }
    };
    std::thread other;
    try {
        other = std::thread(run_b);
    } catch (...) {
        // No thread to be had (see parallel_blocks_for): b runs after a.
    }
    std::exception_ptr a_error;
    try {
        a();
    } catch (...) {
        a_error = std::current_exception();
    }
    if (other.joinable()) other.join();
    else run_b();
    if (a_error) std::rethrow_exception(a_error);
    if (b_error) std::rethrow_exception(b_error);
}

}  // namespace rgb
