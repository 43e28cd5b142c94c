// The frame drawn in bands by several threads against the same frame on one thread: the
// same pixels and depths, bit for bit, with every layer the frame can hold.
#include <gtest/gtest.h>

#include <algorithm>

#include "sim/core/simulation.h"
#include "sim/scene_io/scene_loader.h"
#include "view/frame_renderer.h"

namespace weft::view {
namespace {

struct Frame {
    std::vector<raster::Rgba8> colours;
    std::vector<float> depths;
};

// The frame with its depths kept (FrameOptions::keep_depths), so that they can be compared.
Frame draw(const Simulation& simulation, FrameOptions options, int width, int height,
           WorkerPool* pool, const Scene* camera_scene = nullptr) {
    raster::Framebuffer framebuffer(width, height);
    ClothView view(simulation.cloth());
    options.keep_depths = true;
    render_frame(framebuffer, scene_camera(camera_scene ? *camera_scene : simulation.scene()),
                 simulation.cloth(), view, options,
                 ground_height_below(simulation.cloth(), simulation.colliders()),
                 simulation.colliders(), pool);
    return {{framebuffer.colours().begin(), framebuffer.colours().end()},
            {framebuffer.depths().begin(), framebuffer.depths().end()}};
}

TEST(FrameRenderer, BandsOnSeveralThreadsDrawTheSameImageAsOneThread) {
    SceneLoadResult loaded =
        load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/sheet_on_sphere.toml", {});
    ASSERT_TRUE(loaded.ok());
    Simulation simulation(*loaded.scene);
    for (int s = 0; s < 400; ++s) simulation.step();  // draped over the ball: folds, overlaps
    FrameOptions everything;
    everything.wireframe = everything.strain_springs = everything.particles = true;
    for (const FrameOptions& options : {FrameOptions{}, everything}) {
        for (auto [width, height] : {std::pair{320, 240}, std::pair{333, 187}}) {
            const Frame one = draw(simulation, options, width, height, nullptr);
            ASSERT_GT(std::count_if(one.depths.begin(), one.depths.end(),
                                    [](float depth) { return depth < 1.0f; }),
                      width * height / 10);  // the cloth and the ball fill part of the frame
            // The ball and the cloth cast a shadow on the floor (drawn in every band).
            EXPECT_GT(std::count(one.colours.begin(), one.colours.end(), options.shadow_colour),
                      width * height / 50);
            for (int threads : {2, 3, 4}) {
                WorkerPool pool(threads);
                const Frame banded = draw(simulation, options, width, height, &pool);
                EXPECT_TRUE(banded.colours == one.colours)
                    << threads << " threads, " << width << "x" << height;
                EXPECT_TRUE(banded.depths == one.depths)
                    << threads << " threads, " << width << "x" << height;
            }
        }
    }
}

// Without keep_depths and with nothing drawn over the frame, the bands' depths stay with the
// threads: the same colours, and the framebuffer's depths as they were.
TEST(FrameRenderer, DepthsAreWrittenOutOnlyWhenKeptOrWhenLinesTestAgainstThem) {
    SceneLoadResult loaded =
        load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/sheet_on_sphere.toml", {});
    ASSERT_TRUE(loaded.ok());
    Simulation simulation(*loaded.scene);
    for (int s = 0; s < 100; ++s) simulation.step();
    FrameOptions with_points;
    with_points.particles = true;
    for (const FrameOptions& options : {FrameOptions{}, with_points}) {
        const Frame kept = draw(simulation, options, 160, 120, nullptr);
        for (int threads : {1, 2}) {
            WorkerPool pool(threads);
            raster::Framebuffer framebuffer(160, 120);
            framebuffer.clear(raster::Rgba8{0, 0, 0, 255}, 0.5f);
            ClothView view(simulation.cloth());
            render_frame(framebuffer, scene_camera(simulation.scene()), simulation.cloth(), view,
                         options, ground_height_below(simulation.cloth(), simulation.colliders()),
                         simulation.colliders(), &pool);
            EXPECT_TRUE(
                std::equal(kept.colours.begin(), kept.colours.end(), framebuffer.colours().begin()))
                << threads << " threads";
            if (options.particles) {
                // The points are depth-tested against the surface: its depths were written.
                EXPECT_TRUE(std::equal(kept.depths.begin(), kept.depths.end(),
                                       framebuffer.depths().begin()))
                    << threads << " threads";
            } else {
                EXPECT_EQ(
                    std::count(framebuffer.depths().begin(), framebuffer.depths().end(), 0.5f),
                    160 * 120)
                    << threads << " threads";
            }
        }
    }
}

// A sheet big enough for its triangles to be binned by several threads (4096 or more), seen
// from a camera among its particles: triangles behind the camera, triangles crossing its
// near plane (clipped, so binned into every band), and a cloth across most of the frame.
TEST(FrameRenderer, ALargeSheetSeenFromInsideIsTheSameOnAnyThreadCount) {
    SceneLoadResult loaded = load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/hanging_sheet.toml",
                                             {"cloth.rows=64", "cloth.cols=64"});
    ASSERT_TRUE(loaded.ok());
    Scene scene = *loaded.scene;
    Simulation simulation(scene);
    for (int s = 0; s < 300; ++s) simulation.step();
    // Between the particles of the sheet's middle, looking along it towards a corner.
    const Cloth& cloth = simulation.cloth();
    const Vec3 middle = cloth.positions[32 * 64 + 32], corner = cloth.positions[63 * 64 + 63];
    scene.camera.position = {middle.x, middle.y + 0.01, middle.z};
    scene.camera.target = {corner.x, corner.y, corner.z};
    ASSERT_GE(2 * 63 * 63, 4096);
    const Frame one = draw(simulation, FrameOptions{}, 400, 300, nullptr, &scene);
    ASSERT_GT(std::count_if(one.depths.begin(), one.depths.end(),
                            [](float depth) { return depth < 1.0f; }),
              400 * 300 / 8);
    // Some of its triangles do cross the near plane.
    ClothView view(cloth);
    view.update(cloth);
    raster::PreparedMesh prepared;
    ASSERT_TRUE(raster::prepare_mesh(scene_camera(scene), 400, 300, view.mesh(),
                                     FrameOptions::default_surface(), prepared));
    const auto clipped = std::count_if(
        prepared.mesh.triangles.begin(), prepared.mesh.triangles.end(),
        [&](const raster::TriangleIndices& t) {
            return raster::TriangleOutcodes{prepared.outcodes[t[0]], prepared.outcodes[t[1]],
                                            prepared.outcodes[t[2]]}
                .needs_clipping();
        });
    EXPECT_GT(clipped, 0);
    for (int threads : {2, 3}) {
        WorkerPool pool(threads);
        const Frame banded = draw(simulation, FrameOptions{}, 400, 300, &pool, &scene);
        EXPECT_TRUE(banded.colours == one.colours) << threads << " threads";
        EXPECT_TRUE(banded.depths == one.depths) << threads << " threads";
    }
}

}  // namespace
}  // namespace weft::view
