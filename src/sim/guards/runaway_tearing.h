// Runaway tearing: the divergence guard's eye for an unstable step with tearing on. Such a
// step does not diverge, it shreds: a spring that the unstable mode stretches past the tear
// limit breaks before it can run away, the values stay finite, and tearing takes the elastic
// energy away with the springs, so the energy guard sees the gain late (explicit Euler at
// 2 ms on tearing_sheet.toml: 1255 springs torn before it fires at 0.1 s) or, while the hand
// pulls, not at all.
//
// What tells shredding from tearing: a stable tear runs along a line. It opens where the load
// concentrates (the pins, the hand, a cut's end) and runs from there as a front; even a whole
// row failing at once under a sudden load breaks one line of springs, a share of about
// 1/side of the sheet. An unstable step grows its fastest mode, which alternates from one
// particle to the next all over the sheet, so its tears open over an area: a share of the
// sheet that does not shrink with its size. Measured on tearing_sheet.toml (24², 2162
// springs; docs/accuracy.md, 2026-11-25), the most springs broken within 0.05 s of
// simulated time, not counting those the hand holds an end of:
//   stable, no hand: 70 (the top row giving way at g = 2000 m/s²), 94 (a 108 m/s gale),
//     116 (brittle cloth, tear limit 1.05, falling apart under its own weight);
//   stable, a hand of radius 0.08–0.5 m pulled steadily or flicked ±5 m each frame: 121 at
//     the scene's tear limit 1.6, 200 at 1.2, and up to 285 at 1.05;
//   unstable, no hand: 372 (explicit Euler, 1 ms), 703 (RK4, 6 ms), 716 (symplectic Euler,
//     3 ms), 1255 (explicit Euler, 2 ms); with a hand holding on from the start, so that the
//     energy guard is blind: 354 to 1849.
// So the alarm: more than a tenth of the sheet's springs (216 here) within 0.05 s: 1.9×
// the most stable tearing without a hand, 1.8× with one at the scene's limit, and 1.6× below
// the least shredding. The margin is thin for a hand of 0.5 m (two fifths of the sheet) on
// weaker cloth: 200 at limit 1.2, and brittle cloth (the panel's lowest limit, 1.05) under a
// hand of 0.35 m or more flicked 10 m a frame breaks 248–285 and is flagged (the demo rolls
// back and lets go).
// A small sheet's line is a large share of it, so the alarm also needs two lines' worth: on
// a 10 × 10 sheet that is 22 % of it, and a sheet under ~6 × 6 (where a line is half the
// sheet) is left to the other guards. One unstable run stays below: velocity Verlet at 2 ms
// breaks 140 springs in 0.05 s (6 %), in bursts of 52 and 64; the energy guard catches it
// at 0.1 s (not while a hand pulls).
//
// Not counted, as not the motion's doing: springs cut by the user (they are not torn by a
// step), springs with an end held by the user's hand (the hand's own patch torn out), and
// the springs that break on the step after the tear limit was lowered (ignore_next_step).
// Cost: nothing on a step that tears nothing but dropping old entries; a binary search in
// the hand's particles per torn spring.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <span>
#include <string>

#include "sim/core/cloth.h"
#include "sim/interaction/grab.h"

namespace weft {

class RunawayTearingGuard {
  public:
    static constexpr double window = 0.05;        // s of simulated time
    static constexpr double allowed_share = 0.1;  // of the sheet's springs, within a window
    static constexpr double allowed_lines = 2.0;  // lines across the sheet, within a window

    // After a step that ended at `time` and tore `torn` (tearing's, before the cloth lost
    // them); `hand`: the user's, active or not.
    std::optional<std::string> check(const Cloth& cloth, std::span<const Spring> torn, double time,
                                     const Grab& hand);
    // The sheet was rebuilt or its springs changed other than by tearing and cutting (reset,
    // families switched): the window starts empty and the allowance is measured again.
    void forget() { valid_ = false; }
    // The tear limit was lowered or turned on: the springs past it break on the next step,
    // all at once and all over the sheet, by the user's choice.
    void ignore_next_step() { ignore_next_step_ = true; }

  private:
    struct Burst {
        double time;                             // s, when the step that tore them ended
        std::size_t springs;                     // torn in that step and counted
        int row_min, row_max, col_min, col_max;  // grid rows and columns of their particles
    };
    std::deque<Burst> recent_;  // steps that tore, within a window of the last one
    std::size_t recent_springs_ = 0;
    double allowed_ = 0.0;  // springs within a window
    bool valid_ = false;
    bool ignore_next_step_ = false;
};

}  // namespace weft
