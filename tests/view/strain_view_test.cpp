// The strain view of a flat sheet seen nearly edge-on — the default scene right after R —
// shows its springs, not the surface under them: every pixel a spring covers when drawn alone
// is that spring's colour over the shaded surface too (it was speckled with the surface's dark
// underside where the surface won the depth test).
#include <gtest/gtest.h>

#include "sim/core/simulation.h"
#include "sim/scene_io/scene_loader.h"
#include "view/frame_renderer.h"

namespace weft::view {
namespace {

TEST(StrainView, SpringsOfAnEdgeOnSheetAreNotSpeckledByItsSurface) {
    SceneLoadResult loaded =
        load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/hanging_sheet.toml", {});
    ASSERT_TRUE(loaded.ok());
    const Simulation simulation(*loaded.scene);  // flat, 10 cm above the camera's eye
    auto draw = [&](bool shaded) {
        raster::Framebuffer framebuffer(896, 720);
        ClothView view(simulation.cloth());
        FrameOptions options;
        options.strain_springs = true;
        options.shaded = shaded;
        options.ground = false;
        render_frame(framebuffer, scene_camera(simulation.scene()), simulation.cloth(), view,
                     options, -10.0f);
        return std::vector<raster::Rgba8>(framebuffer.colours().begin(),
                                          framebuffer.colours().end());
    };
    const auto over_surface = draw(true), alone = draw(false);
    const raster::Rgba8 background = FrameOptions{}.background;
    int spring_pixels = 0, hidden = 0;
    for (std::size_t p = 0; p < alone.size(); ++p) {
        if (alone[p] == background) continue;
        ++spring_pixels;
        if (!(over_surface[p] == alone[p])) ++hidden;
    }
    EXPECT_GT(spring_pixels, 5000);
    EXPECT_EQ(hidden, 0) << "of " << spring_pixels << " spring pixels";
}

}  // namespace
}  // namespace weft::view
