#include "raster/strain_colour.h"

#include <algorithm>

#include <glm/common.hpp>

namespace weft::raster {
namespace {

const glm::vec3 neutral{0.82f, 0.82f, 0.80f};
const glm::vec3 orange{1.00f, 0.55f, 0.10f};
const glm::vec3 red{0.85f, 0.08f, 0.05f};
const glm::vec3 light_blue{0.45f, 0.65f, 0.95f};
const glm::vec3 deep_blue{0.10f, 0.25f, 0.85f};

// Piecewise-linear ramp through three colours: a at 0, b at 0.5, c at 1.
glm::vec3 ramp(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, float t) {
    return t < 0.5f ? glm::mix(a, b, t * 2.0f) : glm::mix(b, c, t * 2.0f - 1.0f);
}

}  // namespace

glm::vec3 colour_for_strain(float strain, float saturation_strain) {
    if (!(saturation_strain > 0.0f)) saturation_strain = default_saturation_strain;
    if (strain != strain) return neutral;
    const float t = std::clamp(strain / saturation_strain, -1.0f, 1.0f);
    return t >= 0.0f ? ramp(neutral, orange, red, t) : ramp(neutral, light_blue, deep_blue, -t);
}

}  // namespace weft::raster
