// A whole grid's normals (grid_normals.h), its row loops built with AVX2 and no FMA
// (grid_normals_kernel.inl): the same bits as the baseline build.
#include <cmath>
#include <vector>

#include "raster/grid_normals.h"

namespace weft::raster::grid_normals_kernel {

#if defined(WEFT_RASTER_AVX2)

namespace avx2 {
#include "raster/grid_normals_kernel.inl"
}  // namespace avx2

void find_faces_avx2(const FaceJob& job, float* const (&a)[3], float* const (&b)[3],
                     std::size_t row_begin, std::size_t row_end) {
    avx2::find_faces(job, a, b, row_begin, row_end);
}

void gather_avx2(const FaceJob& job, glm::vec3* normals, std::size_t row_begin,
                 std::size_t row_end) {
    avx2::gather(job, normals, row_begin, row_end);
}

#else

void find_faces_avx2(const FaceJob&, float* const (&)[3], float* const (&)[3], std::size_t,
                     std::size_t) {}
void gather_avx2(const FaceJob&, glm::vec3*, std::size_t, std::size_t) {}

#endif

}  // namespace weft::raster::grid_normals_kernel
