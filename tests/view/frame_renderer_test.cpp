// The frame drawn in bands by several threads against the same frame on one thread: the
// same pixels and depths, bit for bit, with every layer the frame can hold.
#include <gtest/gtest.h>

#include <algorithm>

#include "sim/scene_loader.h"
#include "sim/simulation.h"
#include "view/frame_renderer.h"

namespace weft::view {
namespace {

struct Frame {
    std::vector<raster::Rgba8> colours;
    std::vector<float> depths;
};

Frame draw(const Simulation& simulation, const FrameOptions& options, int width, int height,
           WorkerPool* pool) {
    raster::Framebuffer framebuffer(width, height);
    ClothView view(simulation.cloth());
    render_frame(framebuffer, scene_camera(simulation.scene()), simulation.cloth(), view, options,
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

}  // namespace
}  // namespace weft::view
