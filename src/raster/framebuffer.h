// Framebuffer: an RGBA8 colour buffer and a float depth buffer of the same size.
//
// Pixel (x, y) has x to the right and y downwards, row 0 at the top, as in PNG files and SDL
// textures; both buffers are flat row-major arrays (index y * width + x) so the rasterizer's
// inner loops walk them linearly.
//
// Depth is window depth in [0, 1]: 0 on the camera's near plane, 1 on its far plane (OpenGL's
// default depth range). clear() resets depth to far_depth = 1.0 by default, and the depth test
// keeps a fragment only if it is strictly nearer than what is stored, so anything beyond the
// far plane is rejected per pixel as if it had been clipped.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "raster/colour.h"
#include "raster/pixel_rect.h"
#include "raster/vector_isa.h"

namespace weft::raster {

class Framebuffer {
  public:
    static constexpr int max_side = 16384;    // per side; 16384² pixels take 2 GiB already
    static constexpr float far_depth = 1.0f;  // the depth clear() writes unless told otherwise

    // Throws std::invalid_argument unless 1 <= width, height <= max_side.
    Framebuffer(int width, int height);

    // Same rule as the constructor; the contents are undefined until the next clear().
    void resize(int width, int height);

    // Whether drawing into it uses the AVX-512 builds of the block traversal and the lighting
    // (vector_isa.h): by default where the CPU runs them; the frame is the same to the byte.
    bool avx512_in_use() const { return avx512_; }
    void use_avx512(bool enabled) { avx512_ = enabled && avx512_supported(); }
    // The same for the AVX2 build of the lighting, used where AVX-512 is not.
    bool avx2_in_use() const { return avx2_; }
    void use_avx2(bool enabled) { avx2_ = enabled && avx2_supported(); }

    int width() const { return width_; }
    int height() const { return height_; }
    PixelRect bounds() const { return {0, 0, width_, height_}; }
    bool contains(int x, int y) const { return x >= 0 && x < width_ && y >= 0 && y < height_; }

    void clear(Rgba8 colour, float depth = far_depth);
    // Only the pixels inside `rect` (a band drawn by one thread).
    void clear(Rgba8 colour, float depth, const PixelRect& rect);

    // Single pixels, for tests and tools; x and y must be inside (checked only by assert).
    Rgba8& colour(int x, int y) { return colours_[index(x, y)]; }
    Rgba8 colour(int x, int y) const { return colours_[index(x, y)]; }
    float& depth(int x, int y) { return depths_[index(x, y)]; }
    float depth(int x, int y) const { return depths_[index(x, y)]; }

    // The whole buffers, row-major, for the rasterizer, PNG writing and blitting.
    std::span<Rgba8> colours() { return colours_; }
    std::span<const Rgba8> colours() const { return colours_; }
    std::span<float> depths() { return depths_; }
    std::span<const float> depths() const { return depths_; }

    std::size_t index(int x, int y) const;

  private:
    int width_ = 0;
    int height_ = 0;
    std::vector<Rgba8> colours_;
    std::vector<float> depths_;
    bool avx512_ = avx512_supported();
    bool avx2_ = avx2_supported();
};

}  // namespace weft::raster
