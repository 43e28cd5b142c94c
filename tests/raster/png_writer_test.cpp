// PNG writing, checked by reading the file back with stb_image (a different code path:
// the decoder) and comparing every pixel; failures are reported, not fatal.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <stb/stb_image.h>

#include "raster/framebuffer.h"
#include "raster/png_writer.h"

namespace weft::raster {
namespace {

std::filesystem::path scratch_path(const std::string& name) {
    return std::filesystem::temp_directory_path() /
           ("weft_png_writer_test_" +
            std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

TEST(PngWriter, WrittenFileReadsBackPixelForPixel) {
    Framebuffer fb(7, 5);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 7; ++x) {
            fb.colour(x, y) = Rgba8{
                static_cast<std::uint8_t>(x * 36), static_cast<std::uint8_t>(y * 60),
                static_cast<std::uint8_t>((x * y * 13) % 256), static_cast<std::uint8_t>(255 - x)};
        }
    }
    const std::filesystem::path path = scratch_path("roundtrip.png");
    std::string error;
    ASSERT_TRUE(write_png(fb, path.string(), &error)) << error;

    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load(path.string().c_str(), &width, &height, &channels, 4);
    ASSERT_NE(pixels, nullptr) << stbi_failure_reason();
    EXPECT_EQ(width, 7);
    EXPECT_EQ(height, 5);
    EXPECT_EQ(channels, 4);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 7; ++x) {
            const stbi_uc* p = pixels + 4 * (y * 7 + x);
            EXPECT_EQ((Rgba8{p[0], p[1], p[2], p[3]}), fb.colour(x, y))
                << "pixel (" << x << ", " << y << ")";
        }
    }
    stbi_image_free(pixels);
    std::filesystem::remove(path);
}

TEST(PngWriter, UnwritablePathReturnsFalseWithAReason) {
    Framebuffer fb(4, 4);
    std::string error;
    EXPECT_FALSE(write_png(fb, "/nonexistent-weft-directory/sub/out.png", &error));
    EXPECT_NE(error.find("/nonexistent-weft-directory/sub/out.png"), std::string::npos) << error;
    EXPECT_NE(error.find("No such file"), std::string::npos) << error;

    const std::filesystem::path directory = scratch_path("a_directory");
    std::filesystem::create_directories(directory);
    EXPECT_FALSE(write_png(fb, directory.string(), &error));
    std::filesystem::remove(directory);

    EXPECT_FALSE(write_png(fb, "", nullptr));  // no error string asked for: still no crash
}

}  // namespace
}  // namespace weft::raster
