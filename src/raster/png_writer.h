// Writing the framebuffer to a PNG file (RGBA, 8 bits per channel, top row first), through
// stb_image_write. Failure is reported, never fatal: an unwritable path returns false.
#pragma once

#include <string>

#include "raster/framebuffer.h"

namespace weft::raster {

// Returns true on success. On failure returns false and, if `error` is given, sets it to a
// message naming the path and the reason.
bool write_png(const Framebuffer& framebuffer, const std::string& path,
               std::string* error = nullptr);

}  // namespace weft::raster
