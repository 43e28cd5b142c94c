// One frame of weft: clear, shadows, ground grid, shaded cloth, optional wireframe /
// strain-coloured springs / particles. The headless screenshot and the window draw through this
// same code.
#pragma once

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "raster/mesh_renderer.h"
#include "sim/collision/colliders.h"
#include "sim/core/cloth.h"
#include "sim/scene/scene.h"
#include "view/cloth_view.h"

namespace weft::view {

struct FrameOptions {
    bool shaded = true;           // the lit, two-sided cloth surface
    bool wireframe = false;       // triangle edges over the surface
    bool strain_springs = false;  // every spring as a line coloured by its strain
    bool particles = false;       // particles as points, pinned ones highlighted
    bool ground = true;           // the ground grid
    bool shadows = true;          // the cloth's and spheres' shadows on the ground, from the key
                                  // light (drawn only with the ground)
    raster::SurfaceStyle surface = default_surface();
    raster::Lighting lighting;
    bool light_over_shoulder = true;  // overrides lighting.direction_to_light to follow the camera
    raster::Rgba8 background{28, 30, 36, 255};
    raster::Rgba8 shadow_colour{16, 17, 21, 255};  // the background in shadow
    // Whether the framebuffer's depths must hold the frame's afterwards (render_frame).
    bool keep_depths = false;

    static raster::SurfaceStyle default_surface();
};

// The scene's [camera] as the rasterizer's camera.
raster::Camera scene_camera(const Scene& scene);

// Where the ground grid goes: on the floor, the scene's ground plane or the one the simulation
// adds (sim/collision/floor.h), or where that floor would be in a scene without one.
float ground_height_below(const Cloth& cloth, std::span<const Collider> colliders = {});

// Draws the frame; spheres among `colliders` are drawn as shaded balls (planes show as the
// ground grid). The framebuffer is drawn in bands of 32 rows, each whole (clear, grids,
// spheres, the cloth's triangles binned to it) by one thread — with a pool of several, the
// threads claim bands in turn — then the lines and points over the whole frame: the image
// is the same, pixel for pixel, whatever the number of threads. A band's depths stay in its
// thread's cache; they are written to the framebuffer only where lines or points are drawn
// over the frame, or with keep_depths. Otherwise the framebuffer's depths are left as they
// were.
void render_frame(raster::Framebuffer& framebuffer, const raster::Camera& camera,
                  const Cloth& cloth, ClothView& view, const FrameOptions& options,
                  float ground_height, std::span<const Collider> colliders = {},
                  WorkerPool* pool = nullptr);

}  // namespace weft::view
