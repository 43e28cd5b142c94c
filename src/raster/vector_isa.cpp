#include "raster/vector_isa.h"

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

bool detect_avx2() {
#if defined(WEFT_RASTER_AVX2) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

const bool supported = detect_avx512();
const bool avx2 = detect_avx2();

}  // namespace

bool avx512_supported() {
    return supported;
}

bool avx2_supported() {
    return avx2;
}

}  // namespace weft::raster
