#include "sim/integrators/integrator.h"

namespace weft {

void IntegratorWorkspace::resize(std::size_t particle_count, Integrator integrator) {
    using Method = Integrator;
    const bool rk4 = integrator == Method::rk4;
    // Which arrays each method reads (integrator.h); every method evaluates forces.
    const std::pair<std::vector<Vec3>*, bool> arrays[] = {
        {&forces, true},
        {&accelerations, integrator == Method::velocity_verlet},
        {&previous_positions, integrator == Method::verlet},
        {&stage_positions, rk4},
        {&stage_velocities, rk4 || integrator == Method::velocity_verlet},
        {&position_rate_sum, rk4},
        {&velocity_rate_sum, rk4},
        {&next_positions, integrator == Method::symplectic_euler},
        {&next_velocities, integrator == Method::symplectic_euler},
    };
    for (auto [array, used] : arrays) {
        if (used)
            array->assign(particle_count, Vec3(0.0));
        else
            std::vector<Vec3>().swap(*array);
    }
    if (integrator != Method::implicit_euler) {  // implicit Euler sizes its own on first use
        for (std::vector<Vec3>* array :
             {&implicit_delta_v, &implicit_rhs, &implicit_residual, &implicit_direction,
              &implicit_product, &implicit_step_start_positions, &implicit_step_start_velocities})
            std::vector<Vec3>().swap(*array);
        std::vector<ImplicitSpringTerms>().swap(implicit_springs);
        implicit_grid = ImplicitGridSolver{};
    }
    implicit_start_depth = 0;
    history_valid = false;
}

void evaluate_forces(const Cloth& cloth, const ForceField& field, std::span<const Vec3> positions,
                     std::span<const Vec3> velocities, IntegratorWorkspace& work) {
    accumulate_forces(cloth, field, positions, velocities, work.forces, work.pool,
                      work.options.kernel_build);
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
