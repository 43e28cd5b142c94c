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
// lighting, with its outcode (so culling a triangle is three ANDs) and its window row (so a
// band rejects a triangle with two comparisons). Vertices [begin, end).
void transform_vertices(const glm::mat4& view_projection, const MeshView& mesh, int colour_slot,
                        PreparedMesh& prepared, std::size_t begin, std::size_t end) {
    const glm::mat4 clip_from_model = view_projection * mesh.model;
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(mesh.model)));
    for (std::size_t i = begin; i < end; ++i) {
        const glm::vec4 model_position(mesh.positions[i], 1.0f);
        ClipVertex& vertex = prepared.vertices[i];
        vertex.position = clip_from_model * model_position;
        prepared.outcodes[i] = clip_outcode(vertex.position);
        // What setup would compute for this corner of each of its triangles, once.
        if ((prepared.outcodes[i] & clipping_planes) == 0)
            prepared.window[i] = window_vertex(vertex.position, prepared.width, prepared.height);
        const glm::vec3 world(mesh.model * model_position);
        const glm::vec3 normal = normal_matrix * mesh.normals[i];
        float* v = vertex.varyings.data();
        for (int k = 0; k < 3; ++k) {
            v[position_slot + k] = world[k];
            v[normal_slot + k] = normal[k];
        }
        if (prepared.with_uv) {
            v[uv_slot] = mesh.uvs[i].x;
            v[uv_slot + 1] = mesh.uvs[i].y;
        }
        if (colour_slot >= 0) {
            for (int k = 0; k < 3; ++k) v[colour_slot + k] = mesh.colours[i][k];
        }
    }
}

// Draws the triangles `for_each_triangle` visits (it calls its argument with each index,
// in order) inside `scissor`.
template <bool HasUv, bool HasColour, class TriangleVisitor>
void draw_prepared_with(Framebuffer& framebuffer, const PreparedMesh& prepared,
                        const SurfaceStyle& style, const Lighting& lighting,
                        const PixelRect& scissor, TriangleVisitor&& for_each_triangle) {
    using Shader = SurfaceShader<HasUv, HasColour>;
    const std::size_t count = prepared.vertices.size();
    const ClipVertex* vertices = prepared.vertices.data();
    const std::uint32_t* outcodes = prepared.outcodes.data();
    const WindowVertex* window = prepared.window.data();
    const TriangleIndices* triangles = prepared.triangles.data();
    const PixelRect bounds = scissor.intersect(framebuffer.bounds());
    if (bounds.empty()) return;
    // A triangle whose snapped corners all lie a pixel or more above or below the band
    // draws nothing in it (the pixel centres it may cover lie between its corners).
    const std::int64_t band_top = (std::int64_t{bounds.y_begin} - 1) * subpixel_scale;
    const std::int64_t band_bottom = (std::int64_t{bounds.y_end} + 1) * subpixel_scale;

    // Cull, clip, rasterize, shade: triangle_rasterizer.h.
    const Shader shader{&style, prepare(style, lighting), prepared.eye};
    RasterState state;
    state.scissor = bounds;
    for_each_triangle([&](std::size_t index) {
        const TriangleIndices& t = triangles[index];
        if (t[0] >= count || t[1] >= count || t[2] >= count) return;
        const TriangleOutcodes codes{outcodes[t[0]], outcodes[t[1]], outcodes[t[2]]};
        if (codes.culled()) return;
        if (!codes.needs_clipping()) {
            const std::int64_t y0 = window[t[0]].y, y1 = window[t[1]].y, y2 = window[t[2]].y;
            if ((y0 < band_top && y1 < band_top && y2 < band_top) ||
                (y0 > band_bottom && y1 > band_bottom && y2 > band_bottom))
                return;
        }
        draw_triangle(framebuffer, state, vertices[t[0]], vertices[t[1]], vertices[t[2]],
                      window[t[0]], window[t[1]], window[t[2]], codes, shader);
    });
}

// The shader variant the prepared mesh needs, drawing the triangles `for_each_triangle`
// visits.
template <class TriangleVisitor>
void draw_prepared_triangles(Framebuffer& framebuffer, const PreparedMesh& prepared,
                             const SurfaceStyle& style, const Lighting& lighting,
                             const PixelRect& scissor, TriangleVisitor&& for_each_triangle) {
    if (prepared.with_uv && prepared.with_colour) {
        draw_prepared_with<true, true>(framebuffer, prepared, style, lighting, scissor,
                                       for_each_triangle);
    } else if (prepared.with_uv) {
        draw_prepared_with<true, false>(framebuffer, prepared, style, lighting, scissor,
                                        for_each_triangle);
    } else if (prepared.with_colour) {
        draw_prepared_with<false, true>(framebuffer, prepared, style, lighting, scissor,
                                        for_each_triangle);
    } else {
        draw_prepared_with<false, false>(framebuffer, prepared, style, lighting, scissor,
                                         for_each_triangle);
    }
}

// Triangles [begin, end) into the bands they may reach: lists[slice * band_count + band].
void bin_triangle_run(const PreparedMesh& prepared, std::size_t begin, std::size_t end, int slice,
                      TriangleBands& bands) {
    const std::size_t count = prepared.vertices.size();
    const std::uint32_t* outcodes = prepared.outcodes.data();
    const WindowVertex* window = prepared.window.data();
    const PixelRect viewport{0, 0, prepared.width, prepared.height};
    std::vector<std::uint32_t>* lists = bands.lists.data() + slice * bands.band_count;
    const std::int64_t rows_per_band = std::int64_t{bands.band_height} * subpixel_scale;
    for (std::size_t index = begin; index < end; ++index) {
        const TriangleIndices& t = prepared.triangles[index];
        if (t[0] >= count || t[1] >= count || t[2] >= count) continue;
        const TriangleOutcodes codes{outcodes[t[0]], outcodes[t[1]], outcodes[t[2]]};
        if (codes.culled()) continue;
        int first = 0, last = bands.band_count - 1;
        if (!codes.needs_clipping()) {
            const WindowVertex &a = window[t[0]], &b = window[t[1]], &c = window[t[2]];
            if (!may_cover_pixels(a, b, c, viewport)) continue;
            // The bands of the rows between its corners (on the viewport: covered pixels
            // are), with the draw's own pixel of margin.
            const std::int64_t top = std::min({a.y, b.y, c.y}) - subpixel_scale;
            const std::int64_t bottom = std::max({a.y, b.y, c.y}) + subpixel_scale;
            first = static_cast<int>(std::max<std::int64_t>(top, 0) / rows_per_band);
            last = static_cast<int>(std::min<std::int64_t>(
                std::max<std::int64_t>(bottom, 0) / rows_per_band, bands.band_count - 1));
        }
        for (int band = first; band <= last; ++band)
            lists[band].push_back(static_cast<std::uint32_t>(index));
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

bool prepare_mesh(const Camera& camera, int width, int height, const MeshView& mesh,
                  const SurfaceStyle& style, PreparedMesh& prepared, WorkerPool* pool) {
    const std::size_t count = mesh.positions.size();
    if (mesh.normals.size() != count) return false;
    if (!mesh.uvs.empty() && mesh.uvs.size() != count) return false;
    if (!mesh.colours.empty() && mesh.colours.size() != count) return false;
    prepared.triangles = mesh.triangles;
    prepared.vertices.resize(count);
    prepared.outcodes.resize(count);
    prepared.window.resize(count);
    prepared.width = width;
    prepared.height = height;
    prepared.eye = camera.position;
    prepared.with_uv = style.pattern != SurfacePattern::none && !mesh.uvs.empty();
    prepared.with_colour = !mesh.colours.empty();
    const int colour_slot = !prepared.with_colour ? -1
                            : prepared.with_uv    ? SurfaceShader<true, true>::colour_slot
                                                  : SurfaceShader<false, true>::colour_slot;
    const glm::mat4 view_projection = view_projection_matrix(camera, width, height);
    // Each vertex is written by one slice: the same values for any split.
    constexpr std::size_t min_vertices_for_threads = 4096;
    if (pool && pool->thread_count() > 1 && count >= min_vertices_for_threads) {
        pool->parallel_for(count, [&](std::size_t begin, std::size_t end) {
            transform_vertices(view_projection, mesh, colour_slot, prepared, begin, end);
        });
    } else {
        transform_vertices(view_projection, mesh, colour_slot, prepared, 0, count);
    }
    return true;
}

void draw_prepared_mesh(Framebuffer& framebuffer, const PreparedMesh& prepared,
                        const SurfaceStyle& style, const Lighting& lighting,
                        const PixelRect& scissor) {
    draw_prepared_triangles(framebuffer, prepared, style, lighting, scissor, [&](auto&& draw) {
        for (std::size_t index = 0; index < prepared.triangles.size(); ++index) draw(index);
    });
}

PixelRect TriangleBands::band_rect(int band, int width, int height) const {
    return {0, std::min(band * band_height, height), width,
            std::min((band + 1) * band_height, height)};
}

void bin_triangles(const PreparedMesh& prepared, int band_height, TriangleBands& bands,
                   WorkerPool* pool) {
    bands.band_height = std::max(band_height, 1);
    bands.band_count = std::max((prepared.height + bands.band_height - 1) / bands.band_height, 1);
    const std::size_t triangle_count = prepared.triangles.size();
    constexpr std::size_t min_triangles_for_threads = 4096;
    const bool threaded =
        pool && pool->thread_count() > 1 && triangle_count >= min_triangles_for_threads;
    bands.slice_count = threaded ? pool->thread_count() : 1;
    const auto list_count = static_cast<std::size_t>(bands.slice_count * bands.band_count);
    if (bands.lists.size() < list_count) bands.lists.resize(list_count);
    for (std::vector<std::uint32_t>& list : bands.lists) list.clear();
    if (!threaded) {
        bin_triangle_run(prepared, 0, triangle_count, 0, bands);
        return;
    }
    // One run per slice, so each slice writes only its own lists.
    const auto slices = static_cast<std::size_t>(bands.slice_count);
    pool->parallel_for(slices, [&](std::size_t begin, std::size_t end) {
        for (std::size_t slice = begin; slice < end; ++slice)
            bin_triangle_run(prepared, triangle_count * slice / slices,
                             triangle_count * (slice + 1) / slices, static_cast<int>(slice), bands);
    });
}

void draw_prepared_band(Framebuffer& framebuffer, const PreparedMesh& prepared,
                        const TriangleBands& bands, int band, const SurfaceStyle& style,
                        const Lighting& lighting) {
    if (band < 0 || band >= bands.band_count) return;
    const PixelRect rect = bands.band_rect(band, framebuffer.width(), framebuffer.height());
    draw_prepared_triangles(framebuffer, prepared, style, lighting, rect, [&](auto&& draw) {
        for (int slice = 0; slice < bands.slice_count; ++slice)
            for (std::uint32_t index :
                 bands.lists[static_cast<std::size_t>(slice * bands.band_count + band)])
                draw(index);
    });
}

bool draw_mesh(Framebuffer& framebuffer, const Camera& camera, const MeshView& mesh,
               const SurfaceStyle& style, const Lighting& lighting, const PixelRect& scissor) {
    PreparedMesh prepared;
    if (!prepare_mesh(camera, framebuffer.width(), framebuffer.height(), mesh, style, prepared))
        return false;
    draw_prepared_mesh(framebuffer, prepared, style, lighting, scissor);
    return true;
}

}  // namespace weft::raster
