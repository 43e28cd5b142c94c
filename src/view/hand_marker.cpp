#include "view/hand_marker.h"

#include <glm/geometric.hpp>

#include "raster/line_renderer.h"

namespace weft::view {

void draw_hand_marker(raster::Framebuffer& framebuffer, const raster::Camera& camera,
                      const Grab& grab, const Cloth& cloth) {
    if (!grab.active()) return;
    // The grab point as the cloth has it: the held particle nearest to it, less its offset.
    std::size_t nearest = 0;
    for (std::size_t k = 1; k < grab.particles.size(); ++k)
        if (glm::length(grab.offsets[k]) < glm::length(grab.offsets[nearest])) nearest = k;
    const Vec3 held = cloth.positions[grab.particles[nearest]] - grab.offsets[nearest];
    const glm::vec3 hand(grab.target);
    const raster::Rgba8 colour{255, 210, 60, 255};  // amber: seen on the cloth and the sky
    raster::LineStyle style;
    style.depth_test = false;  // the hand is in front of whatever it holds
    style.depth_write = false;
    constexpr double shown_apart = 0.002;  // m: closer than this, the line is a dot
    if (glm::length(grab.target - held) > shown_apart) {
        const raster::LineSegment segment{hand, glm::vec3(held), colour, colour};
        raster::draw_lines(framebuffer, camera, {&segment, 1}, style);
    }
    raster::draw_points(framebuffer, camera, {&hand, 1}, colour, 9.0f, style);
}

}  // namespace weft::view
