// StepClock: how many fixed steps of dt a frame takes so that simulated time keeps pace with
// wall time — capped by a CPU budget per frame, so a slow machine (or a tiny dt) drops time
// instead of spiralling into ever longer frames. SDL-free, so it is unit-tested.
#pragma once

namespace weft::app {

class StepClock {
  public:
    // budget: most seconds of stepping per frame (wall clock)
    explicit StepClock(double budget_seconds = 1.0 / 40.0) : budget_(budget_seconds) {}

    struct Plan {
        int steps = 0;        // steps to take this frame
        bool behind = false;  // the budget cut the frame short: simulated time fell behind
    };

    // `elapsed` wall seconds passed since the last frame; `seconds_per_step` is the recent
    // cost of one step, or 0 if unknown: then the frame takes one step, to measure it.
    Plan advance(double elapsed, double dt, double seconds_per_step);

    // s: the most simulated time a frame that fell behind leaves owed to the next frames.
    // Dropping every shortfall at once lost 4-8 % of real time on the 64² drape, whose
    // steps take about 0.7 of dt with the host's speed varying from frame to frame.
    static constexpr double max_debt = 0.1;

    void reset() { owed_ = 0.0; }
    double owed() const { return owed_; }  // s of simulated time not yet stepped

  private:
    double budget_;
    double owed_ = 0.0;
};

}  // namespace weft::app
