// Classical fourth-order Runge-Kutta on the first-order system y = (x, v), y' = (v, a(x, v)):
//   k1 = f(y_n), k2 = f(y_n + ½h k1), k3 = f(y_n + ½h k2), k4 = f(y_n + h k3)
//   y_{n+1} = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4)
// Fourth order, four force evaluations per step, stable on an undamped oscillator for
// h ω < 2√2. Not symplectic: its energy slowly decays.
#include "sim/integrators/integrator.h"

namespace weft {

void step_rk4(Cloth& cloth, const ForceField& field, double dt, IntegratorWorkspace& work) {
    const std::size_t count = cloth.particle_count();
    Vec3* x = cloth.positions.data();
    Vec3* v = cloth.velocities.data();
    Vec3* stage_x = work.scratch.stage_positions.data();
    Vec3* stage_v = work.scratch.stage_velocities.data();
    Vec3* x_rate_sum = work.scratch.position_rate_sum.data();
    Vec3* v_rate_sum = work.scratch.velocity_rate_sum.data();
    const double* inverse_mass = cloth.topology().inverse_masses.data();

    // Stage s is evaluated at y_n + stage_offset[s] h k_s; its slope enters with weight[s].
    constexpr double weight[4] = {1.0, 2.0, 2.0, 1.0};
    constexpr double next_stage_offset[3] = {0.5, 0.5, 1.0};

    // Stage 1 is evaluated at y_n itself.
    evaluate_forces(cloth, field, cloth.positions, cloth.velocities, work);
    for (int stage = 0; stage < 4; ++stage) {
        if (stage > 0)
            evaluate_forces(cloth, field, work.scratch.stage_positions,
                            work.scratch.stage_velocities, work);
        const Vec3* f = work.scratch.forces.data();
        const Vec3* k_x = stage == 0 ? v : stage_v;  // dx/dt at this stage
        for_particle_ranges(work, count, [&](std::size_t begin, std::size_t end) {
            for (std::size_t p = begin; p < end; ++p) {
                const Vec3 k_v = inverse_mass[p] * f[p];  // dv/dt at this stage
                const Vec3 slope_x = k_x[p];
                if (stage == 0) {
                    x_rate_sum[p] = slope_x;
                    v_rate_sum[p] = k_v;
                } else {
                    x_rate_sum[p] += weight[stage] * slope_x;
                    v_rate_sum[p] += weight[stage] * k_v;
                }
                if (stage < 3) {
                    const double offset = next_stage_offset[stage] * dt;
                    stage_x[p] = x[p] + offset * slope_x;
                    stage_v[p] = v[p] + offset * k_v;
                }
            }
        });
    }
    const double sixth_dt = dt / 6.0;
    for_particle_ranges(work, count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
            x[p] += sixth_dt * x_rate_sum[p];
            v[p] += sixth_dt * v_rate_sum[p];
        }
    });
}

}  // namespace weft
