// The framebuffer: size limits, clearing, and the row-major pixel layout the rasterizer and
// the PNG writer rely on.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "raster/framebuffer.h"

namespace weft::raster {
namespace {

TEST(Framebuffer, RejectsSizesOutsideOneTo16384PerSide) {
    EXPECT_THROW(Framebuffer(0, 10), std::invalid_argument);
    EXPECT_THROW(Framebuffer(10, -1), std::invalid_argument);
    EXPECT_THROW(Framebuffer(16385, 1), std::invalid_argument);
    EXPECT_THROW(Framebuffer(1, 1 << 30), std::invalid_argument);
    EXPECT_NO_THROW(Framebuffer(16384, 1));
    Framebuffer fb(1, 1);
    EXPECT_THROW(fb.resize(-5, 3), std::invalid_argument);
    EXPECT_EQ(fb.width(), 1);  // unchanged by the failed resize
}

TEST(Framebuffer, ClearSetsEveryColourAndDepthToFarByDefault) {
    Framebuffer fb(5, 3);
    fb.clear(Rgba8{1, 2, 3, 4});
    EXPECT_TRUE(std::all_of(fb.colours().begin(), fb.colours().end(), [](Rgba8 c) {
        return c == Rgba8{1, 2, 3, 4};
    }));
    EXPECT_TRUE(
        std::all_of(fb.depths().begin(), fb.depths().end(), [](float d) { return d == 1.0f; }));
    fb.clear(Rgba8{}, 0.25f);
    EXPECT_EQ(fb.depth(4, 2), 0.25f);
}

TEST(Framebuffer, ABandViewClearsItsRowsAndKeepsItsDepthsUntilWrittenBack) {
    // Seven wide: the band's rows start off a 16-byte boundary, and its depths end off one.
    Framebuffer frame(7, 6);
    frame.clear(Rgba8{1, 1, 1, 255}, 0.25f);
    std::vector<float> storage;
    Framebuffer band = Framebuffer::band_view(frame, 2, 5, storage);
    EXPECT_EQ(band.width(), 7);
    EXPECT_EQ(band.height(), 6);
    EXPECT_EQ(band.bounds(), (PixelRect{0, 2, 7, 5}));
    EXPECT_TRUE(band.contains(6, 2) && band.contains(0, 4));
    EXPECT_FALSE(band.contains(0, 1) || band.contains(0, 5));
    EXPECT_EQ(storage.size(), 3u * 7u);
    band.clear(Rgba8{9, 9, 9, 255}, 0.5f, PixelRect{0, 0, 7, 6});  // clipped to its rows
    band.depth(3, 3) = 0.125f;
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 7; ++x) {
            const bool inside = y >= 2 && y < 5;
            EXPECT_EQ(frame.colour(x, y), inside ? (Rgba8{9, 9, 9, 255}) : (Rgba8{1, 1, 1, 255}));
            EXPECT_EQ(frame.depth(x, y), 0.25f) << "written back before write_back_depths";
            if (inside) {
                EXPECT_EQ(band.depth(x, y), x == 3 && y == 3 ? 0.125f : 0.5f);
            }
        }
    }
    band.write_back_depths();
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 7; ++x) {
            const bool inside = y >= 2 && y < 5;
            EXPECT_EQ(frame.depth(x, y), !inside ? 0.25f : (x == 3 && y == 3 ? 0.125f : 0.5f))
                << x << ", " << y;
        }
    }
}

TEST(Framebuffer, PixelsAreRowMajorFromTheTopLeft) {
    Framebuffer fb(4, 3);
    fb.clear(Rgba8{});
    fb.colour(3, 1) = Rgba8{9, 9, 9, 9};
    fb.depth(1, 2) = 0.5f;
    EXPECT_EQ(fb.colours()[1 * 4 + 3], (Rgba8{9, 9, 9, 9}));
    EXPECT_EQ(fb.depths()[2 * 4 + 1], 0.5f);
    EXPECT_EQ(fb.bounds(), (PixelRect{0, 0, 4, 3}));
    fb.resize(2, 6);
    EXPECT_EQ(fb.colours().size(), 12u);
    EXPECT_EQ(fb.depths().size(), 12u);
}

}  // namespace
}  // namespace weft::raster
