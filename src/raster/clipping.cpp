#include "raster/clipping.h"

#include <algorithm>

namespace weft::raster {
namespace {

// Signed distance-like value of a vertex to one clipping plane: >= 0 inside.
float plane_distance(std::uint32_t plane, const glm::vec4& p) {
    switch (plane) {
        case outside_near:
            return p.z + p.w;
        case outside_w_min:
            return p.w - min_clip_w;
        case beyond_guard_left:
            return p.x + guard_band * p.w;
        case beyond_guard_right:
            return guard_band * p.w - p.x;
        case beyond_guard_bottom:
            return p.y + guard_band * p.w;
        case beyond_guard_top:
            return guard_band * p.w - p.y;
        default:
            return 0.0f;
    }
}

// The point where edge inside→outside crosses the plane. Always parameterised from the
// inside vertex, so both triangles sharing this edge compute bit-identical results.
void intersect(const ClipVertex& inside, float inside_distance, const ClipVertex& outside,
               float outside_distance, int varying_count, ClipVertex& out) {
    const float t = inside_distance / (inside_distance - outside_distance);
    out.position = inside.position + t * (outside.position - inside.position);
    for (int k = 0; k < varying_count; ++k) {
        out.varyings[k] = inside.varyings[k] + t * (outside.varyings[k] - inside.varyings[k]);
    }
}

// One Sutherland–Hodgman pass: keeps the part of polygon `in` on the inside of `plane`.
void clip_against_plane(std::uint32_t plane, const ClippedPolygon& in, int varying_count,
                        ClippedPolygon& out) {
    out.count = 0;
    if (in.count == 0) return;
    std::array<float, ClippedPolygon::max_vertices> distance;
    for (int i = 0; i < in.count; ++i) distance[i] = plane_distance(plane, in.vertices[i].position);

    for (int i = 0; i < in.count; ++i) {
        const int j = i + 1 == in.count ? 0 : i + 1;  // edge i → j
        const bool i_inside = distance[i] >= 0.0f, j_inside = distance[j] >= 0.0f;
        if (i_inside) out.vertices[out.count++] = in.vertices[i];
        if (i_inside != j_inside && out.count < ClippedPolygon::max_vertices) {
            if (i_inside) {
                intersect(in.vertices[i], distance[i], in.vertices[j], distance[j], varying_count,
                          out.vertices[out.count++]);
            } else {
                intersect(in.vertices[j], distance[j], in.vertices[i], distance[i], varying_count,
                          out.vertices[out.count++]);
            }
        }
    }
    if (out.count < 3) out.count = 0;
}

}  // namespace

void clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                   std::uint32_t planes, int varying_count, ClippedPolygon& out) {
    varying_count = std::clamp(varying_count, 0, max_varyings);
    ClippedPolygon scratch;
    ClippedPolygon* current = &out;
    ClippedPolygon* next = &scratch;
    current->vertices[0] = a;
    current->vertices[1] = b;
    current->vertices[2] = c;
    current->count = 3;

    // Near first: after it every vertex has w > 0, which the guard planes' tests rely on.
    constexpr std::uint32_t order[] = {outside_near,       outside_w_min,       beyond_guard_left,
                                       beyond_guard_right, beyond_guard_bottom, beyond_guard_top};
    for (std::uint32_t plane : order) {
        if ((planes & plane) == 0) continue;
        clip_against_plane(plane, *current, varying_count, *next);
        std::swap(current, next);
        if (current->count == 0) break;
    }
    if (current != &out) out = *current;
}

}  // namespace weft::raster
