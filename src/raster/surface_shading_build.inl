// One build of the batched lighting (surface_batch.inl) as shade_batch_<WEFT_SHADING_SUFFIX>:
// each file that includes this is compiled with its own instruction set (CMakeLists.txt), with
// no fused multiply-add, and runs only where the CPU has it (vector_isa.h).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "raster/surface_shading.h"

#define WEFT_SHADING_JOIN(name, suffix) name##_##suffix
#define WEFT_SHADING_NAME(name, suffix) WEFT_SHADING_JOIN(name, suffix)

namespace weft::raster {
namespace {
#include "raster/surface_batch.inl"
}  // namespace

void WEFT_SHADING_NAME(shade_batch, WEFT_SHADING_SUFFIX)(const PreparedSurface& surface,
                                                         const SurfaceBatch& batch,
                                                         ShadingLanes& lanes, Rgba8* colours) {
    shade_batch_body(surface, batch, lanes, colours);
}

}  // namespace weft::raster
