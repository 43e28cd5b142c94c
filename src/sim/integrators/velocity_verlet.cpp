// Velocity Verlet (kick-drift-kick):
//   v_{n+½} = v_n + ½ h a_n
//   x_{n+1} = x_n + h v_{n+½}
//   v_{n+1} = v_{n+½} + ½ h a(x_{n+1}, v_{n+1})
// Second order, symplectic for position-only forces, stable for h ω < 2, one force
// evaluation per step (a_{n+1} is reused as the next step's a_n).
//
// The trap: with damping and drag the last half-kick needs v_{n+1}, which it is computing.
// Using v_{n+½} there makes the force O(h) wrong and the method first order. Solving the
// half-kick exactly would couple all particles through the spring dampers (a linear solve
// per step). Instead the force is evaluated at the predicted velocity
// v* = v_{n+½} + ½ h a_n, which differs from v_{n+1} by ½ h (a_{n+1} - a_n) = O(h²); the
// kick multiplies that by h, a local error O(h³), so the method stays second order.
#include "sim/integrators/integrator.h"

namespace weft {

void step_velocity_verlet(Cloth& cloth, const ForceField& field, double dt,
                          IntegratorWorkspace& work) {
    const std::size_t count = cloth.particle_count();
    Vec3* x = cloth.positions.data();
    Vec3* v = cloth.velocities.data();
    Vec3* a = work.history.accelerations.data();
    Vec3* v_predicted = work.scratch.stage_velocities.data();
    const double* inverse_mass = cloth.topology().inverse_masses.data();
    const double half_dt = 0.5 * dt;

    if (!work.history.valid) {
        evaluate_forces(cloth, field, cloth.positions, cloth.velocities, work);
        for (std::size_t p = 0; p < count; ++p) a[p] = inverse_mass[p] * work.scratch.forces[p];
        work.history.valid = true;
    }
    for_particle_ranges(work, count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
            v[p] += half_dt * a[p];  // now v_{n+½}
            x[p] += dt * v[p];
            v_predicted[p] = v[p] + half_dt * a[p];
        }
    });
    evaluate_forces(cloth, field, cloth.positions, work.scratch.stage_velocities, work);
    const Vec3* f = work.scratch.forces.data();
    for_particle_ranges(work, count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
            a[p] = inverse_mass[p] * f[p];
            v[p] += half_dt * a[p];
        }
    });
}

}  // namespace weft
