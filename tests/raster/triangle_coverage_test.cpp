// Which pixels a triangle covers. The truth is the pixel-centre rule itself: a pixel belongs
// to a shape when its centre (x + 0.5, y + 0.5) lies inside; centres exactly on an edge go to
// the triangle on the edge's top or left side (so shapes that share edges tile the plane
// without gaps or overlaps). Counting writes per pixel exposes cracks (0) and double draws (2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "raster/framebuffer.h"
#include "raster/triangle_rasterizer.h"
#include "raster_test_support.h"

namespace weft::raster {
namespace {

using testing::CoverageCounter;
using testing::no_depth_state;
using testing::window_vertex;

// A point in window space on the 1/256-pixel lattice, held exactly as integers.
struct LatticePoint {
    std::int64_t x, y;  // window coordinate × 256
    float fx() const { return static_cast<float>(x) / 256.0f; }
    float fy() const { return static_cast<float>(y) / 256.0f; }
};

std::int64_t cross(const LatticePoint& o, const LatticePoint& a, const LatticePoint& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Where a pixel centre lies relative to a convex polygon (either winding), exactly.
enum class Side { inside, boundary, outside };

Side classify(const std::vector<LatticePoint>& polygon, int px, int py) {
    const LatticePoint centre{px * 256 + 128, py * 256 + 128};
    int positive = 0, negative = 0, zero = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const std::int64_t c = cross(polygon[i], polygon[(i + 1) % polygon.size()], centre);
        (c > 0 ? positive : c < 0 ? negative : zero)++;
    }
    if (positive > 0 && negative > 0) return Side::outside;
    return zero > 0 ? Side::boundary : Side::inside;
}

bool strictly_convex(const std::vector<LatticePoint>& polygon) {
    int sign = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const std::int64_t c =
            cross(polygon[i], polygon[(i + 1) % polygon.size()], polygon[(i + 2) % polygon.size()]);
        if (c == 0) return false;
        const int s = c > 0 ? 1 : -1;
        if (sign != 0 && s != sign) return false;
        sign = s;
    }
    return true;
}

void draw_window_triangle(Framebuffer& fb, CoverageCounter& counter, const LatticePoint& a,
                          const LatticePoint& b, const LatticePoint& c) {
    draw_triangle(fb, no_depth_state(), window_vertex(fb, a.fx(), a.fy()),
                  window_vertex(fb, b.fx(), b.fy()), window_vertex(fb, c.fx(), c.fy()),
                  counter.shader());
}

// Checks coverage counts against the polygon: centres strictly inside exactly once (this
// includes the centres on internal shared edges), strictly outside never, on the outline at
// most once. Returns the number of failures and reports the first few.
int check_polygon_coverage(const Framebuffer& fb, const CoverageCounter& counter,
                           const std::vector<LatticePoint>& polygon, const char* what) {
    int failures = 0;
    for (int y = 0; y < fb.height(); ++y) {
        for (int x = 0; x < fb.width(); ++x) {
            const int count = counter.at(x, y);
            const Side side = classify(polygon, x, y);
            const bool ok = side == Side::inside    ? count == 1
                            : side == Side::outside ? count == 0
                                                    : count <= 1;
            if (!ok && ++failures <= 3) {
                ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") written " << count
                              << " times, centre "
                              << (side == Side::inside    ? "inside"
                                  : side == Side::outside ? "outside"
                                                          : "on the outline");
            }
        }
    }
    return failures;
}

// Random convex quads of several kinds: vertices anywhere on the 1/256 lattice, on half
// pixels (so edges run exactly through pixel centres), on pixel centres, and axis-aligned
// rectangles and trapezoids (horizontal and vertical edges).
std::vector<LatticePoint> random_quad(std::mt19937& rng, int kind, int size) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const std::int64_t quantum = kind == 0 ? 1 : kind == 1 ? 128 : 256;
    const std::int64_t offset = kind == 2 ? 128 : 0;  // pixel centres
    auto snap = [&](float v) {
        return static_cast<std::int64_t>(std::round(v * 256.0f / static_cast<float>(quantum))) *
                   quantum +
               offset;
    };
    const float s = static_cast<float>(size);
    if (kind == 3) {  // axis-aligned rectangle
        const float x0 = unit(rng) * s * 0.6f, y0 = unit(rng) * s * 0.6f;
        const float x1 = x0 + 1.0f + unit(rng) * s * 0.4f, y1 = y0 + 1.0f + unit(rng) * s * 0.4f;
        return {
            {snap(x0), snap(y0)}, {snap(x1), snap(y0)}, {snap(x1), snap(y1)}, {snap(x0), snap(y1)}};
    }
    if (kind == 4) {  // trapezoid with horizontal top and bottom
        const float y0 = unit(rng) * s * 0.5f, y1 = y0 + 2.0f + unit(rng) * s * 0.5f;
        const float a = unit(rng) * s * 0.4f, b = a + 2.0f + unit(rng) * s * 0.5f;
        const float c = unit(rng) * s * 0.4f, d = c + 2.0f + unit(rng) * s * 0.5f;
        return {{snap(a), snap(y0)}, {snap(b), snap(y0)}, {snap(d), snap(y1)}, {snap(c), snap(y1)}};
    }
    // General: four angles around a centre, each gap below pi, random radii.
    const float cx = s * (0.3f + 0.4f * unit(rng)), cy = s * (0.3f + 0.4f * unit(rng));
    float angle = unit(rng) * 2.0f * std::numbers::pi_v<float>;
    std::vector<LatticePoint> quad;
    for (int i = 0; i < 4; ++i) {
        const float radius = 1.0f + unit(rng) * s * 0.3f;
        quad.push_back({snap(cx + radius * std::cos(angle)), snap(cy + radius * std::sin(angle))});
        angle += (0.25f + 0.45f * unit(rng)) * std::numbers::pi_v<float>;
    }
    return quad;
}

TEST(TriangleRasterizer, SharedEdgePixelsDrawnExactlyOnceForRandomQuads) {
    Framebuffer fb(64, 64);
    std::mt19937 rng(20240601);
    int quads = 0;
    for (int trial = 0; trial < 2000 && !HasFailure(); ++trial) {
        const int kind = trial % 5;
        std::vector<LatticePoint> quad = random_quad(rng, kind, 64);
        if (!strictly_convex(quad)) continue;
        if (trial % 2 == 1) std::reverse(quad.begin(), quad.end());  // both windings
        ++quads;
        for (int diagonal = 0; diagonal < 2; ++diagonal) {
            const LatticePoint& a = quad[diagonal];
            const LatticePoint& b = quad[diagonal + 1];
            const LatticePoint& c = quad[diagonal + 2];
            const LatticePoint& d = quad[(diagonal + 3) % 4];
            CoverageCounter counter(fb);
            draw_window_triangle(fb, counter, a, b, c);
            draw_window_triangle(fb, counter, a, c, d);
            check_polygon_coverage(fb, counter, quad, "quad");
        }
    }
    EXPECT_GT(quads, 1500);
}

// Triangles a few pixels across, as a fine cloth seen whole is made of: their boxes hold at
// most 2×2 pixel centres, which the rasterizer and the binning decide without its general
// pixel loop. The pixel-centre rule still decides coverage, and the rows binning reports are
// exactly the rows of the pixels drawn, or none when none is.
TEST(TriangleRasterizer, TinyTrianglesCoverTheirCentresAndBinIntoTheRowsTheyDraw) {
    Framebuffer fb(8, 8);
    std::mt19937 rng(20261127);
    int quads = 0, triangles_drawing_nothing = 0, triangles_drawing = 0;
    for (int trial = 0; trial < 4000 && !HasFailure(); ++trial) {
        std::vector<LatticePoint> quad = random_quad(rng, trial % 5, 3);
        // Inside the framebuffer, or across its right or bottom edge, where the pixels
        // beyond it are not drawn and binning must not count their rows.
        const std::int64_t shift_x = trial % 3 == 1 ? 6 : 2, shift_y = trial % 3 == 2 ? 6 : 2;
        for (LatticePoint& corner : quad) {
            corner.x += shift_x * 256;
            corner.y += shift_y * 256;
        }
        if (!strictly_convex(quad)) continue;
        if (trial % 2 == 1) std::reverse(quad.begin(), quad.end());
        ++quads;
        CoverageCounter both(fb);
        for (int half = 0; half < 2; ++half) {
            const LatticePoint& a = quad[0];
            const LatticePoint& b = quad[half + 1];
            const LatticePoint& c = quad[half + 2];
            draw_window_triangle(fb, both, a, b, c);
            CoverageCounter alone(fb);
            draw_window_triangle(fb, alone, a, b, c);
            int first = fb.height(), last = -1;
            for (int y = 0; y < fb.height(); ++y) {
                for (int x = 0; x < fb.width(); ++x) {
                    if (alone.at(x, y) == 0) continue;
                    first = std::min(first, y);
                    last = std::max(last, y);
                }
            }
            auto window = [&](const LatticePoint& p) {
                return raster::window_vertex(testing::window_vertex(fb, p.fx(), p.fy()).position,
                                             fb.width(), fb.height());
            };
            BinnedCoverage rows;
            bin_coverage(window(a), window(b), window(c), fb.bounds(), rows);
            // How many pixel centres the triangle's extent spans along x and along y (its
            // corners lie at positive coordinates): binning decides exactly up to 2×2, and
            // gives a larger triangle its box's rows.
            auto centres = [](std::int64_t low, std::int64_t high) {
                return (high - 128) / 256 - (low - 128 + 255) / 256 + 1;
            };
            const bool tiny = centres(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x})) <= 2 &&
                              centres(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y})) <= 2;
            if (last < 0) {
                ++triangles_drawing_nothing;
                if (tiny) {
                    EXPECT_TRUE(rows.empty()) << "trial " << trial;
                }
            } else {
                ++triangles_drawing;
                EXPECT_LE(rows.first, first) << "trial " << trial;
                EXPECT_GE(rows.last, last) << "trial " << trial;
                if (tiny) {
                    EXPECT_EQ(rows.first, first) << "trial " << trial;
                    EXPECT_EQ(rows.last, last) << "trial " << trial;
                }
            }
        }
        check_polygon_coverage(fb, both, quad, "small quad");
    }
    EXPECT_GT(quads, 3000);
    // Both cases are exercised, many times over.
    EXPECT_GT(triangles_drawing_nothing, 500);
    EXPECT_GT(triangles_drawing, 500);
}

TEST(TriangleRasterizer, FanAroundSharedVertexCoversEveryPixelOnce) {
    Framebuffer fb(64, 64);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 200 && !HasFailure(); ++trial) {
        // Centre on a pixel centre for even trials, anywhere on the lattice for odd ones.
        const float cx = trial % 2 == 0 ? 31.5f : 20.0f + 24.0f * unit(rng);
        const float cy = trial % 2 == 0 ? 32.5f : 20.0f + 24.0f * unit(rng);
        const LatticePoint centre{static_cast<std::int64_t>(std::round(cx * 256.0f)),
                                  static_cast<std::int64_t>(std::round(cy * 256.0f))};
        const int spokes = 3 + trial % 14;
        const float radius = 8.0f + 10.0f * unit(rng), phase = unit(rng) * 6.3f;
        std::vector<LatticePoint> rim;
        for (int i = 0; i < spokes; ++i) {
            const float angle = phase + 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) /
                                            static_cast<float>(spokes);
            rim.push_back(
                {static_cast<std::int64_t>(std::round((cx + radius * std::cos(angle)) * 256.0f)),
                 static_cast<std::int64_t>(std::round((cy + radius * std::sin(angle)) * 256.0f))});
        }
        ASSERT_TRUE(strictly_convex(rim));
        CoverageCounter counter(fb);
        for (int i = 0; i < spokes; ++i) {
            draw_window_triangle(fb, counter, centre, rim[i], rim[(i + 1) % spokes]);
        }
        check_polygon_coverage(fb, counter, rim, "fan");
        const int centre_x = static_cast<int>(std::floor(cx)),
                  centre_y = static_cast<int>(std::floor(cy));
        if (trial % 2 == 0) {
            EXPECT_EQ(counter.at(centre_x, centre_y), 1) << "shared vertex pixel";
        }
    }
}

// Axis-aligned rectangle [x0, x1) × [y0, y1): centres on the top and left edges are in, on
// the bottom and right edges out — the whole of the top-left rule in one picture.
TEST(TriangleRasterizer, RectangleCoversExactlyThePixelCentresInsideWithTopLeftRule) {
    Framebuffer fb(40, 30);
    std::mt19937 rng(99);
    std::uniform_int_distribution<int> quarter(0, 4 * 30);
    for (int trial = 0; trial < 300 && !HasFailure(); ++trial) {
        // Quarter-pixel corners: half of them land exactly on pixel-centre rows/columns.
        float x0 = static_cast<float>(quarter(rng)) / 4.0f,
              x1 = static_cast<float>(quarter(rng)) / 4.0f;
        float y0 = static_cast<float>(quarter(rng)) / 4.0f * 0.7f,
              y1 = static_cast<float>(quarter(rng)) / 4.0f * 0.7f;
        y0 = std::round(y0 * 4.0f) / 4.0f, y1 = std::round(y1 * 4.0f) / 4.0f;
        if (x0 == x1 || y0 == y1) continue;
        if (x0 > x1) std::swap(x0, x1);
        if (y0 > y1) std::swap(y0, y1);
        CoverageCounter counter(fb);
        const ClipVertex tl = window_vertex(fb, x0, y0), tr = window_vertex(fb, x1, y0);
        const ClipVertex br = window_vertex(fb, x1, y1), bl = window_vertex(fb, x0, y1);
        if (trial % 2 == 0) {
            draw_triangle(fb, no_depth_state(), tl, tr, br, counter.shader());
            draw_triangle(fb, no_depth_state(), tl, br, bl, counter.shader());
        } else {  // the other diagonal, the other winding
            draw_triangle(fb, no_depth_state(), tr, tl, bl, counter.shader());
            draw_triangle(fb, no_depth_state(), tr, bl, br, counter.shader());
        }
        for (int y = 0; y < fb.height(); ++y) {
            for (int x = 0; x < fb.width(); ++x) {
                const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
                const int expected = cx >= x0 && cx < x1 && cy >= y0 && cy < y1 ? 1 : 0;
                ASSERT_EQ(counter.at(x, y), expected)
                    << "pixel (" << x << ", " << y << ") rectangle x [" << x0 << ", " << x1
                    << ") y [" << y0 << ", " << y1 << ")";
            }
        }
    }
}

TEST(TriangleRasterizer, SinglePixelCentreTriangleFollowsTopLeftRule) {
    // A right triangle whose corner sits exactly on the centre of pixel (5, 5): its top edge
    // and left edge pass through that centre, so the pixel is in.
    Framebuffer fb(16, 16);
    CoverageCounter top_left(fb);
    draw_triangle(fb, no_depth_state(), window_vertex(fb, 5.5f, 5.5f),
                  window_vertex(fb, 9.5f, 5.5f), window_vertex(fb, 5.5f, 9.5f), top_left.shader());
    EXPECT_EQ(top_left.at(5, 5), 1);
    EXPECT_EQ(top_left.at(9, 5), 0);  // right end of the top edge is on the hypotenuse: out
    EXPECT_EQ(top_left.at(5, 9), 0);  // bottom end of the left edge: out
    // Mirrored: the corner now lies on a bottom edge and a right edge: out.
    CoverageCounter bottom_right(fb);
    draw_triangle(fb, no_depth_state(), window_vertex(fb, 9.5f, 9.5f),
                  window_vertex(fb, 5.5f, 9.5f), window_vertex(fb, 9.5f, 5.5f),
                  bottom_right.shader());
    EXPECT_EQ(bottom_right.at(9, 9), 0);
    EXPECT_EQ(bottom_right.at(8, 8), 1);
}

TEST(TriangleRasterizer, HugeTrianglesAroundTheScreenShareTheirEdgeWithoutCracks) {
    // A quad a thousand screens wide (vertices beyond the guard band, so both halves are
    // clipped) whose diagonal crosses the screen: every pixel exactly once.
    Framebuffer fb(48, 32);
    const float big = 48.0f * 1000.0f;
    for (float w : {1.0f, 0.37f}) {
        CoverageCounter counter(fb);
        const ClipVertex a = window_vertex(fb, -big, -big * 0.5f, 0.5f, w);
        const ClipVertex b = window_vertex(fb, big * 1.3f, -big * 0.9f, 0.5f, w);
        const ClipVertex c = window_vertex(fb, big, big, 0.5f, w);
        const ClipVertex d = window_vertex(fb, -big * 1.1f, big * 0.8f, 0.5f, w);
        draw_triangle(fb, no_depth_state(), a, b, c, counter.shader());
        draw_triangle(fb, no_depth_state(), a, c, d, counter.shader());
        for (int y = 0; y < fb.height(); ++y) {
            for (int x = 0; x < fb.width(); ++x) {
                ASSERT_EQ(counter.at(x, y), 1) << "pixel (" << x << ", " << y << "), w " << w;
            }
        }
    }
}

TEST(TriangleRasterizer, ScissorTilesTogetherDrawExactlyWhatTheWholeFramebufferDraws) {
    // The tile API: drawing the same triangles once per tile (as a threaded renderer will)
    // writes every pixel exactly as often as one untiled draw.
    Framebuffer fb(50, 37);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> coordinate(-10.0f, 60.0f);
    std::vector<ClipVertex> vertices;
    for (int i = 0; i < 60; ++i)
        vertices.push_back(window_vertex(fb, coordinate(rng), coordinate(rng)));
    CoverageCounter whole(fb), tiled(fb);
    for (std::size_t i = 0; i + 2 < vertices.size(); i += 3) {
        draw_triangle(fb, no_depth_state(), vertices[i], vertices[i + 1], vertices[i + 2],
                      whole.shader());
    }
    for (int ty = 0; ty < fb.height(); ty += 16) {
        for (int tx = 0; tx < fb.width(); tx += 16) {
            RasterState state = no_depth_state();
            state.scissor = {tx, ty, tx + 16, ty + 16};
            for (std::size_t i = 0; i + 2 < vertices.size(); i += 3) {
                draw_triangle(fb, state, vertices[i], vertices[i + 1], vertices[i + 2],
                              tiled.shader());
            }
        }
    }
    EXPECT_EQ(whole.counts, tiled.counts);
    EXPECT_GT(std::count_if(whole.counts.begin(), whole.counts.end(), [](int c) { return c > 0; }),
              500);
}

TEST(TriangleRasterizer, ReportsCounterClockwiseOnScreenAsFrontFacing) {
    Framebuffer fb(16, 16);
    int front = 0, back = 0;
    auto shader = [&](const Fragment& f) {
        (f.front_facing ? front : back)++;
        return Rgba8{};
    };
    // On screen (y down) a → b → c going down, right, then back up-left is counter-clockwise.
    const ClipVertex a = window_vertex(fb, 2, 2), b = window_vertex(fb, 2, 12),
                     c = window_vertex(fb, 12, 12);
    draw_triangle(fb, no_depth_state(), a, b, c, shader);
    EXPECT_GT(front, 0);
    EXPECT_EQ(back, 0);
    front = 0;
    draw_triangle(fb, no_depth_state(), a, c, b, shader);
    EXPECT_EQ(front, 0);
    EXPECT_GT(back, 0);
}

TEST(TriangleRasterizer, DegenerateOffscreenAndNonFiniteTrianglesDrawNothing) {
    Framebuffer fb(16, 16);
    CoverageCounter counter(fb);
    const float nan = std::nanf("");
    // Zero area, entirely left of the screen, entirely behind the camera, NaN, infinity.
    draw_triangle(fb, no_depth_state(), window_vertex(fb, 1, 1), window_vertex(fb, 5, 5),
                  window_vertex(fb, 9, 9), counter.shader());
    draw_triangle(fb, no_depth_state(), window_vertex(fb, -9, 1), window_vertex(fb, -1, 5),
                  window_vertex(fb, -5, 12), counter.shader());
    draw_triangle(fb, no_depth_state(), window_vertex(fb, 1, 1, 0.5f, -1.0f),
                  window_vertex(fb, 15, 1, 0.5f, -2.0f), window_vertex(fb, 8, 15, 0.5f, -1.0f),
                  counter.shader());
    draw_triangle(fb, no_depth_state(), window_vertex(fb, nan, 1), window_vertex(fb, 15, 1),
                  window_vertex(fb, 8, 15), counter.shader());
    ClipVertex infinite = window_vertex(fb, 8, 15);
    infinite.position.x = std::numeric_limits<float>::infinity();
    draw_triangle(fb, no_depth_state(), window_vertex(fb, 1, 1), window_vertex(fb, 15, 1), infinite,
                  counter.shader());
    EXPECT_TRUE(
        std::all_of(counter.counts.begin(), counter.counts.end(), [](int c) { return c == 0; }));
}

}  // namespace
}  // namespace weft::raster
