// Colours: the framebuffer stores 8-bit RGBA; shading works in float RGB in [0, 1].
//
// Colours are display values: nothing here applies a gamma curve, so what a shader returns is
// what the PNG or the window shows.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

namespace weft::raster {

// One framebuffer pixel, laid out as stb_image_write and SDL's ABGR8888 expect: r, g, b, a.
struct Rgba8 {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;

    friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

// Rounds a channel in [0, 1] to [0, 255]; values outside are clamped, NaN becomes 0.
// Written as selections, with no branch, so that a loop of it over many pixels vectorises
// (a NaN fails `value > 0`).
inline std::uint8_t to_channel(float value) {
    const float clamped = value > 0.0f ? (value < 1.0f ? value : 1.0f) : 0.0f;
    return static_cast<std::uint8_t>(static_cast<int>(clamped * 255.0f + 0.5f));
}

inline Rgba8 to_rgba8(const glm::vec3& rgb, float alpha = 1.0f) {
    return {to_channel(rgb.r), to_channel(rgb.g), to_channel(rgb.b), to_channel(alpha)};
}

inline glm::vec3 to_vec3(Rgba8 colour) {
    return glm::vec3(colour.r, colour.g, colour.b) * (1.0f / 255.0f);
}

}  // namespace weft::raster
