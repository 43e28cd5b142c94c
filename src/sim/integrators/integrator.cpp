#include "sim/integrators/integrator.h"

namespace weft {

void IntegratorWorkspace::resize(std::size_t particle_count, Integrator integrator) {
    using Method = Integrator;
    const bool rk4 = integrator == Method::rk4;
    // Which arrays each method reads (integrator.h); every method evaluates forces.
    const std::pair<std::vector<Vec3>*, bool> arrays[] = {
        {&scratch.forces, true},
        {&history.accelerations, integrator == Method::velocity_verlet},
        {&history.previous_positions, integrator == Method::verlet},
        {&scratch.stage_positions, rk4},
        {&scratch.stage_velocities, rk4 || integrator == Method::velocity_verlet},
        {&scratch.position_rate_sum, rk4},
        {&scratch.velocity_rate_sum, rk4},
        {&scratch.next_positions, integrator == Method::symplectic_euler},
        {&scratch.next_velocities, integrator == Method::symplectic_euler},
    };
    for (auto [array, used] : arrays) {
        if (used)
            array->assign(particle_count, Vec3(0.0));
        else
            std::vector<Vec3>().swap(*array);
    }
    if (integrator != Method::implicit_euler) {  // implicit Euler sizes its own on first use
        for (std::vector<Vec3>* array :
             {&scratch.implicit_delta_v, &scratch.implicit_rhs, &scratch.implicit_residual,
              &scratch.implicit_direction, &scratch.implicit_product,
              &scratch.implicit_step_start_positions, &scratch.implicit_step_start_velocities,
              &scratch.implicit_linearised_positions, &scratch.implicit_linearised_velocities})
            std::vector<Vec3>().swap(*array);
        std::vector<ImplicitSpringTerms>().swap(scratch.implicit_springs);
        scratch.implicit_grid = ImplicitGridSolver{};
    }
    history.implicit_start_depth = 0;
    history.valid = false;
}

void integrate(Integrator integrator, Cloth& cloth, const ForceField& field, double dt,
               IntegratorWorkspace& work) {
    OnTheWay& way = work.on_the_way;
    way.sweep_result.reset();
    way.rows_done = false;
    way.start_positions = {};
    // The fused step leaves the positions it started from in its output buffer (swapped
    // with the cloth's); any other step is taken in place, so they are copied first.
    if (integrator == Integrator::symplectic_euler &&
        step_symplectic_euler_fused(cloth, field, dt, work, way.after_rows)) {
        way.rows_done = way.after_rows != nullptr;
        if (way.keep_start_positions) way.start_positions = work.scratch.next_positions;
        return;
    }
    if (way.keep_start_positions) {
        work.scratch.start_positions = cloth.positions;  // no allocation after the first step
        way.start_positions = work.scratch.start_positions;
    }
    step_function(integrator)(cloth, field, dt, work);
}

void evaluate_forces(const Cloth& cloth, const ForceField& field, std::span<const Vec3> positions,
                     std::span<const Vec3> velocities, IntegratorWorkspace& work) {
    accumulate_forces(cloth, field, positions, velocities, work.scratch.forces, work.settings.pool,
                      work.settings.options.kernel_build);
    ++work.statistics.force_evaluations;
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
