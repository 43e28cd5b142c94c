// Contacts with solids inside the structured implicit step: particles held on a sphere's or a
// plane's surface by constraints filtered out of the conjugate-gradient solve (Baraff &
// Witkin 1998, section 5.3), instead of being pushed out after it.
//
// Why: at a frame-sized step the solve moves the whole sheet a long way, believing every
// particle free. When the contact pass then moves the particles that went into a solid back
// out, one by one, the springs to their neighbours, which the solve placed for the other
// positions, are left stretched: a 64² sheet draped over a ball and the ground at 1/60 s
// diverged after 2 s (a 64² sheet on a ball alone), or, with the ground beside it, came to
// rest 30 % over its rest length where the explicit reference rests at 6 %. Held
// inside the solve, a particle's velocity along the normal is prescribed and everything
// else, its sliding and all its neighbours, is solved knowing it.
//
// Which particles, per step, from the state at its start (like a speculative contact):
// those that would cross the surface within the step, moving as they move under gravity,
// d + h v·n + h² g·n < 0 (d: the signed distance, n: the outward normal), and those inside.
// Each gets n·v1 = -d/h: it ends the step on the surface (out of it, if it was inside;
// with the collider's restitution, if it was touching and approaching). One surface a
// particle: the one it would cross deepest.
//
// A constraint is an equality, so it could pull. After the solve, A v1 - b at a held
// particle is the impulse its surface gave it (N·s; b and g as in implicit_grid_kernel.h). Where
// one points into the solid and the particle is outside it, the surface would have pulled: those
// particles are let go and the step is solved again from where it stands (one round of an
// active-set method; Baraff and Witkin release such constraints a step later instead, which left
// particles chattering between held and free at 6 cm/s on a draped sheet). Where the impulse
// pushes, Coulomb friction takes up to friction × that impulse from the particle's sliding
// momentum, as the impulse response does (colliders.h). The contact pass after the step still runs
// and catches whatever the constraints did not hold (a second surface, a particle let go).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sim/collision/colliders.h"
#include "sim/core/cloth.h"
#include "sim/integrators/implicit/implicit_grid_kernel.h"

namespace weft {

struct ContactConstraint {
    std::uint32_t particle = 0;
    Vec3 normal{0.0};               // unit, out of the solid
    double distance = 0.0;          // m: signed, at the step's start
    double normal_speed = 0.0;      // m/s: n · v1, prescribed
    double friction = 0.0;          // Coulomb coefficient of the surface
    double rhs_along_normal = 0.0;  // N·s: n · g before g was filtered
};

struct ImplicitContacts {
    std::vector<ContactConstraint> held;  // this step's, ascending by particle

    // Chooses the particles held this step (impulse colliders only) from the cloth's state
    // at its start, after clearing the previous step's normals from the job. Particles
    // something else fixes (`fixed` nonzero: pinned, or in the hand) are left to it.
    void choose(const Cloth& cloth, std::span<const Collider> solids, const Vec3& gravity,
                double dt, std::span<const std::uint8_t> fixed, implicit_kernel::Job& job);

    // Enters the chosen particles in the job: their normals, g filtered (its normal part
    // kept for the impulse), and the guess given its prescribed normal speed.
    void hold(implicit_kernel::Job& job);

    // After a solve, with job.applied = A (v1 - v_k) unfiltered: lets go of the particles
    // outside their surface that it pulled (their normal and g restored), and returns how many.
    std::size_t let_go_of_pulled(implicit_kernel::Job& job);

    // After the last solve, with job.applied = A (v1 - v_k) unfiltered: friction from each held
    // particle's pushing impulse, on job.solution.
    void apply_friction(const Cloth& cloth, implicit_kernel::Job& job) const;
};

}  // namespace weft
