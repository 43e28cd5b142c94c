#include "sim/integrators/integrator.h"

namespace weft {

void IntegratorWorkspace::resize(std::size_t particle_count) {
    for (std::vector<Vec3>* array :
         {&forces, &accelerations, &previous_positions, &stage_positions, &stage_velocities,
          &position_rate_sum, &velocity_rate_sum, &next_positions, &next_velocities})
        array->assign(particle_count, Vec3(0.0));
    history_valid = false;
}

void evaluate_forces(const Cloth& cloth, const ForceField& field, std::span<const Vec3> positions,
                     std::span<const Vec3> velocities, IntegratorWorkspace& work) {
    accumulate_forces(cloth, field, positions, velocities, work.forces, work.pool);
    ++work.force_evaluations;
}

StepFunction step_function(Integrator integrator) {
    switch (integrator) {
        case Integrator::explicit_euler:
            return step_explicit_euler;
        case Integrator::symplectic_euler:
            return step_symplectic_euler;
        case Integrator::verlet:
            return step_verlet;
        case Integrator::velocity_verlet:
            return step_velocity_verlet;
        case Integrator::rk4:
            return step_rk4;
        case Integrator::implicit_euler:
            return step_implicit_euler;
    }
    return nullptr;
}

int force_evaluations_per_step(Integrator integrator) {
    return integrator == Integrator::rk4 ? 4 : 1;
}

}  // namespace weft
