// The determinism checks many simulation tests share: a state hash that must not depend on
// the thread count or on the kernel build (baseline x86-64, AVX2, AVX-512).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>

#include "sim/grid/grid_force_pass.h"
#include "test_scenes.h"

namespace weft::testing {

// hash_of(threads) on 1, 2 and 3 threads: the same, and not 0 (which marks a divergence).
template <class HashOf>
void expect_same_bits_on_any_thread_count(HashOf hash_of) {
    const std::uint64_t one = hash_of(1);
    ASSERT_NE(one, 0u);
    EXPECT_EQ(hash_of(2), one);
    EXPECT_EQ(hash_of(3), one);
}

// hash_of(options) under every kernel build this CPU runs (SimulationOptions::kernel_build):
// the baseline's. Skips the test on a CPU without AVX2 (nothing to compare).
template <class HashOf>
void expect_same_bits_on_every_kernel_build(HashOf hash_of) {
    if (supported_simd_level() == SimdLevel::baseline) GTEST_SKIP() << "no AVX2 on this CPU";
    const std::uint64_t baseline = hash_of(kernel_build(SimdLevel::baseline));
    ASSERT_NE(baseline, 0u);
    for (SimdLevel level : {SimdLevel::avx2, SimdLevel::avx512}) {
        if (level > supported_simd_level()) continue;
        EXPECT_EQ(hash_of(kernel_build(level)), baseline) << simd_level_name(level);
    }
}

}  // namespace weft::testing
