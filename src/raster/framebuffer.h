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

// Depths as the rasterizer reads and writes them: the depth of pixel index i (y · width + x)
// is at data[i - first_index]. A whole frame's start at its first pixel, a band view's
// (Framebuffer::band_view) at its band's.
struct DepthRows {
    float* data = nullptr;
    std::size_t first_index = 0;

    float& operator[](std::size_t index) const { return data[index - first_index]; }
};

class Framebuffer {
  public:
    static constexpr int max_side = 16384;    // per side; 16384² pixels take 2 GiB already
    static constexpr float far_depth = 1.0f;  // the depth clear() writes unless told otherwise

    // Throws std::invalid_argument unless 1 <= width, height <= max_side.
    Framebuffer(int width, int height);

    // Same rule as the constructor; the contents are undefined until the next clear(). Not
    // for a band view.
    void resize(int width, int height);

    // A view of rows [y_begin, y_end) of `frame` (inside it), for one thread to draw a band
    // of the frame: it writes the frame's colours, and keeps the band's depths in
    // `depth_storage` (resized to fit). Those stay in the core's cache from the band's clear
    // to its last triangle, where the frame's own depths would be read from memory and
    // written back to it. Its bounds() are the band's rows, so whatever is drawn into it
    // stays inside them. write_back_depths() puts the band's depths into the frame's.
    static Framebuffer band_view(Framebuffer& frame, int y_begin, int y_end,
                                 std::vector<float>& depth_storage);
    // A band view's depths into its frame's rows, by stores that do not first read what they
    // replace; nothing for a whole frame.
    void write_back_depths();

    // Whether drawing into it uses the AVX-512 builds of the block traversal and the lighting
    // (vector_isa.h): by default where the CPU runs them; the frame is the same to the byte.
    bool avx512_in_use() const { return avx512_; }
    void use_avx512(bool enabled) { avx512_ = enabled && avx512_supported(); }
    // The same for the AVX2 build of the lighting, used where AVX-512 is not.
    bool avx2_in_use() const { return avx2_; }
    void use_avx2(bool enabled) { avx2_ = enabled && avx2_supported(); }

    // The frame's size, also for a band view: pixel coordinates and indices are the frame's.
    int width() const { return width_; }
    int height() const { return height_; }
    // The pixels that can be drawn: the frame's, or a band view's rows.
    PixelRect bounds() const { return {0, rows_begin_, width_, rows_end_}; }
    bool contains(int x, int y) const {
        return x >= 0 && x < width_ && y >= rows_begin_ && y < rows_end_;
    }

    void clear(Rgba8 colour, float depth = far_depth);
    // Only the pixels inside `rect` (a band drawn by one thread).
    void clear(Rgba8 colour, float depth, const PixelRect& rect);

    // Single pixels, for tests and tools; x and y must be inside (checked only by assert).
    Rgba8& colour(int x, int y) { return colours()[index(x, y)]; }
    Rgba8 colour(int x, int y) const { return colours()[index(x, y)]; }
    float& depth(int x, int y) { return depth_rows()[index(x, y)]; }
    float depth(int x, int y) const {
        return held_depths()[index(x, y) - index_of_row(rows_begin_)];
    }

    // The whole frame's colours, row-major, for the rasterizer, PNG writing and blitting.
    std::span<Rgba8> colours() { return frame_ ? frame_->colours() : std::span<Rgba8>(colours_); }
    std::span<const Rgba8> colours() const {
        return frame_ ? std::span<const Rgba8>(frame_->colours()) : colours_;
    }
    // The depths held, row-major: the whole frame's, or a band view's rows only.
    std::span<float> depths() { return {depth_rows().data, held_depth_count()}; }
    std::span<const float> depths() const { return {held_depths(), held_depth_count()}; }
    // The depths as the rasterizer indexes them (DepthRows).
    DepthRows depth_rows() {
        return {frame_ ? band_depths_ : depths_.data(), index_of_row(rows_begin_)};
    }

    std::size_t index(int x, int y) const;

  private:
    Framebuffer() = default;  // for band_view
    std::size_t index_of_row(int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
    }
    std::size_t held_depth_count() const { return index_of_row(rows_end_ - rows_begin_); }
    const float* held_depths() const { return frame_ ? band_depths_ : depths_.data(); }

    int width_ = 0;
    int height_ = 0;
    int rows_begin_ = 0, rows_end_ = 0;  // the rows that can be drawn
    std::vector<Rgba8> colours_;         // a whole frame's
    std::vector<float> depths_;          // a whole frame's
    Framebuffer* frame_ = nullptr;       // a band view's frame
    float* band_depths_ = nullptr;       // a band view's depths, rows_begin_ first
    bool avx512_ = avx512_supported();
    bool avx2_ = avx2_supported();
};

}  // namespace weft::raster
