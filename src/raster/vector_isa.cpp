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

const bool supported = detect_avx512();

}  // namespace

bool avx512_supported() {
    return supported;
}

}  // namespace weft::raster
