// Reductions (sums, maxima) over [0, count) split between a pool's threads in chunks fixed
// by the count alone: each chunk is reduced in index order and the chunks are combined in
// chunk order, so the result is the same bits for any number of threads, and with no pool.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "parallel/worker_pool.h"

namespace weft {

// chunk(begin, end) reduces one chunk; combine(a, b) joins two results, a first.
template <class Value, class Chunk, class Combine>
Value reduce_in_chunks(WorkerPool* pool, std::size_t count, Value zero, Chunk&& chunk,
                       Combine&& combine) {
    // At most 64 chunks (their results live on the stack: nothing is allocated), none under
    // 8192 items, which is what a hand-off to another thread costs about as much as.
    constexpr std::size_t max_chunks = 64;
    constexpr std::size_t min_chunk = 8192;
    const std::size_t size = std::max(min_chunk, (count + max_chunks - 1) / max_chunks);
    const std::size_t chunks = (count + size - 1) / size;
    std::array<Value, max_chunks> partial;
    parallel_for_if(pool, chunks > 1, chunks, [&](std::size_t first, std::size_t last) {
        for (std::size_t c = first; c < last; ++c)
            partial[c] = chunk(c * size, std::min(count, (c + 1) * size));
    });
    Value total = zero;
    for (std::size_t c = 0; c < chunks; ++c) total = combine(total, partial[c]);
    return total;
}

}  // namespace weft
