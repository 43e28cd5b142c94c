// Frames out of the window (F9): the view as drawn, one PNG per 1/frames_per_second s of
// simulated time, into a folder of their own, named as --frames names them
// (frame-00000.png, frame-00001.png, ...), so scripts/make-video.sh takes either.
#pragma once

#include <string>

#include "raster/framebuffer.h"

namespace weft::app {

class FrameCapture {
  public:
    // Frame 0 is due at simulated time `start_time` (s).
    FrameCapture(std::string folder, double start_time, double frames_per_second = 30.0);

    // Writes every frame due by simulated time `time` (s), stepped by `dt` (s), as `image`:
    // none while the run is paused, one for each 1/frames_per_second s it advanced (the same
    // image when a window frame stepped over several). After a restart (the time went back)
    // the numbering goes on. False, with the reason, when a frame cannot be written.
    bool write_due(const raster::Framebuffer& image, double time, double dt, std::string& error);

    const std::string& folder() const { return folder_; }
    unsigned long long frames_written() const { return next_; }

  private:
    std::string folder_;
    double origin_;             // s, simulated time of frame 0
    double frames_per_second_;  // Hz
    unsigned long long next_ = 0;
    double last_time_;  // s, simulated time at the last call
};

}  // namespace weft::app
