// StepClock: how many fixed steps of dt a frame takes so that simulated time keeps pace with
// wall time — capped by a CPU budget per frame, so a slow machine (or a tiny dt) drops time
// instead of spiralling into ever longer frames. SDL-free, so it is unit-tested.
#pragma once

#include <algorithm>

namespace weft::app {

class StepClock {
  public:
    // budget: seconds of stepping a frame may always take (wall clock). A frame whose other
    // work (drawing, the panel) leaves more of floor_period gets that instead: stepping may
    // fill a frame down to 30 fps (floor_period), and below it real time gives way, not the
    // frame rate.
    // A fixed 25 ms cut a 256² implicit sheet, whose 1/60 s step takes 14 ms here, to one
    // step a frame (0.84 of real time at 42 fps) where two fit in a 30 fps frame.
    explicit StepClock(double budget_seconds = 1.0 / 40.0) : budget_(budget_seconds) {}
    static constexpr double floor_period = 1.0 / 30.0;  // s: the frame rate stepping keeps

    struct Plan {
        int steps = 0;        // steps to take this frame
        bool behind = false;  // the budget cut the frame short: simulated time fell behind
    };

    // `elapsed` wall seconds passed since the last frame; `seconds_per_step` is the recent
    // cost of one step, or 0 if unknown: then the frame takes one step, to measure it;
    // `other_seconds` is what the frame spends besides stepping (the last frame's), or 0 if
    // unknown: then the fixed budget holds.
    Plan advance(double elapsed, double dt, double seconds_per_step, double other_seconds = 0.0);

    // s: the most stepping a frame that spends other_seconds on the rest may take.
    double budget(double other_seconds) const {
        return other_seconds > 0.0 ? std::max(budget_, floor_period - other_seconds) : budget_;
    }

    // s: the most simulated time a frame that fell behind leaves owed to the next frames.
    // Dropping every shortfall at once lost 4-8 % of real time on the 64² drape, whose
    // steps take about 0.7 of dt with the host's speed varying from frame to frame.
    static constexpr double max_debt = 0.1;
    // s: the longest step the window takes. A frame carries at most max_debt of simulated
    // time over from one that fell behind, so a longer step could wait for ever, and under
    // ten steps a second no longer reads as motion.
    static constexpr double max_dt = max_debt;

    void reset() { owed_ = 0.0; }
    double owed() const { return owed_; }  // s of simulated time not yet stepped

  private:
    double budget_;
    double owed_ = 0.0;
};

}  // namespace weft::app
