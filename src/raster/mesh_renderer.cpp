#include "raster/mesh_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "raster/clipping.h"
#include "raster/triangle_rasterizer.h"

namespace weft::raster {
namespace {

// Varying layout: world position, normal, then the optional uv and colour.
constexpr int position_slot = 0;
constexpr int normal_slot = 3;
constexpr int uv_slot = 6;

// The lighting model with everything that is constant over a draw worked out once, so the
// per-pixel work is a few dot products.
struct PreparedLighting {
    glm::vec3 to_light;  // unit length, or zero
    glm::vec3 ambient;
    glm::vec3 light;
    glm::vec3 eye_fill;
    float specular_strength;
    float shininess;
    int integer_shininess;  // >= 0 when shininess is a whole number: pow by squaring
    // n·h below which the highlight stays under half an 8-bit step: pow is skipped there.
    float specular_cutoff;
};

PreparedLighting prepare(const SurfaceStyle& style, const Lighting& lighting) {
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

// x^n; the common whole-number exponents by squaring, a handful of multiplies instead of a
// call to pow for most pixels.
inline float power(float x, const PreparedLighting& lighting) {
    int n = lighting.integer_shininess;
    if (n < 0) return std::pow(x, lighting.shininess);
    float result = 1.0f;
    while (n > 0) {
        if (n & 1) result *= x;
        x *= x;
        n >>= 1;
    }
    return result;
}

inline glm::vec3 shade(const PreparedLighting& lighting, const glm::vec3& base_colour,
                       const glm::vec3& normal, const glm::vec3& to_eye, bool front_facing) {
    const float normal_length_squared = glm::dot(normal, normal);
    // A vanishing normal (a vertex of only degenerate triangles) is lit as if facing the eye.
    glm::vec3 n = normal_length_squared > 1e-24f ? normal / std::sqrt(normal_length_squared)
                                                 : (front_facing ? to_eye : -to_eye);
    if (!front_facing) n = -n;  // two-sided: the back is lit through its own normal

    const float lambert = std::max(glm::dot(n, lighting.to_light), 0.0f);
    float specular = 0.0f;
    if (lambert > 0.0f && lighting.specular_strength > 0.0f) {
        const glm::vec3 halfway = lighting.to_light + to_eye;
        const float halfway_length_squared = glm::dot(halfway, halfway);
        if (halfway_length_squared > 0.0f) {
            const float n_dot_h = glm::dot(n, halfway) / std::sqrt(halfway_length_squared);
            if (n_dot_h > lighting.specular_cutoff) {
                specular = lighting.specular_strength * power(n_dot_h, lighting);
            }
        }
    }
    const float fill = std::max(glm::dot(n, to_eye), 0.0f);
    return base_colour * (lighting.ambient + lighting.light * lambert + lighting.eye_fill * fill) +
           lighting.light * specular;
}

// The per-pixel shader of draw_mesh. Its layout is fixed at compile time, so the rasterizer
// interpolates exactly the varyings it reads.
template <bool HasUv, bool HasColour>
struct SurfaceShader {
    static constexpr int colour_slot = HasUv ? uv_slot + 2 : uv_slot;
    static constexpr int varying_count = colour_slot + (HasColour ? 3 : 0);

    const SurfaceStyle* style;
    PreparedLighting lighting;
    glm::vec3 eye;

    Rgba8 operator()(const Fragment& fragment) const {
        const float* v = fragment.varyings;
        const glm::vec3 position(v[position_slot], v[position_slot + 1], v[position_slot + 2]);
        const glm::vec3 normal(v[normal_slot], v[normal_slot + 1], v[normal_slot + 2]);
        glm::vec3 base;
        if constexpr (HasColour) {
            base = glm::vec3(v[colour_slot], v[colour_slot + 1], v[colour_slot + 2]);
        } else {
            base = fragment.front_facing ? style->front_colour : style->back_colour;
        }
        if constexpr (HasUv) base *= pattern_factor(*style, glm::vec2(v[uv_slot], v[uv_slot + 1]));
        const glm::vec3 to_eye = eye - position;
        const float distance_squared = glm::dot(to_eye, to_eye);
        const glm::vec3 to_eye_unit =
            distance_squared > 0.0f ? to_eye / std::sqrt(distance_squared) : glm::vec3(0.0f);
        return to_rgba8(shade(lighting, base, normal, to_eye_unit, fragment.front_facing));
    }
};

// Transform: every vertex once, to clip space for the rasterizer and to world space for
// lighting, with its outcode, so culling a triangle is three ANDs.
void transform_vertices(const glm::mat4& view_projection, const MeshView& mesh, bool with_uv,
                        int colour_slot, std::vector<ClipVertex>& vertices,
                        std::vector<std::uint32_t>& outcodes) {
    const glm::mat4 clip_from_model = view_projection * mesh.model;
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(mesh.model)));
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec4 model_position(mesh.positions[i], 1.0f);
        ClipVertex& vertex = vertices[i];
        vertex.position = clip_from_model * model_position;
        outcodes[i] = clip_outcode(vertex.position);
        const glm::vec3 world(mesh.model * model_position);
        const glm::vec3 normal = normal_matrix * mesh.normals[i];
        float* v = vertex.varyings.data();
        for (int k = 0; k < 3; ++k) {
            v[position_slot + k] = world[k];
            v[normal_slot + k] = normal[k];
        }
        if (with_uv) {
            v[uv_slot] = mesh.uvs[i].x;
            v[uv_slot + 1] = mesh.uvs[i].y;
        }
        if (colour_slot >= 0) {
            for (int k = 0; k < 3; ++k) v[colour_slot + k] = mesh.colours[i][k];
        }
    }
}

template <bool HasUv, bool HasColour>
void draw_mesh_with(Framebuffer& framebuffer, const Camera& camera, const MeshView& mesh,
                    const SurfaceStyle& style, const Lighting& lighting, const PixelRect& scissor) {
    using Shader = SurfaceShader<HasUv, HasColour>;
    const std::size_t count = mesh.positions.size();
    std::vector<ClipVertex> vertices(count);
    std::vector<std::uint32_t> outcodes(count);
    transform_vertices(view_projection_matrix(camera, framebuffer), mesh, HasUv,
                       HasColour ? Shader::colour_slot : -1, vertices, outcodes);

    // Cull, clip, rasterize, shade: triangle_rasterizer.h.
    const Shader shader{&style, prepare(style, lighting), camera.position};
    RasterState state;
    state.scissor = scissor;
    for (const TriangleIndices& t : mesh.triangles) {
        if (t[0] >= count || t[1] >= count || t[2] >= count) continue;
        const TriangleOutcodes codes{outcodes[t[0]], outcodes[t[1]], outcodes[t[2]]};
        if (codes.culled()) continue;
        draw_triangle(framebuffer, state, vertices[t[0]], vertices[t[1]], vertices[t[2]], codes,
                      shader);
    }
}

}  // namespace

float pattern_factor(const SurfaceStyle& style, const glm::vec2& uv) {
    if (style.pattern == SurfacePattern::none) return 1.0f;
    // Cell indices by integer floor: std::floor on floats is a long instruction sequence on
    // baseline x86-64 (no SSE4.1 round), and this runs for every pixel of the cloth.
    auto cell = [](float coordinate) -> std::int64_t {
        if (!(std::abs(coordinate) < 1e15f)) return 0;  // NaN or absurd: any cell will do
        const auto truncated = static_cast<std::int64_t>(coordinate);
        return truncated - (static_cast<float>(truncated) > coordinate ? 1 : 0);
    };
    const std::int64_t cell_u = cell(uv.x * style.pattern_frequency);
    const std::int64_t cells = style.pattern == SurfacePattern::checker
                                   ? cell_u + cell(uv.y * style.pattern_frequency)
                                   : cell_u;
    return (cells & 1) != 0 ? 1.0f - style.pattern_contrast : 1.0f;
}

glm::vec3 shade_surface(const SurfaceStyle& style, const Lighting& lighting,
                        const glm::vec3& base_colour, const glm::vec3& normal,
                        const glm::vec3& to_eye, bool front_facing) {
    return shade(prepare(style, lighting), base_colour, normal, to_eye, front_facing);
}

bool draw_mesh(Framebuffer& framebuffer, const Camera& camera, const MeshView& mesh,
               const SurfaceStyle& style, const Lighting& lighting, const PixelRect& scissor) {
    const std::size_t count = mesh.positions.size();
    if (mesh.normals.size() != count) return false;
    if (!mesh.uvs.empty() && mesh.uvs.size() != count) return false;
    if (!mesh.colours.empty() && mesh.colours.size() != count) return false;

    const bool uv = style.pattern != SurfacePattern::none && !mesh.uvs.empty();
    const bool colour = !mesh.colours.empty();
    if (uv && colour) {
        draw_mesh_with<true, true>(framebuffer, camera, mesh, style, lighting, scissor);
    } else if (uv) {
        draw_mesh_with<true, false>(framebuffer, camera, mesh, style, lighting, scissor);
    } else if (colour) {
        draw_mesh_with<false, true>(framebuffer, camera, mesh, style, lighting, scissor);
    } else {
        draw_mesh_with<false, false>(framebuffer, camera, mesh, style, lighting, scissor);
    }
    return true;
}

}  // namespace weft::raster
