// Energy behaviour of the integrators without damping. For the hanging spring the exact
// discrete truths are known: explicit Euler multiplies the oscillation energy by (1 + h²ω²)
// every step, and symplectic Euler conserves ½ m v² + ½ k z² - ½ h k z v exactly. On a whole
// sheet, the symplectic methods keep the energy error bounded over 10⁵ steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "sim/core/energy.h"
#include "sim/core/simulation.h"
#include "sim/guards/divergence.h"
#include "test_scenes.h"

namespace weft {
namespace {

using testing::HangingSpring;

// Oscillation coordinates of the hanging spring: z = y - y_eq and v.
struct OscillatorState {
    double z, v;
};

OscillatorState oscillator_state(const Simulation& simulation, const HangingSpring& spring) {
    return {simulation.cloth().positions[1].y - spring.equilibrium(),
            simulation.cloth().velocities[1].y};
}

TEST(ExplicitEuler, EnergyGrowsByExactlyOnePlusHOmegaSquaredPerStep) {
    const HangingSpring spring;
    // Chosen so the amplitude grows about 3.5x but the particle never rises above the pin,
    // where the spring would fold over and stop being a linear oscillator.
    const double dt = 2.5e-4;
    Simulation simulation(spring.scene(Integrator::explicit_euler, dt));
    auto oscillation_energy = [&] {
        const auto [z, v] = oscillator_state(simulation, spring);
        return 0.5 * spring.mass * v * v + 0.5 * spring.stiffness * z * z;
    };
    const double initial = oscillation_energy();
    // The total energy the code measures is the oscillation energy plus a constant.
    const double offset =
        measure_energy(simulation.cloth(), simulation.force_field()).total() - initial;
    const double growth_per_step = 1.0 + dt * dt * spring.omega0() * spring.omega0();
    const long long steps = 100'000;
    // The energy guard rightly reports this growth (energy_guard.h); the test measures the
    // growth itself, so it steps on and only checks that the guard saw it.
    bool flagged_by_energy = false;
    for (long long s = 0; s < steps; ++s) {
        const StepReport report = simulation.step();
        if (report.diverged()) {
            ASSERT_NE(report.divergence->find("energy grew"), std::string::npos)
                << *report.divergence;
            flagged_by_energy = true;
        }
    }
    EXPECT_TRUE(flagged_by_energy);
    const double expected = initial * std::pow(growth_per_step, static_cast<double>(steps));
    EXPECT_NEAR(oscillation_energy() / expected, 1.0, 1e-9);
    EXPECT_GT(expected / initial, 10.0);  // e^{10⁵ · 2.5·10⁻⁵} ≈ 12: it really grew
    const double measured_total =
        measure_energy(simulation.cloth(), simulation.force_field()).total();
    EXPECT_NEAR((measured_total - offset) / expected, 1.0, 1e-9);
}

TEST(SymplecticEuler, ConservesItsModifiedEnergyExactly) {
    const HangingSpring spring;
    const double dt = 1e-3;
    Simulation simulation(spring.scene(Integrator::symplectic_euler, dt));
    auto modified_energy = [&] {
        const auto [z, v] = oscillator_state(simulation, spring);
        return 0.5 * spring.mass * v * v + 0.5 * spring.stiffness * z * z -
               0.5 * dt * spring.stiffness * z * v;
    };
    const double initial = modified_energy();
    for (int block = 0; block < 100; ++block) {
        ASSERT_TRUE(testing::run_steps(simulation, 1000));
        ASSERT_NEAR(modified_energy() / initial, 1.0, 1e-9)
            << "after " << (block + 1) * 1000 << " steps";
    }
}

// An undamped sheet with all spring families, released flat: it swings and ripples.
Scene undamped_sheet(Integrator integrator) {
    Scene scene;
    scene.cloth.rows = 8;
    scene.cloth.cols = 8;
    scene.structural = {true, 800.0, 0.0};
    scene.shear = {true, 400.0, 0.0};
    scene.bend = {true, 100.0, 0.0};
    scene.solver = {integrator, 5e-4};  // h ω_max <= 0.51 (Gershgorin bound on the stiffness)
    return scene;
}

struct EnergyDrift {
    double early;  // J, largest |E - E0| over the first tenth of the run
    double late;   // J, same over the last tenth
    double scale;  // J, largest kinetic energy seen: the energy that moves around
    bool finite = true;
};

EnergyDrift energy_drift(Integrator integrator, long long steps) {
    Simulation simulation(undamped_sheet(integrator));
    const double initial = measure_energy(simulation.cloth(), simulation.force_field()).total();
    EnergyDrift drift{0.0, 0.0, 0.0};
    for (long long s = 1; s <= steps; ++s) {
        if (simulation.step().diverged()) {
            drift.finite = false;
            return drift;
        }
        const Energy energy = measure_energy(simulation.cloth(), simulation.force_field());
        const double error = std::abs(energy.total() - initial);
        drift.scale = std::max(drift.scale, energy.kinetic);
        if (s <= steps / 10) drift.early = std::max(drift.early, error);
        if (s > steps - steps / 10) drift.late = std::max(drift.late, error);
    }
    return drift;
}

TEST(SymplecticMethods, EnergyErrorStaysBoundedOverOneHundredThousandUndampedSteps) {
    for (Integrator integrator :
         {Integrator::symplectic_euler, Integrator::verlet, Integrator::velocity_verlet}) {
        const EnergyDrift drift = energy_drift(integrator, 100'000);
        ASSERT_TRUE(drift.finite) << integrator_name(integrator);
        // Bounded: no growth from the start of the run to its end...
        EXPECT_LT(drift.late, 2.0 * drift.early) << integrator_name(integrator);
        // ...and small against the energy in motion.
        EXPECT_LT(drift.late, 0.05 * drift.scale) << integrator_name(integrator);
    }
}

TEST(ExplicitEuler, EnergyOfTheSheetGrowsWithoutBound) {
    const EnergyDrift drift = energy_drift(Integrator::explicit_euler, 100'000);
    // Either it blew up outright, or the error at the end dwarfs the one at the start.
    if (drift.finite) {
        EXPECT_GT(drift.late, 100.0 * drift.early);
    }
}

// The demo measures the sheet every frame on the simulation's threads, in chunks fixed by the
// size alone: the energy and the largest stretch must be the same bits on any number of
// threads, and equal the plain sums over particles and springs to rounding.
TEST(SheetMeasures, AreTheSameBitsOnAnyThreadCount) {
    Scene scene;
    scene.cloth.rows = 96;  // 96² particles, 37 000 springs: several chunks each
    scene.cloth.cols = 96;
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    scene.solver.integrator = Integrator::implicit_euler;
    scene.solver.dt = 1.0 / 60.0;
    Simulation simulation(scene);
    for (int step = 0; step < 20; ++step) ASSERT_FALSE(simulation.step().diverged());
    const Cloth& cloth = simulation.cloth();
    const ForceField& field = simulation.force_field();

    Energy plain;  // the sums as written in energy.h, in one loop each
    double plain_largest = 0.0;
    Spring plain_spring{0, 0, 0.0};  // the first spring stretched that much
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        if (cloth.is_pinned(p)) continue;
        plain.kinetic +=
            0.5 * cloth.topology().masses[p] * glm::dot(cloth.velocities[p], cloth.velocities[p]);
        plain.gravitational -=
            cloth.topology().masses[p] * glm::dot(field.gravity, cloth.positions[p]);
    }
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs) {
            const double length =
                glm::length(cloth.positions[spring.j] - cloth.positions[spring.i]);
            plain.elastic += 0.5 * group.stiffness * (length - spring.rest_length) *
                             (length - spring.rest_length);
            if (length / spring.rest_length > plain_largest) {  // the first of the largest
                plain_largest = length / spring.rest_length;
                plain_spring = spring;
            }
        }
    ASSERT_GT(plain_largest, 1.0);  // the sheet has fallen: the springs are stretched

    const Energy serial = measure_energy(cloth, field);
    EXPECT_NEAR(serial.total(), plain.total(), 1e-12 * std::abs(plain.total()));
    EXPECT_NEAR(serial.elastic, plain.elastic, 1e-12 * plain.elastic);
    EXPECT_EQ(largest_stretch_ratio(cloth), plain_largest);
    for (int threads : {1, 2, 3}) {
        WorkerPool pool(threads);
        const Energy split = measure_energy(cloth, field, &pool);
        EXPECT_EQ(split.kinetic, serial.kinetic) << threads;
        EXPECT_EQ(split.gravitational, serial.gravitational) << threads;
        EXPECT_EQ(split.elastic, serial.elastic) << threads;
        EXPECT_EQ(largest_stretch_ratio(cloth, &pool), plain_largest) << threads;
        // The window's one pass for both: the same bits as the two passes.
        const EnergyAndStretch both = measure_energy_and_stretch(cloth, field, &pool);
        EXPECT_EQ(both.energy.kinetic, serial.kinetic) << threads;
        EXPECT_EQ(both.energy.gravitational, serial.gravitational) << threads;
        EXPECT_EQ(both.energy.elastic, serial.elastic) << threads;
        EXPECT_EQ(both.largest_stretch_ratio, plain_largest) << threads;
        // And which spring that is, whatever the split.
        EXPECT_EQ(both.most_stretched.i, plain_spring.i) << threads;
        EXPECT_EQ(both.most_stretched.j, plain_spring.j) << threads;
    }
}

}  // namespace
}  // namespace weft
