// The force pass: every force on every particle, accumulated in one sweep over flat arrays.
// All integrators share it; they differ only in where they evaluate it.
#pragma once

#include <span>

#include "parallel/worker_pool.h"
#include "sim/collision/colliders.h"
#include "sim/core/cloth.h"
#include "sim/core/hand_grip.h"
#include "sim/grid/kernel_build.h"

namespace weft {

// The external force field, constant over a step.
struct ForceField {
    Vec3 gravity{0.0, -9.81, 0.0};  // m/s²
    double air_drag = 0.0;          // N·s/m per particle: f = -air_drag (v - wind)
    Vec3 wind{0.0};                 // m/s
    // The particles the hand holds this step (grab.h), ascending: their velocities are
    // prescribed. Only the implicit solves read it; other steps are corrected after.
    std::span<const std::uint32_t> held;
    // The hand's grip, where the step's solve answers the hand (implicit Euler): the springs
    // at the hand and the stretch, in rest lengths, past which the grip slips; 0: the grip is
    // not judged within the step.
    std::span<const HandGripSpring> grip_springs;
    double grip_stretch = 0.0;
    std::span<const Collider> colliders;  // those with repulsion contacts, if any
    // Every collider, for the structured implicit step, which holds particles on the impulse
    // ones inside its solve (integrators/implicit_contacts.h); the other steps leave those to
    // the contact pass after the step.
    std::span<const Collider> solids;
};

// Writes into `forces` the total force on each particle (N) for the state (positions,
// velocities), which need not be cloth.positions/velocities (RK4 evaluates at stages):
//
//   gravity  m g
//   drag     -air_drag (v - wind)
//   contact  repulsion from colliders (colliders.h), only if the scene has such colliders
//   springs  for spring (i, j) with rest length L, d = x_j - x_i, u = d / |d|:
//            f_i = (k (|d| - L) + c ((v_j - v_i) · u)) u,   f_j = -f_i
//
// Forces on pinned particles are computed like any other; integrators ignore them through
// the zero inverse mass. A spring of zero length has no direction and exerts no force.
//
// With a pool, each spring colour is split between its threads; the result is the same bit
// for bit whatever the number of threads (each particle gets its forces colour by colour)
// and whatever the kernel build `level` of the structured pass (kernel_build.h).
void accumulate_forces(const Cloth& cloth, const ForceField& field, std::span<const Vec3> positions,
                       std::span<const Vec3> velocities, std::span<Vec3> forces,
                       WorkerPool* pool = nullptr, SimdLevel level = supported_simd_level());

// Only the internal (spring) forces: the part that must conserve momentum.
void accumulate_spring_forces(const SpringGroup& group, std::span<const Vec3> positions,
                              std::span<const Vec3> velocities, std::span<Vec3> forces,
                              WorkerPool* pool = nullptr);

}  // namespace weft
