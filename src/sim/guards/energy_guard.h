// Energy guard: the divergence guard's second eye, for the instabilities that show first as
// energy gained rather than as a spring run away: an unstable explicit step on a sheet
// draped over a ball gains tens of joules a tenth of a second while no spring is yet past
// the runaway stretch (explicit Euler on sheet_on_sphere.toml: +45 J by 0.5 s, +158 J by
// 0.55 s, caught by stretch only at 0.655 s).
//
// Without a hand on it, the cloth's mechanical energy E (kinetic + gravitational + elastic)
// can only grow by the wind's work: springs' dampers, air drag, inelastic contacts, strain
// limiting and implicit Euler's numerical damping all take energy away. So E - W (W: the
// wind's work so far) never rises far above the least value it has had, and when it does the
// step is gaining energy from nowhere. "Far": allowed_gain × the sheet's energy scale,
// M (|g| L + ½ (1 m/s)²) with M its mass and L its rest diagonal, the energy of letting it
// fall its own size: the symplectic methods' bounded oscillation of E and the small work of
// position corrections (a particle pushed out of a ball is lifted) stay far below it.
//
// Checked every check_interval of simulated time: a serial pass over the springs, 0.33 ms on
// a 128² sheet (measured while another build ran), so at one implicit step per 60 Hz frame
// it costs 0.11 ms a step on average, and an unstable run's growth (tens of joules in a
// tenth of a second) is seen within a twentieth. The wind's power
// Σ air_drag (w · v) sampled there and integrated by the trapezoid rule. While the user's hand
// pulls, the work it does is not measured: the reference follows E - W, and the check
// resumes from where the hand lets go.
#pragma once

#include <optional>
#include <string>

#include "parallel/worker_pool.h"
#include "sim/core/cloth.h"
#include "sim/core/force_pass.h"

namespace weft {

class EnergyGuard {
  public:
    static constexpr double check_interval = 0.05;  // s of simulated time
    static constexpr double allowed_gain = 0.5;     // × the energy scale

    // After a step that ended at `time` in `field` (its gravity and wind), the hand pulling
    // or not.
    std::optional<std::string> check(const Cloth& cloth, const ForceField& field, double time,
                                     bool hand_pulls, WorkerPool* pool = nullptr);
    // The state was replaced (reset, rollback, edits): start again from the next check.
    void forget() { valid_ = false; }

  private:
    bool valid_ = false;
    double next_check_ = 0.0;   // s
    double last_time_ = 0.0;    // s: of the last check
    double last_power_ = 0.0;   // W: the wind's, at the last check
    double work_ = 0.0;         // J: the wind's, since the first check
    double lowest_ = 0.0;       // J: the least E - W seen
    double lowest_time_ = 0.0;  // s
    double scale_ = 0.0;        // J
};

}  // namespace weft
