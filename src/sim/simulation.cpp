#include "sim/simulation.h"

#include <stdexcept>

#include "sim/cloth_builder.h"
#include "sim/divergence.h"
#include "sim/tearing.h"

namespace weft {
namespace {

Vec3 to_vec3(const Vec3d& v) {
    return {v[0], v[1], v[2]};
}

}  // namespace

std::optional<std::string> Simulation::unsupported_feature(const Scene& scene) {
    if (scene.solver.integrator == Integrator::implicit_euler)
        return "solver.integrator \"implicit-euler\" is not available yet";
    if (scene.cloth.layout == Layout::offset) return "cloth.layout \"offset\" is not available yet";
    return std::nullopt;
}

Simulation::Simulation(const Scene& scene)
    : scene_(scene),
      integrator_(scene.solver.integrator),
      step_function_(step_function(scene.solver.integrator)),
      dt_(scene.solver.dt) {
    if (auto why = unsupported_feature(scene)) throw std::invalid_argument(*why);
    cloth_ = build_grid_cloth(scene);
    field_.gravity = to_vec3(scene.forces.gravity);
    field_.air_drag = scene.forces.air_drag;
    field_.wind = to_vec3(scene.forces.wind);
    workspace_.resize(cloth_.particle_count());
}

StepReport Simulation::step() {
    StepReport report;
    step_function_(cloth_, field_, dt_, workspace_);
    time_ += dt_;
    ++steps_taken_;
    if (scene_.tear_max_stretch)
        report.springs_torn = tear_overstretched_springs(cloth_, *scene_.tear_max_stretch);
    // With tearing on, a runaway spring breaks instead of stretching without bound, so only
    // non-finite values count as divergence.
    report.divergence = find_divergence(cloth_, /*check_runaway_stretch=*/!scene_.tear_max_stretch);
    return report;
}

void Simulation::set_integrator(Integrator integrator) {
    StepFunction function = step_function(integrator);
    if (!function) throw std::invalid_argument("integrator not available");
    integrator_ = integrator;
    step_function_ = function;
    workspace_.history_valid = false;
}

void Simulation::set_dt(double dt) {
    dt_ = dt;
    workspace_.history_valid = false;
}

Cloth& Simulation::edit_cloth() {
    workspace_.history_valid = false;
    return cloth_;
}

}  // namespace weft
