// The batched lighting (surface_batch.inl) built with AVX-512: sixteen pixels per
// instruction. This file alone gets the instruction set (CMakeLists.txt) and runs only where
// the CPU has it (vector_isa.h).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "raster/surface_shading.h"

namespace weft::raster {
namespace {
#include "raster/surface_batch.inl"
}  // namespace

void shade_batch_avx512(const PreparedSurface& surface, const SurfaceBatch& batch,
                        ShadingLanes& lanes, Rgba8* colours) {
    shade_batch_body(surface, batch, lanes, colours);
}

}  // namespace weft::raster
