#include "app/frame_capture.h"

#include <cstdio>
#include <filesystem>
#include <utility>

#include "raster/png_writer.h"

namespace weft::app {

FrameCapture::FrameCapture(std::string folder, double start_time, double frames_per_second)
    : folder_(std::move(folder)),
      origin_(start_time),
      frames_per_second_(frames_per_second),
      last_time_(start_time) {}

bool FrameCapture::write_due(const raster::Framebuffer& image, double time, double dt,
                             std::string& error) {
    // A restart: the clock went back. The next frame is due now, and numbering goes on.
    if (time < last_time_) origin_ = time - static_cast<double>(next_) / frames_per_second_;
    last_time_ = time;
    while (static_cast<double>(next_) / frames_per_second_ <= time - origin_ + 0.5 * dt) {
        char name[32];
        std::snprintf(name, sizeof name, "frame-%05llu.png", next_);
        const std::string path = (std::filesystem::path(folder_) / name).string();
        if (!raster::write_png(image, path, &error)) return false;
        ++next_;
    }
    return true;
}

}  // namespace weft::app
