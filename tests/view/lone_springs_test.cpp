// Springs the shaded surface does not show: none on a whole sheet, the ones crossing a hole
// after a cut, and a piece's last spring drawn as a line in the shaded view.
#include <gtest/gtest.h>

#include <algorithm>

#include "sim/build/cloth_builder.h"
#include "sim/scene_io/scene_loader.h"
#include "view/cloth_view.h"
#include "view/frame_renderer.h"

namespace weft::view {
namespace {

Scene sheet(Layout layout, Orientation orientation) {
    Scene scene;
    scene.cloth.rows = 9;
    scene.cloth.cols = 7;
    scene.cloth.layout = layout;
    scene.cloth.orientation = orientation;
    scene.shear.enabled = scene.bend.enabled = true;
    return scene;
}

TEST(LoneSprings, NoneOnAWholeSheet) {
    for (Layout layout : {Layout::grid, Layout::offset})
        for (Orientation orientation : {Orientation::vertical, Orientation::horizontal}) {
            const Cloth cloth = build_cloth(sheet(layout, orientation));
            ASSERT_GT(cloth.spring_count(), 100u);
            EXPECT_TRUE(ClothView(cloth).lone_springs().empty());
        }
}

// The shipped meshes (a flat disc in triangles; a flag with a hole and a skirt in quads, the
// skirt curved, where its bend springs leave the planes of its triangles): whole, no spring
// is lone; a piece cut off but for one bend spring hangs by a lone one.
TEST(LoneSprings, MeshesByTopology) {
    for (const char* name : {"round_tablecloth", "flag_with_hole", "skirt"}) {
        SceneLoadResult loaded =
            load_scene_file(std::string(WEFT_SOURCE_DIR "/assets/scenes/") + name + ".toml");
        ASSERT_TRUE(loaded.ok()) << loaded.error->message();
        Cloth cloth = build_cloth(*loaded.scene);
        ASSERT_GT(cloth.mesh_extent, 0.0);
        EXPECT_TRUE(ClothView(cloth).lone_springs().empty()) << name;
        // Every triangle at the far end of the first bend spring goes: the spring no longer
        // touches the surface there.
        const Spring bend = cloth.find_group(SpringFamily::bend)->springs.front();
        std::erase_if(cloth.edit_topology().triangles, [&](const Triangle& t) {
            return t.a == bend.j || t.b == bend.j || t.c == bend.j;
        });
        const ClothView cut(cloth);
        EXPECT_TRUE(std::any_of(
            cut.lone_springs().begin(), cut.lone_springs().end(),
            [&](const raster::LineIndices& l) { return l[0] == bend.i && l[1] == bend.j; }))
            << name;
    }
}

// Removes the springs for which `cut` says true, and the triangles that used one as an edge.
template <typename Cut>
void remove_springs(Cloth& cloth, Cut cut) {
    auto has_edge = [&](std::uint32_t a, std::uint32_t b) {
        for (const SpringGroup& group : cloth.topology().spring_groups)
            for (const Spring& s : group.springs)
                if (((s.i == a && s.j == b) || (s.i == b && s.j == a)) && cut(s)) return true;
        return false;
    };
    std::erase_if(cloth.edit_topology().triangles, [&](const Triangle& t) {
        return has_edge(t.a, t.b) || has_edge(t.b, t.c) || has_edge(t.c, t.a);
    });
    for (SpringGroup& group : cloth.edit_topology().spring_groups)
        std::erase_if(group.springs, cut);
}

TEST(LoneSprings, AHoleShowsTheSpringsThatCrossIt) {
    Cloth cloth = build_cloth(sheet(Layout::grid, Orientation::vertical));
    const std::uint32_t cols = 7, a = 4 * cols + 3, b = a + 1;  // (4, 3)-(4, 4), inside
    remove_springs(
        cloth, [&](const Spring& s) { return (s.i == a && s.j == b) || (s.i == b && s.j == a); });
    const ClothView view(cloth);
    const auto lone = view.lone_springs();
    // The two triangles beside the cut edge are gone: the bend springs along row 4 that span
    // the edge and the shear diagonals that crossed those triangles now cross a hole; the
    // springs with a triangle left on one side do not.
    auto listed = [&](std::uint32_t i, std::uint32_t j) {
        return std::any_of(lone.begin(), lone.end(), [&](const raster::LineIndices& l) {
            return (l[0] == i && l[1] == j) || (l[0] == j && l[1] == i);
        });
    };
    EXPECT_TRUE(listed(a - 1, b));      // bend (4, 2)-(4, 4)
    EXPECT_TRUE(listed(a, b + 1));      // bend (4, 3)-(4, 5)
    EXPECT_TRUE(listed(a, b + cols));   // shear (4, 3)-(5, 4)
    EXPECT_TRUE(listed(a - cols, b));   // shear (3, 3)-(4, 4)
    EXPECT_FALSE(listed(a, b - cols));  // shear (3, 4)-(4, 3): the upper cell's split
    EXPECT_FALSE(listed(a, a + cols));  // structural (4, 3)-(5, 3): its left side is whole
    EXPECT_EQ(lone.size(), 4u);
}

TEST(LoneSprings, APiecesLastSpringIsDrawnInTheShadedView) {
    Cloth cloth = build_cloth(sheet(Layout::grid, Orientation::vertical));
    const std::uint32_t kept_i = 4 * 7 + 3, kept_j = kept_i + 7;  // (4, 3)-(5, 3), vertical
    Cloth bare = cloth;
    bare.edit_topology().triangles.clear();
    remove_springs(bare, [](const Spring&) { return true; });
    Cloth thread = cloth;
    thread.edit_topology().triangles.clear();
    remove_springs(thread, [&](const Spring& s) { return !(s.i == kept_i && s.j == kept_j); });
    ASSERT_EQ(thread.spring_count(), 1u);

    // The default scene's camera looks at the sheet face on; the spring runs from (0.15, -0.2)
    // to (0.15, -0.25) m.
    const Scene scene;
    const int width = 640, height = 480;
    FrameOptions options;
    options.ground = false;
    auto draw = [&](const Cloth& c) {
        raster::Framebuffer framebuffer(width, height);
        ClothView view(c);
        render_frame(framebuffer, scene_camera(scene), c, view, options, -10.0f);
        return std::vector<raster::Rgba8>(framebuffer.colours().begin(),
                                          framebuffer.colours().end());
    };
    const auto without = draw(bare), with = draw(thread);
    int changed = 0;
    for (int p = 0; p < width * height; ++p)
        if (!(with[p] == without[p])) ++changed;
    // The spring's projection: 0.05 m at 3 m with a 50° vertical fov over 480 px.
    const auto top = raster::project_to_window(scene_camera(scene), width, height,
                                               glm::vec3(cloth.positions[kept_i]));
    const auto bottom = raster::project_to_window(scene_camera(scene), width, height,
                                                  glm::vec3(cloth.positions[kept_j]));
    ASSERT_TRUE(top && bottom);
    const int length = static_cast<int>(bottom->y) - static_cast<int>(top->y);
    ASSERT_GE(length, 5);
    EXPECT_GE(changed, length - 1);
    EXPECT_LE(changed, 2 * length + 2);  // a thin line, one pixel per row
    const int mid_x = static_cast<int>(top->x),
              mid_y = static_cast<int>(0.5f * (top->y + bottom->y));
    const raster::Rgba8 fabric = raster::to_rgba8(options.surface.front_colour);
    EXPECT_TRUE(with[mid_y * width + mid_x] == fabric ||
                with[mid_y * width + mid_x - 1] == fabric ||
                with[mid_y * width + mid_x + 1] == fabric);
}

}  // namespace
}  // namespace weft::view
