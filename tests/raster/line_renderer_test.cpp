// Lines and points. Truths: the pixel rule stated in line_renderer.h (one pixel per column
// whose centre lies in [x0, x1), the row the line passes through there) worked out by hand;
// the near plane, behind which nothing may appear (a line through the camera would otherwise
// wrap into the top of the screen); depth against a surface at known depth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "raster/ground_grid.h"
#include "raster/line_renderer.h"
#include "raster/mesh.h"
#include "raster/mesh_renderer.h"
#include "raster_test_support.h"

namespace weft::raster {
namespace {

using testing::window_vertex;

constexpr Rgba8 background{0, 0, 0, 255};
constexpr Rgba8 white{255, 255, 255, 255};

std::set<std::pair<int, int>> drawn_pixels(const Framebuffer& fb) {
    std::set<std::pair<int, int>> pixels;
    for (int y = 0; y < fb.height(); ++y) {
        for (int x = 0; x < fb.width(); ++x) {
            if (fb.colour(x, y) != background) pixels.insert({x, y});
        }
    }
    return pixels;
}

void draw_window_line(Framebuffer& fb, float x0, float y0, float x1, float y1) {
    draw_clip_space_line(fb, window_vertex(fb, x0, y0).position, window_vertex(fb, x1, y1).position,
                         white, white);
}

TEST(LineRenderer, HorizontalLineCoversExactlyTheColumnsBetweenItsEnds) {
    Framebuffer fb(32, 24);
    fb.clear(background);
    draw_window_line(fb, 2.0f, 10.5f, 8.0f, 10.5f);  // centres 2.5 … 7.5 are in [2, 8)
    std::set<std::pair<int, int>> expected;
    for (int x = 2; x <= 7; ++x) expected.insert({x, 10});
    EXPECT_EQ(drawn_pixels(fb), expected);

    fb.clear(background);
    draw_window_line(fb, 8.0f, 10.5f, 2.0f, 10.5f);  // same segment, other direction
    EXPECT_EQ(drawn_pixels(fb), expected);
}

TEST(LineRenderer, VerticalAndDiagonalLinesFollowTheSameRule) {
    Framebuffer fb(32, 24);
    fb.clear(background);
    draw_window_line(fb, 5.25f, 3.0f, 5.25f, 9.0f);
    std::set<std::pair<int, int>> expected;
    for (int y = 3; y <= 8; ++y) expected.insert({5, y});
    EXPECT_EQ(drawn_pixels(fb), expected);

    fb.clear(background);
    draw_window_line(fb, 1.0f, 1.0f, 11.0f, 11.0f);  // through the pixel centres (i+0.5, i+0.5)
    expected.clear();
    for (int i = 1; i <= 10; ++i) expected.insert({i, i});
    EXPECT_EQ(drawn_pixels(fb), expected);
}

TEST(LineRenderer, WorldSpaceLineLandsOnTheExpectedPixels) {
    // Endpoints placed on the eye rays through window points (2, 10.5) and (8, 10.5).
    const int width = 32, height = 24;
    Framebuffer fb(width, height);
    fb.clear(background);
    const Camera camera = make_camera({0.3f, 0.2f, 2.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    const Ray a = camera_ray(camera, width, height, {2.0f, 10.5f});
    const Ray b = camera_ray(camera, width, height, {8.0f, 10.5f});
    const LineSegment segment{a.at(1.5f), b.at(3.0f), white, white};
    draw_lines(fb, camera, std::span(&segment, 1));
    std::set<std::pair<int, int>> expected;
    for (int x = 2; x <= 7; ++x) expected.insert({x, 10});
    EXPECT_EQ(drawn_pixels(fb), expected);
}

TEST(LineRenderer, LinePassingBehindTheCameraIsClippedNotWrapped) {
    // Eye at the origin looking down -z; the line runs below the eye from 5 m ahead to 5 m
    // behind. Only its front part is visible: straight down the middle column, all of it
    // below the centre of the screen. Unclipped, the part behind would reappear above.
    const int width = 33, height = 33;
    Framebuffer fb(width, height);
    fb.clear(background);
    const Camera camera = make_camera({0, 0, 0}, {0, 0, -1}, 60.0f);
    const LineSegment segment{{0.0f, -1.0f, -5.0f}, {0.0f, -1.0f, 5.0f}, white, white};
    draw_lines(fb, camera, std::span(&segment, 1));
    const auto pixels = drawn_pixels(fb);
    ASSERT_FALSE(pixels.empty());
    for (const auto& [x, y] : pixels) {
        EXPECT_EQ(x, 16);
        EXPECT_GT(y, height / 2);
        EXPECT_GE(fb.depth(x, y), 0.0f) << "drawn between the eye and the near plane";
    }
    EXPECT_TRUE(pixels.count({16, height - 1}));  // reaches the bottom edge

    // 1 cm below the eye, the stretch between the eye and the near plane (0.05 m) is on
    // screen; it must not be drawn. The line ends where it meets the near plane, 0.2 below
    // the axis at that depth: window y = (1 + 0.2 / tan 30°) / 2 · 33 ≈ 22.2, so the last
    // row whose centre it reaches is row 21 (centre 21.5).
    fb.clear(background);
    const LineSegment close{{0.0f, -0.01f, -1.0f}, {0.0f, -0.01f, 1.0f}, white, white};
    draw_lines(fb, camera, std::span(&close, 1));
    const auto close_pixels = drawn_pixels(fb);
    ASSERT_FALSE(close_pixels.empty());
    int lowest = 0;
    for (const auto& [x, y] : close_pixels) {
        EXPECT_GE(fb.depth(x, y), 0.0f)
            << "pixel (" << x << ", " << y << ") nearer than the near plane";
        lowest = std::max(lowest, y);
    }
    EXPECT_EQ(lowest, 21);
}

TEST(LineRenderer, IsHiddenBehindASurfaceButShowsOnTopOfItsOwnSurface) {
    // A slanted quad, and lines on it (its edges and diagonals) and behind it.
    const int width = 64, height = 48;
    const Camera camera = make_camera({0.6f, 0.5f, 2.5f}, {0, 0, 0}, 50.0f);
    const std::vector<glm::vec3> positions{
        {-1, -0.8f, 0.6f}, {1, -0.8f, -0.6f}, {1, 0.8f, -0.9f}, {-1, 0.8f, 0.3f}};
    const std::vector<glm::vec3> normals =
        compute_vertex_normals(positions, std::vector<TriangleIndices>{{0, 1, 2}, {0, 2, 3}});
    const std::vector<TriangleIndices> triangles{{0, 1, 2}, {0, 2, 3}};
    Lighting lighting;
    Framebuffer fb(width, height);
    fb.clear(background);
    ASSERT_TRUE(
        draw_mesh(fb, camera, MeshView{positions, normals, triangles}, SurfaceStyle{}, lighting));
    const Rgba8 line_colour{0, 255, 0, 255};
    const std::vector<LineIndices> on_surface{{0, 2}, {1, 3}};
    draw_indexed_lines(fb, camera, positions, on_surface, line_colour);
    int visible = 0, total = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) visible += fb.colour(x, y) == line_colour;
    }
    // Count the pixels the two diagonals cover without a surface: all must stay visible.
    Framebuffer bare(width, height);
    bare.clear(background);
    draw_indexed_lines(bare, camera, positions, on_surface, line_colour);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) total += bare.colour(x, y) == line_colour;
    }
    EXPECT_GT(total, 80);
    EXPECT_EQ(visible, total) << "the wireframe fights with its own surface";

    // A line 0.3 m behind the quad's centre, crossing it: hidden where the quad covers it.
    const Rgba8 hidden_colour{255, 0, 255, 255};
    const LineSegment behind{
        {-0.5f, 0.0f, -0.45f}, {0.5f, 0.0f, -0.45f}, hidden_colour, hidden_colour};
    draw_lines(fb, camera, std::span(&behind, 1));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) EXPECT_NE(fb.colour(x, y), hidden_colour) << x << ", " << y;
    }
}

TEST(LineRenderer, ColoursBlendAlongTheLineAndIndexedLinesTakeOneColourEach) {
    Framebuffer fb(32, 8);
    fb.clear(background);
    draw_clip_space_line(fb, window_vertex(fb, 0.0f, 4.5f).position,
                         window_vertex(fb, 32.0f, 4.5f).position, Rgba8{0, 0, 0, 255},
                         Rgba8{255, 0, 0, 255});
    EXPECT_LE(fb.colour(0, 4).r, 8);
    EXPECT_NEAR(fb.colour(16, 4).r, 131, 2);  // centre 16.5 of 32: 0.516 · 255
    EXPECT_GE(fb.colour(31, 4).r, 245);

    const Camera camera = make_camera({0, 0, 3}, {0, 0, 0}, 50.0f);
    const std::vector<glm::vec3> positions{
        {-1, 0.2f, 0}, {1, 0.2f, 0}, {-1, -0.2f, 0}, {1, -0.2f, 0}};
    const std::vector<LineIndices> lines{{0, 1}, {2, 3}, {0, 7}};  // the last is out of range
    const std::vector<Rgba8> colours{{255, 0, 0, 255}, {0, 0, 255, 255}, {0, 255, 0, 255}};
    Framebuffer two(32, 32);
    two.clear(background);
    draw_indexed_lines(two, camera, positions, lines, colours);
    int red = 0, blue = 0, green = 0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            red += two.colour(x, y) == colours[0];
            blue += two.colour(x, y) == colours[1];
            green += two.colour(x, y) == colours[2];
        }
    }
    EXPECT_GT(red, 10);
    EXPECT_GT(blue, 10);
    EXPECT_EQ(green, 0);
}

// Forty segments every which way, for a camera at about (0.3, 0.6, 1.2): long ones running
// far off screen and behind the camera among them; every other one fades to red.
std::vector<LineSegment> scattered_segments() {
    std::vector<LineSegment> segments;
    for (int i = 0; i < 40; ++i) {
        const float a = 0.37f * static_cast<float>(i), b = 1.3f + 0.71f * static_cast<float>(i);
        const Rgba8 colour{static_cast<std::uint8_t>(40 + 5 * i), 200,
                           static_cast<std::uint8_t>(250 - 5 * i), 255};
        segments.push_back({{std::cos(a) * 3.0f, std::sin(b) * 0.8f, std::sin(a) * 3.0f},
                            {std::cos(b) * 0.5f, std::cos(a) * 2.0f, (i % 3 == 0 ? 6.0f : -0.7f)},
                            colour,
                            i % 2 == 0 ? colour : Rgba8{255, 40, 40, 255}});
    }
    return segments;
}

TEST(LineRenderer, ScissorTilesTogetherDrawExactlyWhatTheWholeFramebufferDraws) {
    // Lines drawn tile by tile (as a threaded renderer will) must land on the same pixels as
    // one untiled draw, including long lines running far off screen and behind the camera.
    const int width = 61, height = 47;
    const Camera camera = make_camera({0.3f, 0.6f, 1.2f}, {0.0f, 0.0f, 0.0f}, 60.0f);
    const std::vector<LineSegment> segments = scattered_segments();
    Framebuffer whole(width, height), tiled(width, height);
    whole.clear(background);
    tiled.clear(background);
    draw_lines(whole, camera, segments);
    for (int y = 0; y < height; y += 16) {
        for (int x = 0; x < width; x += 16) {
            LineStyle style;
            style.scissor = {x, y, x + 16, y + 16};
            draw_lines(tiled, camera, segments, style);
        }
    }
    EXPECT_GT(drawn_pixels(whole).size(), 300u);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            ASSERT_EQ(whole.colour(x, y), tiled.colour(x, y)) << "pixel (" << x << ", " << y << ")";
            ASSERT_EQ(whole.depth(x, y), tiled.depth(x, y)) << "pixel (" << x << ", " << y << ")";
        }
    }
}

TEST(LineRenderer, LinesSetUpOnceDrawInBandsWhatTheyDrawWhole) {
    // A banded frame sets its grids' lines up once and walks them in every band: the same
    // pixels, colours and depths as drawing the lines whole, for any band height, including
    // lines that run behind the camera and off screen. Each band's depth test sees what the
    // surface left, so a surface is drawn first.
    const int width = 97, height = 61;
    const Camera camera = make_camera({0.3f, 0.6f, 1.2f}, {0.0f, 0.0f, 0.0f}, 60.0f);
    const std::vector<LineSegment> segments = scattered_segments();
    GroundGrid ground;
    ground.height = -0.4f;
    PlaneGrid wall = PlaneGrid::facing({0.0f, 0.0f, -1.0f}, {0.2f, 0.1f, 1.0f});
    wall.cell_count = 8;
    auto surface = [&](Framebuffer& fb) {
        fb.clear(background);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) fb.depth(x, y) = 0.9f + 0.001f * static_cast<float>(x);
    };
    const float bias = LineStyle{}.depth_bias;
    Framebuffer whole(width, height);
    surface(whole);
    draw_lines(whole, camera, segments);
    draw_ground_grid(whole, camera, ground);
    draw_plane_grid(whole, camera, wall);
    std::vector<PreparedLine> prepared;
    prepare_lines(whole, camera, segments, bias, prepared);
    prepare_ground_grid(whole, camera, ground, bias, prepared);
    prepare_plane_grid(whole, camera, wall, bias, prepared);
    EXPECT_GT(prepared.size(), 40u);
    EXPECT_LT(prepared.size(), segments.size() + 2 * 21 + 2 * 9);  // some are off screen
    for (int band_height : {1, 7, 16, height}) {
        Framebuffer banded(width, height);
        surface(banded);
        for (int y = 0; y < height; y += band_height) {
            LineStyle style;
            style.scissor = {0, y, width, std::min(y + band_height, height)};
            draw_prepared_lines(banded, prepared, style);
        }
        EXPECT_GT(drawn_pixels(whole).size(), 400u);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                ASSERT_EQ(whole.colour(x, y), banded.colour(x, y))
                    << "pixel (" << x << ", " << y << "), bands of " << band_height;
                ASSERT_EQ(whole.depth(x, y), banded.depth(x, y))
                    << "pixel (" << x << ", " << y << "), bands of " << band_height;
            }
        }
    }
}

TEST(PointRenderer, DrawsSquaresOfTheGivenSizeAndSkipsPointsBehindTheCamera) {
    const int width = 33, height = 33;
    Framebuffer fb(width, height);
    fb.clear(background);
    const Camera camera = make_camera({0, 0, 2}, {0, 0, 0}, 50.0f);
    const std::vector<glm::vec3> points{{0, 0, 0}, {0, 0, 4}};  // the second is behind the eye
    draw_points(fb, camera, points, white, 3.0f);
    std::set<std::pair<int, int>> expected;
    for (int y = 15; y <= 17; ++y) {
        for (int x = 15; x <= 17; ++x) expected.insert({x, y});  // centred on pixel (16, 16)
    }
    EXPECT_EQ(drawn_pixels(fb), expected);

    fb.clear(background);
    const std::vector<Rgba8> colours{white, white};
    draw_points(fb, camera, points, colours, 1.0f);
    EXPECT_EQ(drawn_pixels(fb), (std::set<std::pair<int, int>>{{16, 16}}));

    // Depth-tested: a surface in front hides the point.
    fb.clear(background, 0.1f);
    draw_points(fb, camera, points, white, 5.0f);
    EXPECT_TRUE(drawn_pixels(fb).empty());
}

TEST(GroundGrid, StaysBelowTheHorizonAndReachesTheBottomOfTheScreen) {
    const int width = 64, height = 48;
    Framebuffer fb(width, height);
    fb.clear(background);
    const Camera camera = make_camera({0.3f, 1.0f, 0.2f}, {0.3f, 1.0f, -1.0f}, 60.0f);
    GroundGrid grid;  // 20 cells of 0.25 m around the origin: the eye stands inside it
    grid.colour = white;
    grid.centre_colour = white;
    draw_ground_grid(fb, camera, grid);
    const auto pixels = drawn_pixels(fb);
    ASSERT_GT(pixels.size(), 100u);
    int bottom_rows = 0;
    for (const auto& [x, y] : pixels) {
        EXPECT_GE(y, height / 2) << "pixel (" << x << ", " << y << ") above the horizon";
        bottom_rows += y >= height - 4;
    }
    EXPECT_GT(bottom_rows, 4);
}

}  // namespace
}  // namespace weft::raster
