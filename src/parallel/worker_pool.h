// WorkerPool: a few persistent threads that run the slices of one parallel loop and wait
// for the next. Used by sim (force pass, particle loops, divergence guard) and raster
// (bands of the framebuffer); a step makes several such loops, so the hand-off must be
// cheap: workers spin briefly on a generation counter before sleeping.
//
// Results never depend on the number of threads: callers split work so that each item is
// written by exactly one slice, and the split itself does not change the arithmetic.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace weft {

class WorkerPool {
  public:
    // `threads` counts the calling thread too: 1 means no extra threads at all.
    explicit WorkerPool(int threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int thread_count() const { return static_cast<int>(workers_.size()) + 1; }

    // Runs body(begin, end) over [0, count) split into thread_count() contiguous slices;
    // returns when all are done. Slices are claimed, not assigned: the calling thread and
    // the workers each take the next unclaimed slice until none is left, so a worker that
    // the OS has not scheduled yet (a busy machine) costs a slice of waiting at most, never
    // a whole time slice. Which thread runs a slice never changes what the slice computes.
    // The body is called through a plain pointer, never copied into a std::function: a step
    // makes several such calls and none may allocate.
    template <class Body>
    void parallel_for(std::size_t count, Body&& body) {
        using Callable = std::remove_reference_t<Body>;
        run(count, const_cast<void*>(static_cast<const void*>(&body)),
            [](void* callable, std::size_t begin, std::size_t end) {
                (*static_cast<Callable*>(callable))(begin, end);
            });
    }

  private:
    using Trampoline = void (*)(void* callable, std::size_t begin, std::size_t end);
    void run(std::size_t count, void* callable, Trampoline trampoline);
    void worker_loop();
    // Claims and runs one slice of loop `generation`; false when none is left to claim.
    bool run_one_slice(std::uint32_t generation);

    std::vector<std::thread> workers_;
    // The loop in progress: written by the caller before it publishes the generation in
    // claims_, read by a thread only after it has claimed a slice of that generation.
    void* callable_ = nullptr;
    Trampoline trampoline_ = nullptr;
    std::size_t count_ = 0;
    std::uint32_t current_generation_ = 0;  // the caller's count of loops
    // generation (32 bits) | slice count (16) | next slice to claim (16), in one word, so a
    // claim can check that it belongs to the loop in progress.
    std::atomic<std::uint64_t> claims_{0};
    std::atomic<std::uint32_t> slices_done_{0};
    std::atomic<std::uint64_t> generation_{0};  // wakes the workers
    std::atomic<bool> stopping_{false};
    std::mutex mutex_;
    std::condition_variable wake_;
};

// Runs body(begin, end) over [0, count): split between the pool's threads when there is a
// pool with more than one thread and the caller judges the work `worth_threads` (a hand-off
// costs microseconds), else on the calling thread in one call (none when count is 0).
template <class Body>
void parallel_for_if(WorkerPool* pool, bool worth_threads, std::size_t count, Body&& body) {
    if (pool && pool->thread_count() > 1 && worth_threads)
        pool->parallel_for(count, body);
    else if (count > 0)
        body(std::size_t{0}, count);
}

// Threads to use by default: the WEFT_THREADS environment variable if set (>= 1), else the
// machine's hardware threads.
int default_thread_count();

}  // namespace weft
