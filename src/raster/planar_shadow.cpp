#include "raster/planar_shadow.h"

#include <cmath>
#include <cstdint>

#include "raster/clipping.h"
#include "raster/triangle_rasterizer.h"

namespace weft::raster {
namespace {

// One colour for every pixel the shadow covers.
struct FlatShader {
    static constexpr int varying_count = 0;
    Rgba8 colour;
    Rgba8 operator()(const Fragment&) const { return colour; }
};

void transform_flat(const glm::mat4& clip_from_model, PreparedMesh& prepared,
                    std::span<const std::uint32_t> used, std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
        const std::size_t i = used.empty() ? k : used[k];
        const glm::vec4 clip = clip_from_model * glm::vec4(prepared.mesh.positions[i], 1.0f);
        prepared.clip[i] = clip;
        const std::uint32_t outcode = clip_outcode(clip);
        prepared.outcodes[i] = outcode;
        if ((outcode & clipping_planes) == 0)
            prepared.window[i] = window_vertex(clip, prepared.width, prepared.height);
    }
}

// The triangles `for_each_triangle` visits inside `scissor` (it calls its first argument with
// each triangle's index and its second with each binned fragment, in the mesh's order), as
// draw_prepared_mesh draws them but with no varyings.
template <class TriangleVisitor>
void draw_flat_with(Framebuffer& framebuffer, const PreparedMesh& prepared, Rgba8 colour,
                    const PixelRect& scissor, TriangleVisitor&& for_each_triangle) {
    const std::size_t count = prepared.clip.size();
    const PixelRect bounds = scissor.intersect(framebuffer.bounds());
    if (bounds.empty()) return;
    const std::int64_t band_top = (std::int64_t{bounds.y_begin} - 1) * subpixel_scale;
    const std::int64_t band_bottom = (std::int64_t{bounds.y_end} + 1) * subpixel_scale;
    const FlatShader shader{colour};
    RasterState state;
    state.scissor = bounds;
    const float* const no_varyings[3] = {nullptr, nullptr, nullptr};
    for_each_triangle(
        [&](std::size_t index) {
            const TriangleIndices& t = prepared.mesh.triangles[index];
            if (t[0] >= count || t[1] >= count || t[2] >= count) return;
            const TriangleOutcodes codes{prepared.outcodes[t[0]], prepared.outcodes[t[1]],
                                         prepared.outcodes[t[2]]};
            if (codes.culled()) return;
            if (codes.needs_clipping()) {
                ClipVertex a, b, c;
                a.position = prepared.clip[t[0]];
                b.position = prepared.clip[t[1]];
                c.position = prepared.clip[t[2]];
                draw_triangle(framebuffer, state, a, b, c, codes, shader);
                return;
            }
            const WindowVertex &a = prepared.window[t[0]], &b = prepared.window[t[1]],
                               &c = prepared.window[t[2]];
            if ((a.y < band_top && b.y < band_top && c.y < band_top) ||
                (a.y > band_bottom && b.y > band_bottom && c.y > band_bottom))
                return;
            draw_prepared_triangle(framebuffer, state, a, b, c, no_varyings, shader);
        },
        [&](const BinnedFragment& fragment) {
            const auto [v0, v1, v2] =
                fragment.setup_vertices(prepared.mesh.triangles[fragment.triangle_index()]);
            const WindowVertex* const vertex[3] = {&prepared.window[v0], &prepared.window[v1],
                                                   &prepared.window[v2]};
            shade_binned_fragment(framebuffer, state, fragment, vertex, no_varyings, shader);
        });
}

}  // namespace

std::optional<glm::mat4> shadow_projection(const glm::vec3& direction_to_light, float height) {
    const float length = glm::length(direction_to_light);
    if (!std::isfinite(length) || !std::isfinite(height) || length <= 0.0f ||
        direction_to_light.y < 0.15f * length)
        return std::nullopt;
    const float run_x = direction_to_light.x / direction_to_light.y;  // x moved per metre of y
    const float run_z = direction_to_light.z / direction_to_light.y;
    glm::mat4 projection(1.0f);  // columns: the images of x, y, z and the origin
    projection[1] = glm::vec4(-run_x, 0.0f, -run_z, 0.0f);
    projection[3] = glm::vec4(run_x * height, height, run_z * height, 1.0f);
    return projection;
}

void prepare_flat_mesh(const Camera& camera, int width, int height, const MeshView& mesh,
                       PreparedMesh& prepared, WorkerPool* pool,
                       std::span<const std::uint32_t> used) {
    const std::size_t count = mesh.positions.size();
    prepared.mesh = mesh;
    // No snapped window corners are kept here, so binning must not load a whole grid's
    // groups from them (PreparedMesh::snapped_x): it gathers each triangle's corners.
    prepared.mesh.grid_cols = 0;
    prepared.snapped_x.clear();
    prepared.snapped_y.clear();
    prepared.model_is_world = mesh.model == glm::mat4(1.0f);
    prepared.clip.resize(count);
    prepared.outcodes.resize(count);
    prepared.window.resize(count);
    prepared.varyings_over_w.clear();
    prepared.varying_stride = 0;
    prepared.width = width;
    prepared.height = height;
    prepared.eye = camera.position;
    prepared.with_uv = prepared.with_colour = false;
    const glm::mat4 clip_from_model = view_projection_matrix(camera, width, height) * mesh.model;
    // Each vertex is written by one slice: the same values for any split.
    const std::size_t transformed = used.empty() ? count : used.size();
    constexpr std::size_t min_vertices_for_threads = 4096;
    if (pool && pool->thread_count() > 1 && transformed >= min_vertices_for_threads)
        pool->parallel_for(transformed, [&](std::size_t begin, std::size_t end) {
            transform_flat(clip_from_model, prepared, used, begin, end);
        });
    else
        transform_flat(clip_from_model, prepared, used, 0, transformed);
}

void draw_flat_mesh(Framebuffer& framebuffer, const PreparedMesh& prepared, Rgba8 colour,
                    const PixelRect& scissor) {
    draw_flat_with(framebuffer, prepared, colour, scissor, [&](auto&& draw, auto&&) {
        for (std::size_t index = 0; index < prepared.mesh.triangles.size(); ++index) draw(index);
    });
}

void draw_flat_band(Framebuffer& framebuffer, const PreparedMesh& prepared,
                    const TriangleBands& bands, int band, Rgba8 colour) {
    if (band < 0 || band >= bands.band_count) return;
    const PixelRect rect = bands.band_rect(band, framebuffer.width(), framebuffer.height());
    draw_flat_with(framebuffer, prepared, colour, rect,
                   [&](auto&& draw, auto&& shade) { visit_band(bands, band, draw, shade); });
}

}  // namespace weft::raster
