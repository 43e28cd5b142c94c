#include "raster/framebuffer.h"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace weft::raster {
namespace {

void check_size(int width, int height) {
    auto valid = [](int side) { return side >= 1 && side <= Framebuffer::max_side; };
    if (!valid(width) || !valid(height)) {
        throw std::invalid_argument("framebuffer size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " is outside 1.." +
                                    std::to_string(Framebuffer::max_side) + " per side");
    }
}

}  // namespace

Framebuffer::Framebuffer(int width, int height) {
    resize(width, height);
    clear(Rgba8{0, 0, 0, 255});
}

void Framebuffer::resize(int width, int height) {
    assert(frame_ == nullptr);
    check_size(width, height);
    width_ = width;
    height_ = height;
    rows_begin_ = 0;
    rows_end_ = height;
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    colours_.resize(count);
    depths_.resize(count);
}

void Framebuffer::clear(Rgba8 colour, float depth) {
    clear(colour, depth, bounds());
}

void Framebuffer::clear(Rgba8 colour, float depth, const PixelRect& rect) {
    const PixelRect inside = rect.intersect(bounds());
    if (inside.empty()) return;
    // Colours are filled one row and copied to the others: a fill of four-byte structs
    // compiles to one store per pixel, which took two thirds of a 1280-wide band's clear;
    // memcpy moves whole vectors.
    const auto width = static_cast<std::size_t>(inside.width());
    Rgba8* const colours = this->colours().data();
    const DepthRows depths = depth_rows();
    Rgba8* const first_row = colours + index(inside.x_begin, inside.y_begin);
    std::fill_n(first_row, width, colour);
    for (int y = inside.y_begin; y < inside.y_end; ++y) {
        const std::size_t first = index(inside.x_begin, y);
        if (y > inside.y_begin) std::memcpy(colours + first, first_row, width * sizeof(Rgba8));
        std::fill_n(&depths[first], width, depth);
    }
}

Framebuffer Framebuffer::band_view(Framebuffer& frame, int y_begin, int y_end,
                                   std::vector<float>& depth_storage) {
    assert(frame.frame_ == nullptr && 0 <= y_begin && y_begin <= y_end && y_end <= frame.height_);
    Framebuffer view;
    view.width_ = frame.width_;
    view.height_ = frame.height_;
    view.rows_begin_ = y_begin;
    view.rows_end_ = y_end;
    view.frame_ = &frame;
    view.avx512_ = frame.avx512_;
    view.avx2_ = frame.avx2_;
    depth_storage.resize(view.held_depth_count());
    view.band_depths_ = depth_storage.data();
    return view;
}

void Framebuffer::write_back_depths() {
    if (frame_ == nullptr) return;
    const std::size_t count = held_depth_count();
    float* to = frame_->depths_.data() + index_of_row(rows_begin_);
    const float* from = band_depths_;
#if defined(__SSE2__)
    // Streaming stores: the frame's old depths are not read from memory first, and this
    // band's do not displace the next band's from the cache.
    std::size_t i = 0;
    for (; i < count && reinterpret_cast<std::uintptr_t>(to + i) % 16 != 0; ++i) to[i] = from[i];
    for (; i + 16 <= count; i += 16) {  // a cache line a round
        _mm_stream_ps(to + i, _mm_loadu_ps(from + i));
        _mm_stream_ps(to + i + 4, _mm_loadu_ps(from + i + 4));
        _mm_stream_ps(to + i + 8, _mm_loadu_ps(from + i + 8));
        _mm_stream_ps(to + i + 12, _mm_loadu_ps(from + i + 12));
    }
    for (; i + 4 <= count; i += 4) _mm_stream_ps(to + i, _mm_loadu_ps(from + i));
    for (; i < count; ++i) to[i] = from[i];
    _mm_sfence();
#else
    std::memcpy(to, from, count * sizeof(float));
#endif
}

std::size_t Framebuffer::index(int x, int y) const {
    assert(contains(x, y));
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
}

}  // namespace weft::raster
