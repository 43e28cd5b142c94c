#include "app/step_clock.h"

#include <algorithm>
#include <cmath>

namespace weft::app {

StepClock::Plan StepClock::advance(double elapsed, double dt, double seconds_per_step,
                                   double other_seconds) {
    Plan plan;
    // A frame longer than a quarter second (a window drag, a debugger) is not caught up.
    owed_ += std::min(std::max(elapsed, 0.0), 0.25);
    const auto wanted = static_cast<long long>(std::floor(owed_ / dt));
    // An unknown cost (the first frame, a cloth just rebuilt) buys one step, which measures
    // it. Taking all that was owed instead stepped a quarter second of a 1024 x 1024 sheet
    // in one frame: a 6 s freeze.
    long long affordable = 1;
    if (seconds_per_step > 0.0)
        affordable = std::max<long long>(
            1, static_cast<long long>(budget(other_seconds) / seconds_per_step));
    plan.steps = static_cast<int>(std::min({wanted, affordable, 100000LL}));
    owed_ -= plan.steps * dt;
    if (plan.steps < wanted) {
        plan.behind = true;
        // What one slow frame (a busy host, a rebuild) could not afford is owed to the next
        // ones, which have budget to spare when the machine keeps pace on average; beyond
        // max_debt it is dropped, so a machine that cannot keep pace does not spiral.
        owed_ = std::min(owed_, max_debt + std::fmod(owed_, dt));
    }
    return plan;
}

}  // namespace weft::app
