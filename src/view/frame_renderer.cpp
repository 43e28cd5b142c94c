#include "view/frame_renderer.h"

#include <algorithm>
#include <atomic>
#include <optional>

#include "raster/ground_grid.h"
#include "raster/line_renderer.h"
#include "raster/planar_shadow.h"
#include "raster/sphere.h"
#include "sim/collision/floor.h"

namespace weft::view {

raster::SurfaceStyle FrameOptions::default_surface() {
    raster::SurfaceStyle style;
    style.pattern = raster::SurfacePattern::checker;
    style.pattern_frequency = 10.0f;  // cells per metre of rest fabric: 10 cm squares
    style.pattern_contrast = 0.25f;
    return style;
}

raster::Camera scene_camera(const Scene& scene) {
    auto to_vec3 = [](const Vec3d& v) {
        return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]),
                         static_cast<float>(v[2]));
    };
    return raster::make_camera(to_vec3(scene.camera.position), to_vec3(scene.camera.target),
                               static_cast<float>(scene.camera.fov_degrees));
}

namespace {

// Rows per band of the frame: a band's colours and depths fit a core's L2 cache at 1280
// wide, a cloth across part of the screen spreads over several bands, and each band's
// own work (clearing, the grids' transform) stays small.
constexpr int frame_band_rows = 32;

}  // namespace

float ground_height_below(const Cloth& cloth, std::span<const Collider> colliders) {
    // The grid is drawn where the floor is, or would be (floor.h).
    return static_cast<float>(floor_height(cloth, colliders));
}

void render_frame(raster::Framebuffer& framebuffer, const raster::Camera& camera,
                  const Cloth& cloth, ClothView& view, const FrameOptions& options,
                  float ground_height, std::span<const Collider> colliders, WorkerPool* pool) {
    // Everything shared by the bands is worked out first, once: the view of the cloth, the
    // transformed mesh, the lighting and the per-line colours.
    view.update(cloth, pool);
    raster::Lighting lighting = options.lighting;
    if (options.light_over_shoulder) {
        // A key light above and behind the viewer's right shoulder: whichever side of the
        // cloth faces the camera is lit, as a photographer would light fabric.
        const raster::CameraBasis basis = raster::camera_basis(camera);
        lighting.direction_to_light = -basis.forward + 0.9f * basis.up + 0.5f * basis.right;
    }
    raster::PreparedMesh& cloth_mesh = view.prepared_mesh();
    const bool cloth_drawn =
        options.shaded && raster::prepare_mesh(camera, framebuffer.width(), framebuffer.height(),
                                               view.mesh(), options.surface, cloth_mesh, pool);
    raster::SurfaceStyle collider_style;
    collider_style.front_colour = collider_style.back_colour = {0.62f, 0.64f, 0.68f};
    static const raster::TriangleMesh unit_sphere = raster::make_uv_sphere(48, 24);
    // Spheres transformed once, too. Drawn 1.5 % small: cloth resting on the sphere is flat
    // between its particles, and a full-size ball would show through the middle of every
    // triangle on top of it.
    std::vector<raster::PreparedMesh>& spheres = view.collider_meshes();
    std::size_t sphere_count = 0;
    if (options.shaded) {
        for (const Collider& collider : colliders) {
            if (collider.type != ColliderType::sphere) continue;
            if (spheres.size() <= sphere_count) spheres.resize(sphere_count + 1);
            if (raster::prepare_mesh(
                    camera, framebuffer.width(), framebuffer.height(),
                    raster::sphere_view(unit_sphere, glm::vec3(collider.center),
                                        0.985f * static_cast<float>(collider.radius)),
                    collider_style, spheres[sphere_count]))
                ++sphere_count;
        }
    }
    // Shadows on the ground from the key light: the cloth and the spheres flattened onto the
    // floor, drawn first, a few millimetres below it so that the grid's lines and anything
    // resting on the floor stay in front of them.
    constexpr float shadow_below_ground = 0.003f;  // m
    const std::optional<glm::mat4> onto_ground =
        options.shaded && options.ground && options.shadows
            ? raster::shadow_projection(lighting.direction_to_light,
                                        ground_height - shadow_below_ground)
            : std::nullopt;
    raster::PreparedMesh& cloth_shadow = view.shadow_mesh();
    std::vector<raster::PreparedMesh>& sphere_shadows = view.collider_shadows();
    if (onto_ground) {
        if (cloth_drawn) {
            raster::MeshView flattened = view.shadow_caster();
            flattened.model = *onto_ground * flattened.model;
            raster::prepare_flat_mesh(camera, framebuffer.width(), framebuffer.height(), flattened,
                                      cloth_shadow, pool, view.shadow_vertices());
        }
        if (sphere_shadows.size() < sphere_count) sphere_shadows.resize(sphere_count);
        for (std::size_t k = 0; k < sphere_count; ++k) {
            raster::MeshView flattened = spheres[k].mesh;
            flattened.model = *onto_ground * flattened.model;
            raster::prepare_flat_mesh(camera, framebuffer.width(), framebuffer.height(), flattened,
                                      sphere_shadows[k]);
        }
    }
    std::span<const raster::Rgba8> spring_colours, particle_colours;
    if (options.strain_springs) spring_colours = view.spring_colours(cloth);
    if (options.particles) particle_colours = view.particle_colours(cloth);

    // The frame is drawn in bands of rows, each whole — clear, grids, spheres, cloth — by
    // one thread: a band's colours and depths (about 330 KB at 1280 wide) stay in that
    // core's cache from the clear to the last triangle, where a clear of the whole frame
    // first would leave every depth test a miss. The cloth's triangles are binned by band
    // once, so a band visits only its own. Each pixel sees the same sequence of writes
    // whatever the number of threads, hence the same image, bit for bit (tested).
    const int width = framebuffer.width(), height = framebuffer.height();
    const int band_count = (height + frame_band_rows - 1) / frame_band_rows;
    raster::TriangleBands& cloth_bands = view.triangle_bands();
    if (cloth_drawn) raster::bin_triangles(cloth_mesh, frame_band_rows, cloth_bands, pool);
    raster::TriangleBands& shadow_bands = view.shadow_bands();
    if (onto_ground && cloth_drawn)
        raster::bin_triangles(cloth_shadow, frame_band_rows, shadow_bands, pool);
    // The grids' lines, set up once and walked in every band: the ground's, then planes that
    // are not the ground (a slope, a wall) as a grid of their own.
    std::vector<raster::PreparedLine>& grid_lines = view.grid_lines();
    grid_lines.clear();
    const float line_depth_bias = raster::LineStyle{}.depth_bias;
    if (options.ground) {
        raster::GroundGrid grid;
        grid.height = ground_height;
        raster::prepare_ground_grid(framebuffer, camera, grid, line_depth_bias, grid_lines);
    }
    for (const Collider& collider : colliders) {
        if (collider.type != ColliderType::plane || is_ground_plane(collider)) continue;
        raster::PlaneGrid grid =
            raster::PlaneGrid::facing(glm::vec3(collider.point), glm::vec3(collider.normal));
        grid.cell_count = 8;  // 2 m: the plane is endless, its grid need not be
        grid.colour = {150, 120, 90, 255};
        grid.centre_colour = {190, 150, 110, 255};
        raster::prepare_plane_grid(framebuffer, camera, grid, line_depth_bias, grid_lines);
    }
    // Each thread draws its bands through a band view of the frame, whose depths are its own
    // and stay in its cache. They go into the frame's once the band is done only if the
    // lines drawn over the whole frame test against them, or the caller keeps them: writing
    // them out would cost much of what the view saves.
    // A thread of the fabric's colour where springs are not drawn anyway: a piece hanging by
    // it must not seem to float.
    const bool lone_springs_drawn = !options.strain_springs &&
                                    (options.shaded || options.wireframe) &&
                                    !view.lone_springs().empty();
    const bool lines_drawn =
        options.wireframe || options.strain_springs || options.particles || lone_springs_drawn;
    const bool depths_kept = options.keep_depths || lines_drawn;
    const int threads = pool ? pool->thread_count() : 1;
    auto draw_band = [&](int band) {
        // The depths belong to the thread, not to the frame or to a slice of the pool's
        // loop: whichever thread claims a slice, the storage it draws into is the one its
        // core cached for its last band.
        thread_local std::vector<float> depth_storage;
        const raster::PixelRect rect{0, band * frame_band_rows, width,
                                     std::min((band + 1) * frame_band_rows, height)};
        raster::Framebuffer target =
            raster::Framebuffer::band_view(framebuffer, rect.y_begin, rect.y_end, depth_storage);
        target.clear(options.background, raster::Framebuffer::far_depth, rect);
        if (onto_ground) {
            for (std::size_t k = 0; k < sphere_count; ++k)
                raster::draw_flat_mesh(target, sphere_shadows[k], options.shadow_colour, rect);
            if (cloth_drawn)
                raster::draw_flat_band(target, cloth_shadow, shadow_bands, band,
                                       options.shadow_colour);
        }
        raster::LineStyle lines;
        lines.scissor = rect;
        raster::draw_prepared_lines(target, grid_lines, lines);
        for (std::size_t k = 0; k < sphere_count; ++k)
            raster::draw_prepared_mesh(target, spheres[k], collider_style, lighting, rect);
        if (cloth_drawn)
            raster::draw_prepared_band(target, cloth_mesh, cloth_bands, band, options.surface,
                                       lighting);
        if (depths_kept) target.write_back_depths();
    };

    // Lines and points come last, over the whole frame on the calling thread: every band
    // would transform all their vertices again, which costs more than drawing them once.
    auto draw_lines = [&] {
        raster::LineStyle lines;
        lines.on_surface = true;  // all of them lie in the cloth's surface
        if (options.wireframe)
            raster::draw_indexed_lines(framebuffer, camera, view.positions(),
                                       view.wireframe_edges(), raster::Rgba8{20, 20, 24, 255},
                                       lines);
        if (options.strain_springs)
            raster::draw_indexed_lines(framebuffer, camera, view.positions(), view.spring_lines(),
                                       spring_colours, lines);
        else if (lone_springs_drawn)
            raster::draw_indexed_lines(framebuffer, camera, view.positions(), view.lone_springs(),
                                       raster::to_rgba8(options.surface.front_colour), lines);
        if (options.particles)
            raster::draw_points(framebuffer, camera, view.positions(), particle_colours, 4.0f,
                                lines);
    };

    if (threads <= 1) {
        for (int band = 0; band < band_count; ++band) draw_band(band);
    } else {
        // Bands are claimed, not dealt: a thread that finishes a cheap band (sky) takes the
        // next one, so a cloth across part of the screen is still shared evenly.
        std::atomic<int> next_band{0};
        pool->parallel_for(static_cast<std::size_t>(threads), [&](std::size_t, std::size_t) {
            for (int band = next_band.fetch_add(1); band < band_count;
                 band = next_band.fetch_add(1))
                draw_band(band);
        });
    }
    draw_lines();
}

}  // namespace weft::view
