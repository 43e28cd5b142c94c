// The hand: the user grabs the cloth and pulls it. The grabbed particles are held, not towed:
// while the hand holds them they go where the hand takes them, as pins that move
// (kinematic particles), and the rest of the cloth answers through its own forces.
//
// - Every integrator steps a held particle with the velocity the hand prescribes, and the
//   step ends with it exactly where the hand put it. Implicit Euler takes the prescribed
//   velocities into its solve as Baraff and Witkin do for constrained particles, so the rest
//   of the cloth answers within the same step, at any dt.
// - The hand's point moves from where it is to each new target at the speed the targets
//   arrive with (one target a frame, several steps a frame): smooth within a frame, and on
//   release the cloth keeps the hand's velocity, so a fling flies.
// - The hand holds a patch: the particles within the radius whose falloff weight w is at
//   least 1/2 (and the grabbed one), carried as they were when grabbed, like fingers pinching
//   the fabric. The rest of the radius follows with its weight: each frame (1/60 s) closes
//   the fraction w of the gap between its velocity and the hand's. Not weighted positions:
//   a light-weighted particle closing a small share of its way each step trails a fast hand
//   by many spacings at one step a frame, and tears the patch apart.
// - The grip slips. A spring from a held particle to the free cloth stretched past
//   grip_stretch rest lengths pulls on the hand with k (grip_stretch - 1) L: the most any
//   spring at the hand can, the grip force. Past it the cloth slips from the hand, which
//   lets go. So a hand far beyond the cloth's reach pulls it taut and loses it, and no
//   spring is ever pulled to a runaway length. Where tearing is on with a limit below the
//   grip's, the cloth tears first.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sim/core/cloth.h"
#include "sim/core/hand_grip.h"
#include "sim/interaction/picking.h"

namespace weft {

struct Grab {
    std::vector<std::uint32_t> particles;  // held particles, ascending (pinned ones excluded)
    std::vector<double> weights;           // in [1/2, 1]: 1 at the grab point
    std::vector<Vec3> offsets;             // m, particle minus grab point when grabbed
    std::vector<std::uint32_t> followers;  // the rest of the radius, ascending
    std::vector<double> follower_weights;  // in (0, 1/2): 0 at the radius
    Vec3 target{0.0};                      // m, where the hand was last moved to
    Vec3 hand{0.0};                        // m, where the hand's grab point is now
    double hand_speed = 0.0;               // m/s, how fast the hand's point goes to the target
    // m/s: the fastest a hand moves. A cursor that jumps metres between two frames (a fast
    // mouse on a far grab plane) is not a hand moving at 100 m/s, and whipping the cloth at
    // that speed pumps more energy into it than an explicit step can carry.
    double max_hand_speed = 20.0;
    double last_pull_time = 0.0;  // s, simulated time of the last move of the target

    // The springs from a held particle to a free one, for the grip (ends as in the cloth).
    using GripSpring = HandGripSpring;
    std::vector<GripSpring> grip_springs;
    std::uint64_t grip_topology = 0;  // the topology version grip_springs were found in
    static constexpr double default_grip_stretch = 3.0;  // rest lengths
    double grip_stretch = default_grip_stretch;  // a spring at the hand longer than this slips it

    // This step's prescription, per held particle (the arrays above' order).
    std::vector<Vec3> goals;       // m, where the particle ends the step
    std::vector<Vec3> velocities;  // m/s, (goal - x) / h
    Vec3 hand_velocity{0.0};       // m/s, of the hand's point over this step

    bool active() const { return !particles.empty(); }
};

// A handle grabbing the cloth where `hit` is: every free particle within `radius` (m) of
// the hit point gets a weight (1 - (d/r)²)², held from 1/2 up, following below; the hit
// triangle's nearest corner is always held, so a small radius still grabs one particle.
Grab grab_cloth(const Cloth& cloth, const RayHit& hit, double radius);

// A new target for the hand at simulated time `time` (s): the hand's point goes there in the
// time the last target took to come (at least one step of dt, at most 1/30 s, a slow frame).
void move_hand(Grab& grab, const Vec3& target, double time, double dt);

// Before a step of dt: moves the hand's point on and sets each held particle's goal (the
// hand's point plus its offset) and prescribed velocity.
void prescribe_hand_motion(Grab& grab, const Cloth& cloth, double dt);

// Gives each held particle its prescribed velocity, for the step to take it to its goal, and
// brings each follower's velocity towards the hand's by its weight.
void start_hand_motion(const Grab& grab, Cloth& cloth, double dt);

// The springs from the hand to the free cloth, found again if the cloth's topology changed
// since (a tear, a cut).
void find_grip_springs(Grab& grab, const Cloth& cloth);

// After the step: each held particle where its goal is, at its prescribed velocity.
void hold_in_hand(const Grab& grab, Cloth& cloth);

// The largest length, in rest lengths, of the springs from the hand to the free cloth (1 if
// there are none): the grip slips past grab.grip_stretch.
double largest_grip_stretch(const Grab& grab, const Cloth& cloth);

// The same for the step about to be taken, before it: each held particle at its goal, each
// other end where its velocity takes it in dt. What an explicit step will find, since the
// cloth cannot answer the hand within it.
double coming_grip_stretch(const Grab& grab, const Cloth& cloth, double dt);

}  // namespace weft
