// Colour map for spring strain, strain = length / rest_length - 1.
//
//   0                      → neutral light grey
//   stretched (> 0)        → warm: grey → orange (at half saturation) → red
//   compressed (< 0)       → cool: grey → light blue → deep blue
// The map saturates at ±saturation_strain (default 10 %: cloth springs rarely stretch
// further before tearing or strain limiting steps in) and is continuous everywhere.
#pragma once

#include <glm/vec3.hpp>

namespace weft::raster {

inline constexpr float default_saturation_strain = 0.10f;

// RGB in [0, 1]. A non-positive or NaN saturation_strain uses the default; NaN strain gives
// the neutral colour.
glm::vec3 colour_for_strain(float strain, float saturation_strain = default_saturation_strain);

}  // namespace weft::raster
