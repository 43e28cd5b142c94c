// The user's hand on the cloth, in window terms: where a drag holds the cloth, which springs
// a cut stroke crosses, which particle is under the cursor. SDL-free (the window turns
// mouse events into these calls), so it is unit-tested.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "raster/camera.h"
#include "sim/core/simulation.h"

namespace weft::app {

// The cloth under a window point, if any (intact triangles only).
std::optional<RayHit> cloth_under_cursor(const Cloth& cloth, const raster::Camera& camera,
                                         int width, int height, const glm::vec2& window_point);

// Where the cursor ray meets the plane through `anchor` facing the camera: the grabbed
// point follows the cursor at the depth where it was grabbed.
std::optional<Vec3> point_on_grab_plane(const raster::Camera& camera, int width, int height,
                                        const glm::vec2& window_point, const Vec3& anchor);

// Each particle's place in the window (none for those behind the camera).
using ScreenPoints = std::vector<std::optional<glm::vec2>>;
ScreenPoints particles_on_screen(const Cloth& cloth, const raster::Camera& camera, int width,
                                 int height);

// A spring's image in the window, from end a to end b.
struct ScreenSegment {
    glm::vec2 a;
    glm::vec2 b;
};

// Whether the cursor, going straight from `from` to `to` while a spring's image moved
// straight from `before` to `now` over the same time, passed over the spring (touching it
// counts). With `before` equal to `now` this is whether two segments cross.
bool cursor_passes_spring(const glm::vec2& from, const glm::vec2& to, const ScreenSegment& before,
                          const ScreenSegment& now);

// The springs the cursor passed over going from `from` to `to`, while the particles moved
// from `before` to `now` in the window, as ascending edge keys (topology_edits.h). The cloth
// moves between two motion events; testing the stroke against where it is now alone let a
// spring swinging toward the cursor jump from ahead of it to behind it unseen.
std::vector<std::uint64_t> springs_along_stroke(const Cloth& cloth, const ScreenPoints& before,
                                                const ScreenPoints& now, const glm::vec2& from,
                                                const glm::vec2& to);

// The same for a cloth standing still under the stroke.
std::vector<std::uint64_t> springs_along_stroke(const Cloth& cloth, const raster::Camera& camera,
                                                int width, int height, const glm::vec2& from,
                                                const glm::vec2& to);

// Cuts the springs whose on-screen image crosses the cursor's stroke from `from` to `to`, the
// cloth standing still. Returns the number cut.
std::size_t cut_along_stroke(Simulation& simulation, const raster::Camera& camera, int width,
                             int height, const glm::vec2& from, const glm::vec2& to);

}  // namespace weft::app
