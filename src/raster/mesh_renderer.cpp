#include "raster/mesh_renderer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "raster/binning_avx2.h"
#include "raster/clipping.h"
#include "raster/fragment_varyings_avx2.h"
#include "raster/surface_shading.h"
#include "raster/triangle_rasterizer.h"
#include "raster/vector_isa.h"
#include "raster/vertex_transform_avx2.h"

namespace weft::raster {
namespace {

// Varying layout: world position, normal, then the optional uv and colour.
constexpr int position_slot = 0;
constexpr int normal_slot = 3;
constexpr int uv_slot = 6;

// The shader of draw_mesh. Its layout is fixed at compile time, so the rasterizer
// interpolates exactly the varyings it reads. It is deferred (triangle_rasterizer.h): covered
// pixels are queued with their varyings and lit a batch at a time (surface_shading.h).
template <bool HasUv, bool HasColour>
struct SurfaceShader {
    static constexpr int colour_slot = HasUv ? uv_slot + 2 : uv_slot;
    static constexpr int varying_count = colour_slot + (HasColour ? 3 : 0);
    static constexpr bool deferred = true;
    static constexpr bool takes_fragment_blocks = true;

    // Pixels waiting for their colour: framebuffer index, varyings, side seen.
    struct Queue {
        int count = 0;
        std::uint32_t pixel[ShadingLanes::capacity];
        float varyings[varying_count][ShadingLanes::capacity];
        float front[ShadingLanes::capacity];
        ShadingLanes lanes;
        FragmentSink sink;  // the arrays above, for blocks

        Queue() : sink{pixel, {}} {
            for (int k = 0; k < varying_count; ++k) sink.varyings[k] = varyings[k];
        }
        Queue(const Queue&) = delete;
        Queue& operator=(const Queue&) = delete;
    };

    PreparedSurface surface;
    Rgba8* colours;
    Queue* queue;

    void defer(std::size_t pixel, const Fragment& fragment) const {
        Queue& q = *queue;
        q.pixel[q.count] = static_cast<std::uint32_t>(pixel);
        for (int k = 0; k < varying_count; ++k) q.varyings[k][q.count] = fragment.varyings[k];
        q.front[q.count] = fragment.front_facing ? 1.0f : 0.0f;
        if (++q.count == ShadingLanes::capacity) flush();
    }

    // Blocks of fragments (fragment_block.h) go straight into the queue's arrays.
    const FragmentSink& sink() const { return queue->sink; }

    int reserve() const {
        if (queue->count > ShadingLanes::capacity - fragment_block_size) flush();
        return queue->count;
    }

    void commit(int count, bool front_facing) const {
        Queue& q = *queue;
        // All sixteen of the block's slots, whatever the count: no loop to mispredict.
        std::fill_n(q.front + q.count, fragment_block_size, front_facing ? 1.0f : 0.0f);
        q.count += count;
        if (q.count == ShadingLanes::capacity) flush();  // defer() needs a free slot
    }

    // Binned fragments that passed their depth test, their varyings interpolated eight at a
    // time (fragment_varyings_avx2.h): queued as defer() would have queued them one by one.
    void defer_group(const FragmentGroup& group, const float* varyings_over_w) const
        requires(varying_count == grouped_varying_count) {
        Queue& q = *queue;
        if (q.count > ShadingLanes::capacity - fragment_group_size) flush();
        float* const out[grouped_varying_count] = {
            q.varyings[0] + q.count, q.varyings[1] + q.count, q.varyings[2] + q.count,
            q.varyings[3] + q.count, q.varyings[4] + q.count, q.varyings[5] + q.count,
            q.varyings[6] + q.count, q.varyings[7] + q.count};
        interpolate_fragment_varyings_avx2(varyings_over_w, group, out);
        for (int j = 0; j < group.count; ++j) {
            q.pixel[q.count + j] = group.pixel[j];
            q.front[q.count + j] = group.front[j];
        }
        q.count += group.count;
        if (q.count == ShadingLanes::capacity) flush();  // defer() needs a free slot
    }

    // Lights the queued pixels and writes their colours, in the order they were queued: a
    // pixel covered twice ends with the later fragment's colour, as if drawn at once.
    void flush() const {
        Queue& q = *queue;
        SurfaceBatch batch;
        batch.count = q.count;
        batch.pixels = q.pixel;
        for (int k = 0; k < 3; ++k) {
            batch.position[k] = q.varyings[position_slot + k];
            batch.normal[k] = q.varyings[normal_slot + k];
        }
        if constexpr (HasUv) {
            batch.uv[0] = q.varyings[uv_slot];
            batch.uv[1] = q.varyings[uv_slot + 1];
        }
        if constexpr (HasColour) {
            for (int k = 0; k < 3; ++k) batch.colour[k] = q.varyings[colour_slot + k];
        }
        batch.front = q.front;
        shade_batch(surface, batch, q.lanes, colours);
        q.count = 0;
    }
};

// Vertex i's varyings in the layout of SurfaceShader<HasUv, HasColour>: its world position
// and normal (a cloth is given in world space: no product by an identity matrix for it),
// then its uv and colour.
template <bool HasUv, bool HasColour>
void vertex_varyings(const PreparedMesh& prepared, std::size_t i, float* varyings) {
    const MeshView& mesh = prepared.mesh;
    const glm::vec3 world = prepared.model_is_world
                                ? mesh.positions[i]
                                : glm::vec3(mesh.model * glm::vec4(mesh.positions[i], 1.0f));
    const glm::vec3 normal =
        prepared.model_is_world ? mesh.normals[i] : prepared.normal_matrix * mesh.normals[i];
    for (int k = 0; k < 3; ++k) {
        varyings[position_slot + k] = world[k];
        varyings[normal_slot + k] = normal[k];
    }
    if constexpr (HasUv) {
        varyings[uv_slot] = mesh.uvs[i].x;
        varyings[uv_slot + 1] = mesh.uvs[i].y;
    }
    if constexpr (HasColour) {
        for (int k = 0; k < 3; ++k)
            varyings[SurfaceShader<HasUv, HasColour>::colour_slot + k] = mesh.colours[i][k];
    }
}

// Transform: every vertex once, to clip space, with its outcode (so culling a triangle is
// three ANDs), its window position (so setup and binning need no divide) and its varyings
// divided by w (what the rasterizer interpolates). Vertices [begin, end). The varyings
// themselves are not kept: only a triangle that needs clipping uses them, and it computes
// them again (clip_vertex below) — writing them for every vertex was a third of this pass.
// With `with_avx2`, the positions of whole groups of eight vertices go through
// transform_positions_avx2 (the same bits), then their varyings here.
template <bool HasUv, bool HasColour>
void transform_vertices(const glm::mat4& view_projection, PreparedMesh& prepared, std::size_t begin,
                        std::size_t end, bool with_avx2) {
    constexpr int varying_count = SurfaceShader<HasUv, HasColour>::varying_count;
    const glm::mat4 clip_from_model = view_projection * prepared.mesh.model;
    // What setup would compute for each corner of the vertex's triangles, once.
    const auto divide_varyings = [&](std::size_t i, float inverse_w) {
        float varyings[varying_count];
        vertex_varyings<HasUv, HasColour>(prepared, i, varyings);
        float* over_w = prepared.varyings_over_w.data() + i * varying_count;
        for (int k = 0; k < varying_count; ++k) over_w[k] = varyings[k] * inverse_w;
    };
    // Only a whole grid's binning reads them (PreparedMesh::snapped_x).
    const bool whole_grid = prepared.mesh.grid_cols > 1;
    const auto keep_snapped = [&](std::size_t i, const WindowVertex& window) {
        if (!whole_grid) return;
        prepared.snapped_x[i] = static_cast<std::int32_t>(window.x);
        prepared.snapped_y[i] = static_cast<std::int32_t>(window.y);
    };
    std::size_t i = begin;
    if (with_avx2) {
        const std::size_t groups = (end - begin) / transform_group_size;
        transform_positions_avx2(clip_from_model, prepared.mesh.positions.data(), begin, groups,
                                 prepared.width, prepared.height, prepared.clip.data(),
                                 prepared.outcodes.data(), prepared.window.data());
        const std::size_t stepped = begin + groups * transform_group_size;
        // A surface in world space with uvs and no colours (a cloth's) has its eight varyings
        // in one vector a vertex.
        bool divided = false;
        if constexpr (HasUv && !HasColour) {
            if (prepared.model_is_world) {
                divide_surface_varyings_avx2(prepared.mesh.positions.data(),
                                             prepared.mesh.normals.data(), prepared.mesh.uvs.data(),
                                             prepared.outcodes.data(), prepared.window.data(), i,
                                             stepped, prepared.varyings_over_w.data());
                divided = true;
            }
        }
        for (; i < stepped; ++i) {
            if ((prepared.outcodes[i] & clipping_planes) == 0) {
                keep_snapped(i, prepared.window[i]);
                if (!divided) divide_varyings(i, prepared.window[i].inverse_w);
            }
        }
    }
    for (; i < end; ++i) {
        const glm::vec4 clip = clip_from_model * glm::vec4(prepared.mesh.positions[i], 1.0f);
        prepared.clip[i] = clip;
        const std::uint32_t outcode = clip_outcode(clip);
        prepared.outcodes[i] = outcode;
        if ((outcode & clipping_planes) == 0) {
            const WindowVertex window = window_vertex(clip, prepared.width, prepared.height);
            prepared.window[i] = window;
            keep_snapped(i, window);
            divide_varyings(i, window.inverse_w);
        }
    }
}

// Vertex i as the clipper takes it: clip position and varyings.
template <bool HasUv, bool HasColour>
ClipVertex clip_vertex(const PreparedMesh& prepared, std::size_t i) {
    ClipVertex vertex;
    vertex.position = prepared.clip[i];
    vertex_varyings<HasUv, HasColour>(prepared, i, vertex.varyings.data());
    return vertex;
}

// Draws the triangles `for_each_triangle` visits inside `scissor`: it calls its first
// argument with each triangle's index and its second with each binned fragment, in the
// mesh's order.
template <bool HasUv, bool HasColour, class TriangleVisitor>
void draw_prepared_with(Framebuffer& framebuffer, const PreparedMesh& prepared,
                        const SurfaceStyle& style, const Lighting& lighting,
                        const PixelRect& scissor, TriangleVisitor&& for_each_triangle) {
    using Shader = SurfaceShader<HasUv, HasColour>;
    const std::size_t count = prepared.clip.size();
    const std::uint32_t* outcodes = prepared.outcodes.data();
    const WindowVertex* window = prepared.window.data();
    const TriangleIndices* triangles = prepared.mesh.triangles.data();
    const float* varyings_over_w = prepared.varyings_over_w.data();
    const auto stride = static_cast<std::size_t>(prepared.varying_stride);
    const PixelRect bounds = scissor.intersect(framebuffer.bounds());
    if (bounds.empty()) return;
    // A triangle whose snapped corners all lie a pixel or more above or below the band
    // draws nothing in it (the pixel centres it may cover lie between its corners).
    const std::int64_t band_top = (std::int64_t{bounds.y_begin} - 1) * subpixel_scale;
    const std::int64_t band_bottom = (std::int64_t{bounds.y_end} + 1) * subpixel_scale;

    // Cull, clip, rasterize, shade: triangle_rasterizer.h.
    typename Shader::Queue queue;
    PreparedSurface surface = prepare_surface(style, lighting, prepared.eye);
    surface.avx512 = framebuffer.avx512_in_use();
    surface.avx2 = framebuffer.avx2_in_use();
    const Shader shader{surface, framebuffer.colours().data(), &queue};
    RasterState state;
    state.scissor = bounds;
    const DepthRows depths = framebuffer.depth_rows();
    const auto width = static_cast<std::size_t>(framebuffer.width());
    // Binned fragments are depth-tested one by one, in order, and their varyings interpolated
    // in groups of eight where the lanes hold a vertex's varyings; a group goes into the
    // queue before anything drawn after its fragments, so the queue's order is unchanged.
    constexpr bool groups_fit = Shader::varying_count == grouped_varying_count;
    const bool grouped = groups_fit && surface.avx2;
    FragmentGroup group;
    const auto queue_group = [&] {
        if constexpr (groups_fit) {
            if (group.count > 0) shader.defer_group(group, varyings_over_w);
            group.count = 0;
        }
    };
    for_each_triangle(
        [&](std::size_t index) {
            queue_group();
            const TriangleIndices& t = triangles[index];
            if (t[0] >= count || t[1] >= count || t[2] >= count) return;
            const TriangleOutcodes codes{outcodes[t[0]], outcodes[t[1]], outcodes[t[2]]};
            if (codes.culled()) return;
            if (codes.needs_clipping()) {
                draw_triangle(framebuffer, state, clip_vertex<HasUv, HasColour>(prepared, t[0]),
                              clip_vertex<HasUv, HasColour>(prepared, t[1]),
                              clip_vertex<HasUv, HasColour>(prepared, t[2]), codes, shader);
                return;
            }
            const WindowVertex &a = window[t[0]], &b = window[t[1]], &c = window[t[2]];
            if ((a.y < band_top && b.y < band_top && c.y < band_top) ||
                (a.y > band_bottom && b.y > band_bottom && c.y > band_bottom))
                return;
            const float* const over_w[3] = {varyings_over_w + t[0] * stride,
                                            varyings_over_w + t[1] * stride,
                                            varyings_over_w + t[2] * stride};
            draw_prepared_triangle(framebuffer, state, a, b, c, over_w, shader);
        },
        [&](const BinnedFragment& fragment) {
            const auto [v0, v1, v2] = fragment.setup_vertices(triangles[fragment.triangle_index()]);
            const WindowVertex* const vertex[3] = {window + v0, window + v1, window + v2};
            if (grouped) {
                const BinnedFragmentDepth tested =
                    test_binned_fragment_depth(depths, width, state, fragment, vertex);
                if (!tested.passed) return;
                const int j = group.count++;
                group.pixel[j] = static_cast<std::uint32_t>(tested.index);
                group.front[j] = fragment.front_facing() ? 1.0f : 0.0f;
                group.vertex[j][0] = v0;
                group.vertex[j][1] = v1;
                group.vertex[j][2] = v2;
                for (int i = 0; i < 3; ++i) group.weight[j][i] = fragment.weight[i];
                group.w[j] = binned_fragment_w(fragment, vertex);
                if (group.count == fragment_group_size) queue_group();
                return;
            }
            const float* const over_w[3] = {varyings_over_w + v0 * stride,
                                            varyings_over_w + v1 * stride,
                                            varyings_over_w + v2 * stride};
            shade_binned_fragment(framebuffer, state, fragment, vertex, over_w, shader);
        });
    queue_group();
    shader.flush();
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

// How binning may go about it.
struct BinningChoice {
    bool with_fragments = true;  // tiny triangles go in as fragments, else as triangles
    bool with_avx2 = false;      // eight triangles at a time (binning_avx2.h)
};

// Triangles [begin, end) into the bands they may reach: lists[slice * band_count + band].
void bin_triangle_run(const PreparedMesh& prepared, std::size_t begin, std::size_t end, int slice,
                      BinningChoice choice, TriangleBands& bands) {
    const std::size_t count = prepared.clip.size();
    const std::uint32_t* outcodes = prepared.outcodes.data();
    const WindowVertex* window = prepared.window.data();
    const TriangleIndices* triangles = prepared.mesh.triangles.data();
    const PixelRect viewport{0, 0, prepared.width, prepared.height};
    std::vector<std::uint32_t>* lists = bands.lists.data() + slice * bands.band_count;
    std::vector<BinnedFragment>* fragments = bands.fragments.data() + slice * bands.band_count;
    // The band of a pixel row: a shift when bands are a power of two rows high (the
    // frame's are), as a division per triangle would be a large part of binning.
    const int band_shift = std::has_single_bit(static_cast<unsigned>(bands.band_height))
                               ? std::countr_zero(static_cast<unsigned>(bands.band_height))
                               : -1;
    auto band_of = [&](int row) {
        return std::min(band_shift >= 0 ? row >> band_shift : row / bands.band_height,
                        bands.band_count - 1);
    };
    auto add_to_bands = [&](std::size_t index, int first, int last) {
        for (int band = first; band <= last; ++band)
            lists[band].push_back(static_cast<std::uint32_t>(index));
    };
    // The pixel centres a tiny triangle covers, each into its row's band.
    auto add_fragments = [&](std::size_t index, bool front_facing, int x_begin, int y_begin,
                             unsigned covered, auto&& weights_at) {
        BinnedFragment fragment;
        fragment.triangle =
            static_cast<std::uint32_t>(index) | (front_facing ? BinnedFragment::front_bit : 0u);
        for (; covered != 0; covered &= covered - 1) {
            const int k = std::countr_zero(covered);
            const int y = y_begin + k / tiny_box_side;
            fragment.x = static_cast<std::uint16_t>(x_begin + k % tiny_box_side);
            fragment.y = static_cast<std::uint16_t>(y);
            weights_at(k, fragment.weight);
            // A covered centre lies inside the viewport, so its band needs no clamp.
            fragments[band_shift >= 0 ? y >> band_shift : y / bands.band_height].push_back(
                fragment);
        }
    };
    BinnedCoverage coverage;
    auto bin_one = [&](std::size_t index) {
        const TriangleIndices& t = triangles[index];
        if (t[0] >= count || t[1] >= count || t[2] >= count) return;
        const TriangleOutcodes codes{outcodes[t[0]], outcodes[t[1]], outcodes[t[2]]};
        if (codes.culled()) return;
        int first = 0, last = bands.band_count - 1;
        if (!codes.needs_clipping()) {
            // The bands of the rows of the pixel centres it may cover. Many triangles of a
            // sheet seen whole cover none, and go into no band.
            bin_coverage(window[t[0]], window[t[1]], window[t[2]], viewport, coverage);
            if (coverage.empty()) return;
            if (coverage.tiny && choice.with_fragments) {
                add_fragments(index, coverage.front_facing, coverage.x_begin, coverage.y_begin,
                              coverage.covered, [&](int k, float(&weight)[3]) {
                                  for (int i = 0; i < 3; ++i) weight[i] = coverage.weights[k][i];
                              });
                return;
            }
            first = band_of(coverage.first);
            last = band_of(coverage.last);
        }
        add_to_bands(index, first, last);
    };

    std::size_t index = begin;
    if (choice.with_fragments && choice.with_avx2) {
        // Where the lanes leave most triangles undecided (a mesh seen up close, its triangles
        // many pixels wide), classifying them first only adds work: the next few groups then
        // go straight to the scalar path. The bands are the same either way.
        constexpr int mostly_undecided = 6, groups_skipped = 8;
        int skipped = 0;
        BinningGroup group;
        for (; index + binning_group_size <= end; index += binning_group_size) {
            if (skipped > 0) {
                --skipped;
                for (int lane = 0; lane < binning_group_size; ++lane) bin_one(index + lane);
                continue;
            }
            if (grid_group_fits(index, prepared.mesh.grid_cols))
                classify_grid_group_avx2(index, prepared.mesh.grid_cols, outcodes,
                                         prepared.snapped_x.data(), prepared.snapped_y.data(),
                                         prepared.width, prepared.height, group);
            else
                classify_for_binning_avx2(triangles + index, static_cast<std::uint32_t>(count),
                                          outcodes, window, prepared.width, prepared.height, group);
            if (group.undecided_count >= mostly_undecided) skipped = groups_skipped;
            // Lanes in order, as the scalar path takes the triangles; those that draw nothing
            // are not visited.
            for (unsigned active = group.tiny_lanes | group.box_lanes | group.undecided_lanes;
                 active != 0; active &= active - 1) {
                const int lane = std::countr_zero(active);
                const unsigned bit = 1u << lane;
                if ((group.tiny_lanes & bit) != 0) {
                    add_fragments(index + lane, group.front_facing[lane] != 0, group.x_begin[lane],
                                  group.y_begin[lane], group.covered[lane],
                                  [&](int k, float(&weight)[3]) {
                                      for (int i = 0; i < 3; ++i)
                                          weight[i] = group.weight[k][i][lane];
                                  });
                } else if ((group.box_lanes & bit) != 0) {
                    add_to_bands(index + lane, band_of(group.y_begin[lane]),
                                 band_of(group.y_end[lane] - 1));
                } else {
                    bin_one(index + lane);
                }
            }
        }
    }
    for (; index < end; ++index) bin_one(index);
}

}  // namespace

bool prepare_mesh(const Camera& camera, int width, int height, const MeshView& mesh,
                  const SurfaceStyle& style, PreparedMesh& prepared, WorkerPool* pool,
                  bool allow_avx2) {
    const std::size_t count = mesh.positions.size();
    if (mesh.normals.size() != count) return false;
    if (!mesh.uvs.empty() && mesh.uvs.size() != count) return false;
    if (!mesh.colours.empty() && mesh.colours.size() != count) return false;
    prepared.mesh = mesh;
    prepared.normal_matrix = glm::transpose(glm::inverse(glm::mat3(mesh.model)));
    prepared.model_is_world = mesh.model == glm::mat4(1.0f);
    prepared.clip.resize(count);
    prepared.outcodes.resize(count);
    prepared.window.resize(count);
    // A grid hint that cannot be right is dropped (the full check is its maker's).
    if (mesh.grid_cols > 1 &&
        (count % static_cast<std::size_t>(mesh.grid_cols) != 0 ||
         mesh.triangles.size() != 2 * (count / static_cast<std::size_t>(mesh.grid_cols) - 1) *
                                      static_cast<std::size_t>(mesh.grid_cols - 1)))
        prepared.mesh.grid_cols = 0;
    const std::size_t snapped = prepared.mesh.grid_cols > 1 ? count : 0;
    prepared.snapped_x.resize(snapped);
    prepared.snapped_y.resize(snapped);
    prepared.width = width;
    prepared.height = height;
    prepared.eye = camera.position;
    prepared.with_uv = style.pattern != SurfacePattern::none && !mesh.uvs.empty();
    prepared.with_colour = !mesh.colours.empty();
    prepared.varying_stride =
        prepared.with_uv ? (prepared.with_colour ? SurfaceShader<true, true>::varying_count
                                                 : SurfaceShader<true, false>::varying_count)
                         : (prepared.with_colour ? SurfaceShader<false, true>::varying_count
                                                 : SurfaceShader<false, false>::varying_count);
    prepared.varyings_over_w.resize(count * static_cast<std::size_t>(prepared.varying_stride));
    const glm::mat4 view_projection = view_projection_matrix(camera, width, height);
    const bool with_avx2 = allow_avx2 && avx2_supported() && width <= largest_avx2_viewport_side &&
                           height <= largest_avx2_viewport_side;
    auto transform = [&](std::size_t begin, std::size_t end) {
        if (prepared.with_uv && prepared.with_colour)
            transform_vertices<true, true>(view_projection, prepared, begin, end, with_avx2);
        else if (prepared.with_uv)
            transform_vertices<true, false>(view_projection, prepared, begin, end, with_avx2);
        else if (prepared.with_colour)
            transform_vertices<false, true>(view_projection, prepared, begin, end, with_avx2);
        else
            transform_vertices<false, false>(view_projection, prepared, begin, end, with_avx2);
    };
    // Each vertex is written by one slice: the same values for any split.
    constexpr std::size_t min_vertices_for_threads = 4096;
    if (pool && pool->thread_count() > 1 && count >= min_vertices_for_threads)
        pool->parallel_for(count, transform);
    else
        transform(0, count);
    return true;
}

void draw_prepared_mesh(Framebuffer& framebuffer, const PreparedMesh& prepared,
                        const SurfaceStyle& style, const Lighting& lighting,
                        const PixelRect& scissor) {
    draw_prepared_triangles(
        framebuffer, prepared, style, lighting, scissor, [&](auto&& draw, auto&&) {
            for (std::size_t index = 0; index < prepared.mesh.triangles.size(); ++index)
                draw(index);
        });
}

PixelRect TriangleBands::band_rect(int band, int width, int height) const {
    return {0, std::min(band * band_height, height), width,
            std::min((band + 1) * band_height, height)};
}

void bin_triangles(const PreparedMesh& prepared, int band_height, TriangleBands& bands,
                   WorkerPool* pool, bool allow_avx2) {
    bands.band_height = std::max(band_height, 1);
    bands.band_count = std::max((prepared.height + bands.band_height - 1) / bands.band_height, 1);
    const std::size_t triangle_count = prepared.mesh.triangles.size();
    constexpr std::size_t min_triangles_for_threads = 4096;
    const bool threaded =
        pool && pool->thread_count() > 1 && triangle_count >= min_triangles_for_threads;
    bands.slice_count = threaded ? pool->thread_count() : 1;
    const auto list_count = static_cast<std::size_t>(bands.slice_count * bands.band_count);
    if (bands.lists.size() < list_count) bands.lists.resize(list_count);
    if (bands.fragments.size() < list_count) bands.fragments.resize(list_count);
    for (std::vector<std::uint32_t>& list : bands.lists) list.clear();
    for (std::vector<BinnedFragment>& list : bands.fragments) list.clear();
    // A fragment holds its pixel in 16 bits a coordinate and its triangle's index in 31.
    BinningChoice choice;
    choice.with_fragments = prepared.width <= 0xffff && prepared.height <= 0xffff &&
                            triangle_count <= BinnedFragment::front_bit;
    choice.with_avx2 = allow_avx2 && avx2_supported();
    if (!threaded) {
        bin_triangle_run(prepared, 0, triangle_count, 0, choice, bands);
        return;
    }
    // One run per slice, so each slice writes only its own lists. Slices start on a whole
    // group of triangles: a grid's groups must start on a cell (grid_group_fits), and one
    // offset by a triangle would classify every group of its slice by gathers. The lists
    // are read slice after slice, so the bands are the same for any split.
    const auto slices = static_cast<std::size_t>(bands.slice_count);
    auto slice_start = [&](std::size_t slice) {
        if (slice == slices) return triangle_count;
        const std::size_t start = triangle_count * slice / slices;
        return start - start % static_cast<std::size_t>(binning_group_size);
    };
    pool->parallel_for(slices, [&](std::size_t begin, std::size_t end) {
        for (std::size_t slice = begin; slice < end; ++slice)
            bin_triangle_run(prepared, slice_start(slice), slice_start(slice + 1),
                             static_cast<int>(slice), choice, bands);
    });
}

void draw_prepared_band(Framebuffer& framebuffer, const PreparedMesh& prepared,
                        const TriangleBands& bands, int band, const SurfaceStyle& style,
                        const Lighting& lighting) {
    if (band < 0 || band >= bands.band_count) return;
    const PixelRect rect = bands.band_rect(band, framebuffer.width(), framebuffer.height());
    draw_prepared_triangles(
        framebuffer, prepared, style, lighting, rect,
        [&](auto&& draw, auto&& shade) { visit_band(bands, band, draw, shade); });
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
