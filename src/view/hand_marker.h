// The user's hand over the cloth: a marker where the hand is, and a line from it to the point
// of the cloth it holds while the two differ (within a frame's move, or a patch held off its
// shape), so a pull shows what it holds.
#pragma once

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "sim/core/cloth.h"
#include "sim/interaction/grab.h"

namespace weft::view {

// Draws nothing while the hand holds nothing.
void draw_hand_marker(raster::Framebuffer& framebuffer, const raster::Camera& camera,
                      const Grab& grab, const Cloth& cloth);

}  // namespace weft::view
