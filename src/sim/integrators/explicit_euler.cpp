// Explicit (forward) Euler: x_{n+1} = x_n + h v_n,  v_{n+1} = v_n + h a(x_n, v_n).
// First order, and not stable for any step on an undamped oscillator: its amplification
// factor is |1 + i h ω| > 1, so energy grows every step. It is here as the baseline every
// cloth tutorial starts from.
#include "sim/integrators/integrator.h"

namespace weft {

void step_explicit_euler(Cloth& cloth, const ForceField& field, double dt,
                         IntegratorWorkspace& work) {
    evaluate_forces(cloth, field, cloth.positions, cloth.velocities, work);
    const std::size_t count = cloth.particle_count();
    Vec3* x = cloth.positions.data();
    Vec3* v = cloth.velocities.data();
    const Vec3* f = work.scratch.forces.data();
    const double* inverse_mass = cloth.topology().inverse_masses.data();
    for_particle_ranges(work, count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
            x[p] += dt * v[p];
            v[p] += dt * inverse_mass[p] * f[p];
        }
    });
}

}  // namespace weft
