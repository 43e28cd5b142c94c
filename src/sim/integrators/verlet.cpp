// Position (Störmer) Verlet: x_{n+1} = 2 x_n - x_{n-1} + h² a(x_n, v_n).
// Second order and symplectic for position-only forces; stable for h ω < 2.
//
// Two traps cost an order silently, and both are avoided here:
//  * Start. With x_{-1} = x_0 - h v_0 the first step carries an O(h²) error in x_{-1};
//    the two-step recurrence amplifies a start error by the number of steps, so the method
//    drops to first order. The Taylor start x_{-1} = x_0 - h v_0 + ½ h² a_0 is O(h³).
//  * Velocity. Damping and drag need v_n. The backward difference (x_n - x_{n-1}) / h is
//    only O(h) accurate, which again makes the whole method first order once forces depend
//    on velocity. We use the central difference v_n = (x_{n+1} - x_{n-1}) / 2h, which is
//    O(h²), carried forward by one step of the acceleration to estimate the next step's
//    velocity: v_{n+1} ≈ (x_{n+1} - x_{n-1}) / 2h + h a_n, also O(h²).
#include "sim/integrators/integrator.h"

namespace weft {

void step_verlet(Cloth& cloth, const ForceField& field, double dt, IntegratorWorkspace& work) {
    const std::size_t count = cloth.particle_count();
    Vec3* x = cloth.positions.data();
    Vec3* v = cloth.velocities.data();
    Vec3* x_previous = work.history.previous_positions.data();
    const double* inverse_mass = cloth.topology().inverse_masses.data();

    evaluate_forces(cloth, field, cloth.positions, cloth.velocities, work);
    const Vec3* f = work.scratch.forces.data();
    if (!work.history.valid) {
        // Taylor start: x_{-1} = x_0 - h v_0 + ½ h² a_0.
        for (std::size_t p = 0; p < count; ++p)
            x_previous[p] = x[p] - dt * v[p] + (0.5 * dt * dt * inverse_mass[p]) * f[p];
        work.history.valid = true;
    }
    const double dt_squared = dt * dt;
    const double inverse_two_dt = 1.0 / (2.0 * dt);
    for_particle_ranges(work, count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
            const Vec3 acceleration = inverse_mass[p] * f[p];
            const Vec3 x_next = 2.0 * x[p] - x_previous[p] + dt_squared * acceleration;
            v[p] = (x_next - x_previous[p]) * inverse_two_dt + dt * acceleration;
            x_previous[p] = x[p];
            x[p] = x_next;
        }
    });
}

}  // namespace weft
