// Framing: where the camera goes so that a box — the cloth's current extent — fills the view
// with a margin, as Home does in a model viewer. The camera keeps the direction it is given
// and its field of view and only moves along that direction. SDL-free, so it is tested.
#pragma once

#include <span>

#include <glm/vec3.hpp>

#include "app/camera_rig.h"
#include "sim/core/cloth.h"

namespace weft::app {

// An axis-aligned box, m.
struct Box {
    glm::vec3 low{0.0f};
    glm::vec3 high{0.0f};

    glm::vec3 centre() const { return 0.5f * (low + high); }
};

// The box around `positions` (empty: a point at the origin).
Box bounding_box(std::span<const Vec3> positions);

// The box around the cloth's largest piece: the particles that springs still join, the most
// of them (the first such piece on a tie). A whole cloth is one piece; after a cut or a tear
// it is the sheet, not a scrap that fell away, that Home frames. Particles not at a finite
// position are left out (a point at the origin if none is).
Box largest_piece_box(const Cloth& cloth);

// Share of the view's half-width and half-height left empty around the framed box: 10 %.
inline constexpr float frame_margin = 0.1f;

// `rig` moved along its own viewing direction so it looks at the box's centre from the
// least distance at which all eight corners project inside a view `aspect` (width / height)
// wide, with `margin` of each half-extent left free: the corner that decides the distance
// lands on that inner border, the others inside it. Direction and fov are kept.
CameraRig framed(const CameraRig& rig, const Box& box, float aspect, float margin = frame_margin);

}  // namespace weft::app
