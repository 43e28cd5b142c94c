#include "raster/framebuffer.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <stdexcept>
#include <string>

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
    check_size(width, height);
    width_ = width;
    height_ = height;
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
    Rgba8* const first_row = colours_.data() + index(inside.x_begin, inside.y_begin);
    std::fill_n(first_row, width, colour);
    for (int y = inside.y_begin; y < inside.y_end; ++y) {
        const std::size_t first = index(inside.x_begin, y);
        if (y > inside.y_begin)
            std::memcpy(colours_.data() + first, first_row, width * sizeof(Rgba8));
        std::fill_n(depths_.begin() + static_cast<std::ptrdiff_t>(first), width, depth);
    }
}

std::size_t Framebuffer::index(int x, int y) const {
    assert(contains(x, y));
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
}

}  // namespace weft::raster
