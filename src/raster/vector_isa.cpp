#include "raster/vector_isa.h"

#include <atomic>

namespace weft::raster {
namespace {

bool detect_avx512() {
#if defined(WEFT_RASTER_AVX512) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512dq");
#else
    return false;
#endif
}

const bool supported = detect_avx512();
std::atomic<bool> in_use{supported};

}  // namespace

bool avx512_supported() {
    return supported;
}

bool avx512_in_use() {
    return in_use.load(std::memory_order_relaxed);
}

void use_avx512(bool enabled) {
    in_use.store(enabled && supported, std::memory_order_relaxed);
}

}  // namespace weft::raster
