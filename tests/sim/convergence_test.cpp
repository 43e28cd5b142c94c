// Measured order of convergence: the error must shrink as dt^p with the method's order p,
// undamped and with velocity-dependent forces (spring damping and air drag). Catches the
// traps that silently cost an order (Verlet start and velocity, velocity Verlet's damping).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

#include "sim/core/simulation.h"
#include "test_scenes.h"

namespace weft {
namespace {

using testing::HangingSpring;

struct OrderCase {
    Integrator integrator;
    double coarsest_dt;  // s; the ladder halves it three times, staying in the asymptotic range
    double order;        // expected
};

void PrintTo(const OrderCase& c, std::ostream* out) {
    *out << integrator_name(c.integrator) << " at dt = " << c.coarsest_dt << " s";
}

struct Errors {
    double position;  // m, largest |y - y_exact| over the sample times
    double velocity;  // m/s, same for the velocity
};

// Largest error against the closed form at t = 0.02 s, 0.04 s, ..., 1 s. Sampling many times
// keeps a lucky zero crossing of the error at one time from faking an order.
Errors errors_against_closed_form(const HangingSpring& spring, Integrator integrator, double dt) {
    Simulation simulation = spring.simulate(integrator, dt);
    const long long steps_per_sample = std::llround(0.02 / dt);
    Errors worst{0.0, 0.0};
    for (int sample = 1; sample <= 50; ++sample) {
        for (long long s = 0; s < steps_per_sample; ++s) simulation.step();
        const double t = sample * 0.02;
        worst.position = std::max(worst.position,
                                  std::abs(simulation.cloth().positions[1].y - spring.position(t)));
        worst.velocity = std::max(
            worst.velocity, std::abs(simulation.cloth().velocities[1].y - spring.velocity(t)));
    }
    return worst;
}

// Observed order from the last two halvings of a ladder of errors, averaged.
double observed_order(const std::vector<double>& errors) {
    const std::size_t n = errors.size();
    return 0.5 *
           (std::log2(errors[n - 3] / errors[n - 2]) + std::log2(errors[n - 2] / errors[n - 1]));
}

class ConvergenceOrder : public ::testing::TestWithParam<OrderCase> {
  protected:
    void expect_order(const HangingSpring& spring) {
        const OrderCase c = GetParam();
        std::vector<double> position_errors, velocity_errors;
        for (int halving = 0; halving < 4; ++halving) {
            const Errors e =
                errors_against_closed_form(spring, c.integrator, c.coarsest_dt / (1 << halving));
            position_errors.push_back(e.position);
            velocity_errors.push_back(e.velocity);
        }
        const double position_order = observed_order(position_errors);
        const double velocity_order = observed_order(velocity_errors);
        EXPECT_NEAR(position_order, c.order, 0.15 * c.order)
            << integrator_name(c.integrator) << " position errors " << position_errors[0] << " ... "
            << position_errors[3];
        EXPECT_NEAR(velocity_order, c.order, 0.15 * c.order)
            << integrator_name(c.integrator) << " velocity errors " << velocity_errors[0] << " ... "
            << velocity_errors[3];
    }
};

// Started with a velocity: released at rest (a turning point), symplectic Euler's velocity
// happens to be second-order accurate, which would hide a wrong order.
HangingSpring moving_spring() {
    HangingSpring spring;
    spring.initial_velocity = 0.3;  // m/s
    return spring;
}

TEST_P(ConvergenceOrder, Undamped) {
    expect_order(moving_spring());
}

TEST_P(ConvergenceOrder, WithSpringDampingAndDrag) {
    HangingSpring spring = moving_spring();
    spring.damping = 0.4;
    spring.air_drag = 0.2;
    expect_order(spring);
}

INSTANTIATE_TEST_SUITE_P(Each, ConvergenceOrder,
                         ::testing::Values(OrderCase{Integrator::explicit_euler, 1e-3, 1.0},
                                           OrderCase{Integrator::symplectic_euler, 1e-3, 1.0},
                                           OrderCase{Integrator::verlet, 4e-3, 2.0},
                                           OrderCase{Integrator::velocity_verlet, 4e-3, 2.0},
                                           OrderCase{Integrator::rk4, 2e-2, 4.0},
                                           OrderCase{Integrator::implicit_euler, 1e-3, 1.0}),
                         testing::IntegratorParamName());

// The same orders on a whole damped sheet with all three spring families, moving in 3-D
// under gravity and wind, against an RK4 reference at a far smaller step.
class SheetConvergenceOrder : public ::testing::TestWithParam<OrderCase> {};

Scene small_sheet(Integrator integrator, double dt) {
    Scene scene;
    scene.cloth.rows = 5;
    scene.cloth.cols = 5;
    scene.cloth.spacing = 0.1;
    scene.cloth.particle_mass = 0.05;
    scene.structural = {true, 100.0, 0.05};
    scene.shear = {true, 50.0, 0.05};
    scene.bend = {true, 10.0, 0.01};
    scene.forces.air_drag = 0.01;
    scene.forces.wind = {0.0, 0.0, 2.0};
    scene.solver = {integrator, dt};
    return scene;
}

double sheet_error(const Simulation& run, const Simulation& reference) {
    double worst = 0.0;
    for (std::size_t p = 0; p < run.cloth().particle_count(); ++p)
        worst =
            std::max(worst, glm::length(run.cloth().positions[p] - reference.cloth().positions[p]));
    return worst;
}

TEST_P(SheetConvergenceOrder, AllSpringFamiliesDamped) {
    const OrderCase c = GetParam();
    const double end_time = 0.2;  // s
    Simulation reference(small_sheet(Integrator::rk4, 1.25e-5));
    ASSERT_TRUE(testing::run_steps(reference, std::llround(end_time / 1.25e-5)));
    std::vector<double> errors;
    for (int halving = 0; halving < 4; ++halving) {
        const double dt = c.coarsest_dt / (1 << halving);
        Simulation run(small_sheet(c.integrator, dt));
        ASSERT_TRUE(testing::run_steps(run, std::llround(end_time / dt)));
        errors.push_back(sheet_error(run, reference));
    }
    EXPECT_NEAR(observed_order(errors), c.order, 0.15 * c.order)
        << integrator_name(c.integrator) << " errors " << errors[0] << " ... " << errors[3];
}

INSTANTIATE_TEST_SUITE_P(Each, SheetConvergenceOrder,
                         ::testing::Values(OrderCase{Integrator::explicit_euler, 2e-4, 1.0},
                                           OrderCase{Integrator::symplectic_euler, 2e-4, 1.0},
                                           OrderCase{Integrator::verlet, 1e-3, 2.0},
                                           OrderCase{Integrator::velocity_verlet, 1e-3, 2.0},
                                           OrderCase{Integrator::rk4, 4e-3, 4.0},
                                           OrderCase{Integrator::implicit_euler, 2e-4, 1.0}),
                         testing::IntegratorParamName());

}  // namespace
}  // namespace weft
