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
#include "sim/simulation.h"

namespace weft::app {

// The cloth under a window point, if any (intact triangles only).
std::optional<RayHit> cloth_under_cursor(const Cloth& cloth, const raster::Camera& camera,
                                         int width, int height, const glm::vec2& window_point);

// Where the cursor ray meets the plane through `anchor` facing the camera: the grabbed
// point follows the cursor at the depth where it was grabbed.
std::optional<Vec3> point_on_grab_plane(const raster::Camera& camera, int width, int height,
                                        const glm::vec2& window_point, const Vec3& anchor);

// Whether the window segments a0-a1 and b0-b1 cross.
bool segments_cross(const glm::vec2& a0, const glm::vec2& a1, const glm::vec2& b0,
                    const glm::vec2& b1);

// The springs whose on-screen image crosses the cursor's stroke from `from` to `to`, as
// ascending edge keys (topology_edits.h).
std::vector<std::uint64_t> springs_along_stroke(const Cloth& cloth, const raster::Camera& camera,
                                                int width, int height, const glm::vec2& from,
                                                const glm::vec2& to);

// Cuts the springs whose on-screen image crosses the cursor's stroke from `from` to `to`.
// Returns the number cut.
std::size_t cut_along_stroke(Simulation& simulation, const raster::Camera& camera, int width,
                             int height, const glm::vec2& from, const glm::vec2& to);

}  // namespace weft::app
