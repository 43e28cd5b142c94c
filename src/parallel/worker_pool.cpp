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
    for (int index = 1; index < std::max(1, threads); ++index)
        workers_.emplace_back([this, index] { worker_loop(index); });
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

void WorkerPool::run_slice(int slice) {
    const std::size_t slices = static_cast<std::size_t>(thread_count());
    const std::size_t begin = count_ * static_cast<std::size_t>(slice) / slices;
    const std::size_t end = count_ * (static_cast<std::size_t>(slice) + 1) / slices;
    if (begin < end) trampoline_(callable_, begin, end);
}

void WorkerPool::worker_loop(int index) {
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
        run_slice(index);
        remaining_.fetch_sub(1, std::memory_order_acq_rel);
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
    remaining_.store(static_cast<int>(workers_.size()), std::memory_order_release);
    {
        std::lock_guard lock(mutex_);
        generation_.fetch_add(1, std::memory_order_acq_rel);
    }
    wake_.notify_all();
    run_slice(0);
    while (remaining_.load(std::memory_order_acquire) > 0) std::this_thread::yield();
}

}  // namespace weft
