#include "parallel/worker_pool.h"

#include <algorithm>
#include <cstdlib>

namespace weft {

int default_thread_count() {
    if (const char* text = std::getenv("WEFT_THREADS")) {
        const int requested = std::atoi(text);
        if (requested >= 1) return std::min(requested, 64);
    }
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

WorkerPool::WorkerPool(int threads) {
    for (int index = 1; index < std::clamp(threads, 1, 64); ++index)
        workers_.emplace_back([this] { worker_loop(); });
}

WorkerPool::~WorkerPool() {
    stopping_ = true;
    {
        std::lock_guard lock(mutex_);
        generation_.fetch_add(1);
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

bool WorkerPool::run_one_slice(std::uint32_t generation) {
    std::uint64_t claims = claims_.load(std::memory_order_acquire);
    std::uint64_t slice = 0, slices = 0;
    do {
        if (static_cast<std::uint32_t>(claims >> 32) != generation) return false;
        slices = (claims >> 16) & 0xffff;
        slice = claims & 0xffff;
        if (slice >= slices) return false;
    } while (!claims_.compare_exchange_weak(claims, claims + 1, std::memory_order_acq_rel,
                                            std::memory_order_acquire));
    // The caller waits for this slice, so the loop's description stays valid meanwhile.
    const std::size_t begin = count_ * slice / slices;
    const std::size_t end = count_ * (slice + 1) / slices;
    if (begin < end) trampoline_(callable_, begin, end);
    slices_done_.fetch_add(1, std::memory_order_acq_rel);
    return true;
}

void WorkerPool::worker_loop() {
    std::uint64_t seen = 0;
    while (true) {
        // Spin a little (the next loop usually follows within microseconds), then sleep.
        int spins = 0;
        while (generation_.load(std::memory_order_acquire) == seen && ++spins < 2000)
            std::this_thread::yield();
        if (generation_.load(std::memory_order_acquire) == seen) {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return generation_.load() != seen; });
        }
        seen = generation_.load(std::memory_order_acquire);
        if (stopping_) return;
        while (run_one_slice(static_cast<std::uint32_t>(seen))) {
        }
    }
}

void WorkerPool::run(std::size_t count, void* callable, Trampoline trampoline) {
    if (workers_.empty()) {
        if (count > 0) trampoline(callable, 0, count);
        return;
    }
    callable_ = callable;
    trampoline_ = trampoline;
    count_ = count;
    const auto slices = static_cast<std::uint64_t>(thread_count());
    const std::uint32_t generation = ++current_generation_;
    slices_done_.store(0, std::memory_order_relaxed);
    claims_.store((std::uint64_t{generation} << 32) | (slices << 16), std::memory_order_release);
    {
        std::lock_guard lock(mutex_);
        generation_.store(generation, std::memory_order_release);
    }
    wake_.notify_all();
    while (run_one_slice(generation)) {
    }
    while (slices_done_.load(std::memory_order_acquire) < slices) std::this_thread::yield();
}

}  // namespace weft
