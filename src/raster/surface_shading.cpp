#include "raster/surface_shading.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace weft::raster {

PreparedLighting prepare_lighting(const SurfaceStyle& style, const Lighting& lighting) {
    PreparedLighting prepared;
    const float light_length = glm::length(lighting.direction_to_light);
    prepared.to_light = light_length > 0.0f && std::isfinite(light_length)
                            ? lighting.direction_to_light / light_length
                            : glm::vec3(0.0f);
    prepared.ambient = lighting.ambient_colour;
    prepared.light = lighting.light_colour;
    prepared.eye_fill = lighting.eye_fill_colour;
    prepared.shininess = std::max(style.shininess, 0.0f);
    prepared.integer_shininess =
        prepared.shininess <= 1024.0f && prepared.shininess == std::floor(prepared.shininess)
            ? static_cast<int>(prepared.shininess)
            : -1;
    const float peak =
        style.specular_strength *
        std::max({lighting.light_colour.r, lighting.light_colour.g, lighting.light_colour.b});
    prepared.specular_strength = peak > 0.0f ? style.specular_strength : 0.0f;
    prepared.specular_cutoff =
        peak > 0.0f && prepared.shininess > 0.0f
            ? std::pow(std::min(0.5f / 255.0f / peak, 1.0f), 1.0f / prepared.shininess)
            : 0.0f;
    return prepared;
}

void shade_lanes(const PreparedLighting& lighting, ShadingLanes& lanes, int count) {
    const float light_x = lighting.to_light.x, light_y = lighting.to_light.y,
                light_z = lighting.to_light.z;
    // The unit normal on the side seen, and the three light terms. Each choice selects
    // between values computed either way, so the loop has no branch.
    for (int i = 0; i < count; ++i) {
        const float front = lanes.front[i];
        const float ex = lanes.eye_x[i], ey = lanes.eye_y[i], ez = lanes.eye_z[i];
        const float nx0 = lanes.normal_x[i], ny0 = lanes.normal_y[i], nz0 = lanes.normal_z[i];
        const float length_squared = nx0 * nx0 + ny0 * ny0 + nz0 * nz0;
        const float inverse_length = 1.0f / std::sqrt(length_squared);
        // A vanishing normal (a vertex of only degenerate triangles) is lit as if facing
        // the eye; two-sided, the back is lit through its own (flipped) normal.
        const bool usable = length_squared > 1e-24f;
        const bool seen_front = front != 0.0f;
        float nx = usable ? nx0 * inverse_length : (seen_front ? ex : -ex);
        float ny = usable ? ny0 * inverse_length : (seen_front ? ey : -ey);
        float nz = usable ? nz0 * inverse_length : (seen_front ? ez : -ez);
        nx = seen_front ? nx : -nx;
        ny = seen_front ? ny : -ny;
        nz = seen_front ? nz : -nz;
        lanes.lambert[i] = std::max(nx * light_x + ny * light_y + nz * light_z, 0.0f);
        const float hx = light_x + ex, hy = light_y + ey, hz = light_z + ez;
        const float halfway_squared = hx * hx + hy * hy + hz * hz;
        lanes.halfway_squared[i] = halfway_squared;
        lanes.n_dot_h[i] = (nx * hx + ny * hy + nz * hz) / std::sqrt(halfway_squared);
        lanes.fill[i] = std::max(nx * ex + ny * ey + nz * ez, 0.0f);
    }

    // The highlight's power of n·h: by squaring for a whole exponent — bit by bit over all
    // lanes, the same products in the same order as one pixel's loop — else std::pow.
    if (lighting.integer_shininess >= 0) {
        float* power = lanes.highlight;
        float squares[ShadingLanes::capacity];
        for (int i = 0; i < count; ++i) {
            power[i] = 1.0f;
            squares[i] = lanes.n_dot_h[i];
        }
        for (int n = lighting.integer_shininess; n > 0; n >>= 1) {
            if (n & 1)
                for (int i = 0; i < count; ++i) power[i] *= squares[i];
            for (int i = 0; i < count; ++i) squares[i] *= squares[i];
        }
    } else {
        for (int i = 0; i < count; ++i)
            lanes.highlight[i] = std::pow(lanes.n_dot_h[i], lighting.shininess);
    }

    const float strength = lighting.specular_strength, cutoff = lighting.specular_cutoff;
    const glm::vec3 ambient = lighting.ambient, light = lighting.light, fill = lighting.eye_fill;
    for (int i = 0; i < count; ++i) {
        // The highlight where the light reaches the surface and n·h clears the cutoff.
        const bool lit = lanes.lambert[i] > 0.0f && strength > 0.0f &&
                         lanes.halfway_squared[i] > 0.0f && lanes.n_dot_h[i] > cutoff;
        const float specular = lit ? strength * lanes.highlight[i] : 0.0f;
        const float lambert = lanes.lambert[i], eye_fill = lanes.fill[i];
        lanes.lit_r[i] = lanes.base_r[i] * (ambient.r + light.r * lambert + fill.r * eye_fill) +
                         light.r * specular;
        lanes.lit_g[i] = lanes.base_g[i] * (ambient.g + light.g * lambert + fill.g * eye_fill) +
                         light.g * specular;
        lanes.lit_b[i] = lanes.base_b[i] * (ambient.b + light.b * lambert + fill.b * eye_fill) +
                         light.b * specular;
    }
}

float pattern_factor(const SurfaceStyle& style, const glm::vec2& uv) {
    if (style.pattern == SurfacePattern::none) return 1.0f;
    return pattern_lane(style.pattern, style.pattern_frequency, style.pattern_contrast, uv.x, uv.y);
}

glm::vec3 shade_surface(const SurfaceStyle& style, const Lighting& lighting,
                        const glm::vec3& base_colour, const glm::vec3& normal,
                        const glm::vec3& to_eye, bool front_facing) {
    // One lane of the same loops the drawing runs.
    ShadingLanes lanes;
    lanes.base_r[0] = base_colour.r;
    lanes.base_g[0] = base_colour.g;
    lanes.base_b[0] = base_colour.b;
    lanes.normal_x[0] = normal.x;
    lanes.normal_y[0] = normal.y;
    lanes.normal_z[0] = normal.z;
    lanes.eye_x[0] = to_eye.x;
    lanes.eye_y[0] = to_eye.y;
    lanes.eye_z[0] = to_eye.z;
    lanes.front[0] = front_facing ? 1.0f : 0.0f;
    shade_lanes(prepare_lighting(style, lighting), lanes, 1);
    return {lanes.lit_r[0], lanes.lit_g[0], lanes.lit_b[0]};
}

}  // namespace weft::raster
