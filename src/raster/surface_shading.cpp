#include "raster/surface_shading.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "raster/vector_isa.h"

namespace weft::raster {

// The AVX-512 and AVX2 builds (surface_shading_avx512.cpp, surface_shading_avx2.cpp).
void shade_batch_avx512(const PreparedSurface& surface, const SurfaceBatch& batch,
                        ShadingLanes& lanes, Rgba8* colours);
void shade_batch_avx2(const PreparedSurface& surface, const SurfaceBatch& batch,
                      ShadingLanes& lanes, Rgba8* colours);

namespace {
#include "raster/surface_batch.inl"
}  // namespace

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
    shade_lanes_body(lighting, lanes, count);
}

PreparedSurface prepare_surface(const SurfaceStyle& style, const Lighting& lighting,
                                const glm::vec3& eye) {
    PreparedSurface surface;
    surface.lighting = prepare_lighting(style, lighting);
    surface.eye = eye;
    surface.front_colour = style.front_colour;
    surface.back_colour = style.back_colour;
    surface.pattern = style.pattern;
    surface.pattern_frequency = style.pattern_frequency;
    surface.pattern_contrast = style.pattern_contrast;
    return surface;
}

void shade_batch(const PreparedSurface& surface, const SurfaceBatch& batch, ShadingLanes& lanes,
                 Rgba8* colours) {
    if (surface.avx512)
        shade_batch_avx512(surface, batch, lanes, colours);
    else if (surface.avx2)
        shade_batch_avx2(surface, batch, lanes, colours);
    else
        shade_batch_body(surface, batch, lanes, colours);
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
