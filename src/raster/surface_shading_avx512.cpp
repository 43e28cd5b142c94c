// The batched lighting built with AVX-512: sixteen pixels per instruction.
#define WEFT_SHADING_SUFFIX avx512
#include "raster/surface_shading_build.inl"
