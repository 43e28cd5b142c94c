// Linear stability of explicit stepping: the highest angular frequency of the cloth's small
// undamped oscillations about its current state, and the largest step each method can take.
//
// Linearised about a state, the spring forces are f = -K δx with K the stiffness matrix
// (the Hessian of the elastic energy); the oscillation frequencies are ω² = eigenvalues of
// M⁻¹K. A method is stable on the fastest mode while h·ω_max stays inside its stability
// interval: 2 for symplectic Euler and both Verlets, 2√2 for RK4. Explicit Euler has none
// without damping (its amplification factor is √(1 + h²ω²) > 1 for every h).
#pragma once

#include "sim/core/cloth.h"
#include "sim/scene/scene.h"

namespace weft {

// ω_max (rad/s) by power iteration on M^{-1/2} K M^{-1/2} over the free particles, with the
// full spring Hessian k[u uᵀ + (1 - L/l)(I - u uᵀ)] of every spring at its current length l.
// Accurate to `relative_tolerance` in ω² (or stops after max_iterations).
double highest_angular_frequency(const Cloth& cloth, int max_iterations = 5000,
                                 double relative_tolerance = 1e-7);

// A cheap upper bound for ω_max, for every frame of the demo (Gershgorin's theorem on M⁻¹K
// at rest length): ω²_max <= max over particles i of 2 Σ_j k_ij / m_i.
double angular_frequency_bound(const Cloth& cloth);

// A cheap upper bound for the damping rate (1/s) of the fastest-decaying mode, by Gershgorin
// on M⁻¹C: max over particles i of (2 Σ_j c_ij + air_drag) / m_i.
double damping_rate_bound(const Cloth& cloth, double air_drag);

// The demo's per-frame step-limit estimate, conservative: damping narrows the stable range
// of the methods that treat it explicitly. For symplectic Euler on x'' + c x' + ω² x = 0 the
// step must satisfy h²ω² + 2hc < 4, i.e. h < 4 / (c + √(c² + 4ω²)); the Verlets share the
// bound and RK4's interval is taken √2 times longer. Explicit Euler: 0 (no guaranteed step).
double estimated_step_limit(const Cloth& cloth, double air_drag, Integrator integrator);

// The largest h with h·ω_max inside the method's stability interval; 0 for explicit Euler,
// which has no stable step without damping; infinity for implicit Euler.
double stable_step_limit(Integrator integrator, double omega_max);

}  // namespace weft
