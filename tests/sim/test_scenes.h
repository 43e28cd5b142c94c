// Small scenes and exact solutions shared by the simulation tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sim/core/simulation.h"
#include "sim/grid/grid_force_pass.h"
#include "sim/scene/scene.h"

namespace weft::testing {

inline constexpr Integrator all_integrators[] = {Integrator::explicit_euler,
                                                 Integrator::symplectic_euler, Integrator::verlet,
                                                 Integrator::velocity_verlet, Integrator::rk4};

// Options under which implicit Euler takes its general path (double precision, any
// topology) instead of the structured single-precision solve on grids: for the tests of the
// method's exact discrete behaviour, which the general path is the reference for.
inline SimulationOptions general_implicit_path() {
    SimulationOptions options;
    options.structured_implicit_solve = false;
    return options;
}

// Options with the grid steps fused or not, as asked.
inline SimulationOptions fused_grid_steps(bool fused) {
    SimulationOptions options;
    options.fused_grid_steps = fused;
    return options;
}

// Options with the row kernels of `level`.
inline SimulationOptions kernel_build(SimdLevel level) {
    SimulationOptions options;
    options.kernel_build = level;
    return options;
}

// A vertical chain of `particles` grid particles (one column, the top one pinned), released
// at rest length: spring s from the pin carries the weight below it, so at rest its length is
// exactly L + (N - s) m g / k.
inline Scene hanging_chain(int particles, double mass, double stiffness, double damping,
                           double rest_length, double air_drag = 0.0) {
    Scene scene;
    scene.cloth.rows = particles;
    scene.cloth.cols = 1;
    scene.cloth.spacing = rest_length;
    scene.cloth.particle_mass = mass;
    scene.cloth.pin_preset = PinPreset::top_row;
    scene.structural = {true, stiffness, damping};
    scene.forces.air_drag = air_drag;
    return scene;
}

// One particle of mass m hanging from a pinned one by a single spring (rows = 2, cols = 1),
// released at the spring's rest length, so it oscillates vertically about its equilibrium.
struct HangingSpring {
    double mass = 0.1;         // kg
    double stiffness = 40.0;   // N/m      -> ω0 = 20 rad/s
    double damping = 0.0;      // N·s/m, spring dashpot
    double air_drag = 0.0;     // N·s/m
    double rest_length = 0.1;  // m
    double gravity = 9.81;     // m/s², downwards

    Scene scene(Integrator integrator, double dt) const {
        Scene s;
        s.cloth.rows = 2;
        s.cloth.cols = 1;
        s.cloth.spacing = rest_length;
        s.cloth.particle_mass = mass;
        s.cloth.pin_preset = PinPreset::list;
        s.cloth.pin_list = {{0, 0}};
        s.structural = {true, stiffness, damping};
        s.forces.gravity = {0.0, -gravity, 0.0};
        s.forces.air_drag = air_drag;
        s.solver = {integrator, dt};
        return s;
    }

    double initial_velocity = 0.0;  // m/s, vertical velocity of the free particle at t = 0

    // The scene's simulation with the initial velocity applied.
    Simulation simulate(Integrator integrator, double dt) const {
        Simulation simulation(scene(integrator, dt));
        simulation.edit_cloth().velocities[1].y = initial_velocity;
        return simulation;
    }

    // Closed form. With y the free particle's height (pin at y = 0):
    //   m y'' = -k (y + L) - m g - (c + air_drag) y'
    // so z = y - y_eq, y_eq = -L - m g / k, is an underdamped oscillator starting from
    // z0 = m g / k (released at the rest length) with velocity v0:
    //   z = e^{-γt} (A cos ωd t + B sin ωd t),  A = z0,  B = (v0 + γ z0) / ωd.
    double equilibrium() const { return -rest_length - mass * gravity / stiffness; }
    double gamma() const { return (damping + air_drag) / (2.0 * mass); }
    double omega0() const { return std::sqrt(stiffness / mass); }
    double omega_d() const { return std::sqrt(omega0() * omega0() - gamma() * gamma()); }
    double cosine_amplitude() const { return mass * gravity / stiffness; }
    double sine_amplitude() const {
        return (initial_velocity + gamma() * cosine_amplitude()) / omega_d();
    }
    double position(double t) const {
        const double wd = omega_d(), a = cosine_amplitude(), b = sine_amplitude();
        return equilibrium() +
               std::exp(-gamma() * t) * (a * std::cos(wd * t) + b * std::sin(wd * t));
    }
    double velocity(double t) const {
        const double wd = omega_d(), g = gamma(), a = cosine_amplitude(), b = sine_amplitude();
        return std::exp(-g * t) *
               ((b * wd - g * a) * std::cos(wd * t) - (a * wd + g * b) * std::sin(wd * t));
    }
};

// "symplectic-euler" -> "symplecticeuler": a GoogleTest parameter name.
// The overrides that turn sheet_on_sphere.toml into the heavy material of earlier versions
// (4 kg/m² on 800 N/m springs at 0.5 ms): explicit Euler on it gains energy slowly on
// contact, before any spring runs away, the energy guard's own case.
inline const std::vector<std::string> heavy_sheet_on_sphere = {"cloth.particle_mass=0.006",
                                                               "springs.structural.stiffness=800",
                                                               "springs.structural.damping=0.3",
                                                               "springs.shear.stiffness=400",
                                                               "springs.shear.damping=0.3",
                                                               "springs.bend.stiffness=20",
                                                               "springs.bend.damping=0.02",
                                                               "forces.air_drag=0.01",
                                                               "solver.dt=0.0005"};

inline std::string integrator_test_name(Integrator integrator) {
    std::string name = integrator_name(integrator);
    std::erase(name, '-');
    return name;
}

// Names parameterised tests after the integrator of their parameter.
struct IntegratorParamName {
    template <class Param>
    std::string operator()(const ::testing::TestParamInfo<Param>& param_info) const {
        return integrator_test_name(param_info.param.integrator);
    }
};

// Runs `steps` steps; fails the calling test (returns false) on divergence.
inline bool run_steps(Simulation& simulation, long long steps) {
    for (long long s = 0; s < steps; ++s)
        if (simulation.step().diverged()) return false;
    return true;
}

}  // namespace weft::testing
