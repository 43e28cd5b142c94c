// The batched lighting built with AVX2: eight pixels per instruction.
#define WEFT_SHADING_SUFFIX avx2
#include "raster/surface_shading_build.inl"
