// Mesh drawing with two-sided lighting, for the cloth and the colliders.
//
// The shading model: one directional light plus ambient (and a weak fill from the eye, see
// Lighting). Lambert diffuse and a soft Blinn–Phong highlight, evaluated per pixel from the
// interpolated normal; the normal is
// flipped on back faces so both sides of the cloth are lit as the side facing the camera.
// The two sides get distinct colours, and an optional checker or stripe pattern from the
// (u, v) coordinates makes folds and stretching readable.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "parallel/worker_pool.h"
#include "raster/camera.h"
#include "raster/clipping.h"
#include "raster/framebuffer.h"
#include "raster/mesh.h"
#include "raster/pixel_rect.h"
#include "raster/triangle_setup.h"

namespace weft::raster {

enum class SurfacePattern { none, checker, stripes };

struct SurfaceStyle {
    glm::vec3 front_colour{0.86f, 0.38f, 0.24f};  // terracotta
    glm::vec3 back_colour{0.26f, 0.48f, 0.78f};   // steel blue: the underside reads at a glance
    SurfacePattern pattern = SurfacePattern::none;
    float pattern_frequency = 8.0f;  // cells (or stripes) per unit of u and of v
    float pattern_contrast = 0.3f;   // alternate cells are this fraction darker
    float specular_strength = 0.2f;
    float shininess = 16.0f;  // Blinn–Phong exponent; low keeps the highlight broad and soft
};

struct Lighting {
    glm::vec3 direction_to_light{0.36f, 0.80f, 0.48f};  // world space; normalised when used
    glm::vec3 light_colour{0.85f, 0.85f, 0.82f};
    glm::vec3 ambient_colour{0.22f, 0.22f, 0.25f};
    // A weak diffuse light at the eye. Whichever side of the cloth faces away from the main
    // light would otherwise get only flat ambient and lose its folds; this keeps their shape
    // readable from any viewpoint. Zero turns it off.
    glm::vec3 eye_fill_colour{0.22f, 0.22f, 0.22f};
};

// Base-colour multiplier of the pattern at (u, v): 1, or 1 - contrast on alternate cells.
float pattern_factor(const SurfaceStyle& style, const glm::vec2& uv);

// The lit colour of one surface point (unclamped RGB), exactly as draw_mesh shades each
// pixel. `normal` is the interpolated vertex normal (pointing out of the front; need not be
// unit length), `to_eye` the unit vector from the point towards the eye. Back faces use the
// flipped normal. The highlight is skipped where it would stay below half an 8-bit step.
glm::vec3 shade_surface(const SurfaceStyle& style, const Lighting& lighting,
                        const glm::vec3& base_colour, const glm::vec3& normal,
                        const glm::vec3& to_eye, bool front_facing);

// Draws every triangle of the mesh, depth-tested, both sides. Returns false (drawing
// nothing) if the per-vertex arrays do not match positions in size; triangles with an index
// out of range are skipped. Allocates once per call (the transformed vertices), nothing per
// triangle.
bool draw_mesh(Framebuffer& framebuffer, const Camera& camera, const MeshView& mesh,
               const SurfaceStyle& style, const Lighting& lighting,
               const PixelRect& scissor = PixelRect::unbounded());

// A mesh's vertices transformed once for one camera and framebuffer size — clip position,
// frustum outcodes, snapped window position and varyings divided by w — so that one draw can be
// split into bands of the framebuffer, drawn by several threads, without transforming twice. It
// refers to the mesh's arrays (a triangle that needs clipping takes its varyings from them), so
// the MeshView's arrays must outlive it. Kept between frames, it allocates only when the mesh
// grows.
struct PreparedMesh {
    MeshView mesh;
    glm::mat3 normal_matrix{1.0f};  // of mesh.model
    bool model_is_world = true;     // mesh.model is the identity
    std::vector<glm::vec4> clip;    // each vertex in clip space
    std::vector<std::uint32_t> outcodes;
    // Each vertex through the divide, viewport and snap (meaningless where it needs clipping).
    std::vector<WindowVertex> window;
    // The x and y of each window vertex, on their own (32 bits hold them inside the guard
    // band): what binning reads of a whole grid (binning_avx2.h). Written where `window` is,
    // for a mesh marked as a whole grid (MeshView::grid_cols); empty for any other.
    std::vector<std::int32_t> snapped_x, snapped_y;
    // Each vertex's varyings divided by its w, varying_stride of them per vertex, as the
    // rasterizer interpolates them (meaningless where it needs clipping).
    std::vector<float> varyings_over_w;
    int varying_stride = 0;
    int width = 0, height = 0;  // of the framebuffer it was prepared for
    glm::vec3 eye{0.0f};        // camera position, for the shader's view vector
    bool with_uv = false, with_colour = false;
};

// Transforms the mesh as draw_mesh does, splitting the vertices between the pool's threads
// when there is one. False (and nothing prepared) when draw_mesh would refuse the mesh.
// `allow_avx2`: the positions go through vertex_transform_avx2.h where the CPU runs it (the
// same bits; false for the tests that compare).
bool prepare_mesh(const Camera& camera, int width, int height, const MeshView& mesh,
                  const SurfaceStyle& style, PreparedMesh& prepared, WorkerPool* pool = nullptr,
                  bool allow_avx2 = true);

// Draws a prepared mesh inside `scissor`: exactly the pixels draw_mesh would draw there.
// Triangles whose vertices all lie more than a pixel above or below the scissor are
// rejected before setup, so a band costs little more than the triangles that cross it.
void draw_prepared_mesh(Framebuffer& framebuffer, const PreparedMesh& prepared,
                        const SurfaceStyle& style, const Lighting& lighting,
                        const PixelRect& scissor = PixelRect::unbounded());

// A prepared mesh's triangles sorted into horizontal bands of the framebuffer, so that a
// frame can be cut into many thin bands — an even share for every thread wherever the mesh
// lies on screen — without every band testing every triangle. Kept between frames, it
// allocates only when a list outgrows what it held before.
struct TriangleBands {
    int band_height = 0;  // rows; the last band may be shorter
    int band_count = 0;
    int slice_count = 0;  // the triangles were binned in this many consecutive runs
    // The triangles of run s that may reach band b, in ascending order:
    // lists[s * band_count + b]. Run after run, they are in the mesh's own order.
    std::vector<std::vector<std::uint32_t>> lists;
    // The pixel centres of band b that run s's tiny triangles cover (triangle_setup.h), in the
    // order of their triangles and, within one, in the pixel loop's order:
    // fragments[s * band_count + b]. A tiny triangle is in no list above: these say all that
    // drawing it needs.
    std::vector<std::vector<BinnedFragment>> fragments;

    PixelRect band_rect(int band, int width, int height) const;
};

// Visits what band `band` holds in the mesh's order, run after run: draw(index) for each
// binned triangle and shade(fragment) for each binned fragment.
template <class Draw, class Shade>
void visit_band(const TriangleBands& bands, int band, Draw&& draw, Shade&& shade) {
    for (int slice = 0; slice < bands.slice_count; ++slice) {
        const auto list = static_cast<std::size_t>(slice * bands.band_count + band);
        const std::vector<std::uint32_t>& triangles = bands.lists[list];
        const std::vector<BinnedFragment>& fragments = bands.fragments[list];
        std::size_t next = 0;
        for (const BinnedFragment& fragment : fragments) {
            for (; next < triangles.size() && triangles[next] < fragment.triangle_index(); ++next)
                draw(triangles[next]);
            shade(fragment);
        }
        for (; next < triangles.size(); ++next) draw(triangles[next]);
    }
}

// Sorts the prepared mesh's triangles into bands of `band_height` rows, splitting the
// triangles between the pool's threads in consecutive runs. Triangles that would draw
// nothing (culled, of zero area once snapped, or between pixel centres) go into no band;
// those that need clipping into all; tiny ones (a box of at most 2×2 pixel centres) are set
// up once here and go in as the pixels they cover. With `allow_avx2`, where the CPU has it,
// triangles are classified eight at a time (binning_avx2.h); the bands are the same either way.
void bin_triangles(const PreparedMesh& prepared, int band_height, TriangleBands& bands,
                   WorkerPool* pool = nullptr, bool allow_avx2 = true);

// Draws band `band` of a prepared mesh from its binned triangles: exactly the pixels that
// draw_prepared_mesh draws with the band's rows as scissor, in the same order.
void draw_prepared_band(Framebuffer& framebuffer, const PreparedMesh& prepared,
                        const TriangleBands& bands, int band, const SurfaceStyle& style,
                        const Lighting& lighting);

}  // namespace weft::raster
