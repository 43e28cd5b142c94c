// Symplectic (semi-implicit) Euler: v_{n+1} = v_n + h a(x_n, v_n),  x_{n+1} = x_n + h v_{n+1}.
// First order, but symplectic: on an undamped system it conserves a modified energy, so the
// energy error stays bounded instead of drifting. Stable for h ω < 2.
#include "sim/integrators/integrator.h"

namespace weft {

bool step_symplectic_euler_fused(Cloth& cloth, const ForceField& field, double dt,
                                 IntegratorWorkspace& work, const RowsSteppedWork* after_rows) {
    ParticleSweep sweep;
    if (!work.settings.options.fused_grid_steps ||
        !step_grid_symplectic_euler(
            cloth, field, dt, work.scratch.next_positions, work.scratch.next_velocities,
            work.on_the_way.sweep_request ? &*work.on_the_way.sweep_request : nullptr, &sweep,
            work.settings.pool, work.settings.options.kernel_build, after_rows,
            work.settings.options.single_precision_springs))
        return false;
    ++work.statistics.force_evaluations;
    if (work.on_the_way.sweep_request) work.on_the_way.sweep_result = sweep;
    return true;
}

void step_symplectic_euler(Cloth& cloth, const ForceField& field, double dt,
                           IntegratorWorkspace& work) {
    // A plain grid steps in the force pass itself (grid_force_pass.h): the same bits.
    if (step_symplectic_euler_fused(cloth, field, dt, work)) return;
    evaluate_forces(cloth, field, cloth.positions, cloth.velocities, work);
    const std::size_t count = cloth.particle_count();
    Vec3* x = cloth.positions.data();
    Vec3* v = cloth.velocities.data();
    const Vec3* f = work.scratch.forces.data();
    const double* inverse_mass = cloth.topology().inverse_masses.data();
    for_particle_ranges(work, count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
            v[p] += dt * inverse_mass[p] * f[p];
            x[p] += dt * v[p];
        }
    });
}

}  // namespace weft
