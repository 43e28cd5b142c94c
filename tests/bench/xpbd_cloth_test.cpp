// The XPBD reference of weft-bench's realtime study (bench/weft_bench/xpbd_cloth.h), checked
// against exact truths before its speed and error are compared with weft's methods: the
// static equilibrium of springs under gravity (a compliance of 1/k stores the spring's
// energy, so XPBD must settle where the spring force balances the load), the dashpot's decay
// rate, air drag's terminal velocity, and the conservation of linear momentum (every
// correction moves two particles by opposite impulses).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "../sim/test_scenes.h"
#include "sim/core/simulation.h"
#include "weft_bench/xpbd_cloth.h"

namespace weft::bench {
namespace {

constexpr double frame = 1.0 / 60.0;  // s
constexpr double g = 9.81;            // m/s²

using testing::hanging_chain;

TEST(XpbdCloth, HangingParticleSettlesAtTheSpringsStaticStretch) {
    // m = 0.1 kg on k = 40 N/m (ω = 20 rad/s), a dashpot of a quarter of critical damping:
    // after 5 s the oscillation has decayed by e^-25. Equilibrium: k (l - L) = m g, and
    // predict + project has it as a fixed point exactly, dashpot or not (the dashpot's
    // share of the correction cancels at rest).
    const double mass = 0.1, stiffness = 40.0, rest_length = 0.1;
    const Simulation simulation(hanging_chain(2, mass, stiffness, 1.0, rest_length));
    for (int substeps : {5, 20}) {
        XpbdCloth xpbd(simulation.cloth(), simulation.force_field());
        for (int f = 0; f < 300; ++f) xpbd.step_frame(frame, substeps);
        const auto x = xpbd.positions();
        const double stretch = glm::length(x[1] - x[0]) - rest_length;
        EXPECT_NEAR(stretch / (mass * g / stiffness), 1.0, 1e-3) << substeps << " substeps";
    }
}

// Worst relative error of the links' stretches against the exact static equilibrium of the
// chain: link s (from the pin) carries the weight of the particles below it, (N - s) m g.
double chain_equilibrium_error(int substeps, bool dashpots) {
    const int particles = 8;
    const double mass = 0.01, stiffness = 50.0, rest_length = 0.05;
    // Without dashpots, air drag (which moves no equilibrium) brings the chain to rest.
    const Simulation simulation(
        hanging_chain(particles, mass, stiffness, 0.2, rest_length, dashpots ? 0.0 : 0.01));
    XpbdCloth xpbd(simulation.cloth(), simulation.force_field(), dashpots);
    for (int f = 0; f < 1200; ++f) xpbd.step_frame(frame, substeps);  // 20 s
    const auto x = xpbd.positions();
    double worst = 0.0;
    for (int s = 1; s < particles; ++s) {
        const double exact = (particles - s) * mass * g / stiffness;
        const double stretch = glm::length(x[s] - x[s - 1]) - rest_length;
        worst = std::max(worst, std::abs(stretch / exact - 1.0));
    }
    return worst;
}

TEST(XpbdCloth, HangingChainConvergesToTheExactStaticStretchOfEachLink) {
    // One Gauss–Seidel sweep per substep is one iteration on the implicit system, not its
    // solution: a link corrected early in the sweep is pulled again by the next one. So the
    // chain rests where predict + one sweep is a fixed point, off the exact equilibrium by
    // O(ε) with ε = k h² / m (here 0.056 at 5 substeps: 11 %), and the error falls as h²
    // (4x per doubling of the substeps), until float rounding takes over: an ulp of the
    // position against the h² g each substep moves, about 0.5 % at 20 substeps here.
    const double at5 = chain_equilibrium_error(5, false), at10 = chain_equilibrium_error(10, false),
                 at20 = chain_equilibrium_error(20, false);
    EXPECT_LT(at20, 1e-2);
    EXPECT_GT(at5 / at10, 3.5) << at5 << " then " << at10;
    EXPECT_GT(at10 / at20, 3.5) << at10 << " then " << at20;
}

TEST(XpbdCloth, DashpotsShiftTheChainsRestStateByAFirstOrderTerm) {
    // With eq. 26's dashpot the sweep's corrections look like motion to the next link's
    // damper, which resists them: an O(c h / m) shift of the rest state (c/m = 20 /s here,
    // heavily damped), halving with each doubling of the substeps. It vanishes as h -> 0:
    // the chain still converges to the exact equilibrium.
    const double at5 = chain_equilibrium_error(5, true), at10 = chain_equilibrium_error(10, true),
                 at20 = chain_equilibrium_error(20, true);
    EXPECT_LT(at20, 0.06);
    EXPECT_GT(at5 / at10, 1.7) << at5 << " then " << at10;
    EXPECT_GT(at10 / at20, 1.7) << at10 << " then " << at20;
}

TEST(XpbdCloth, DashpotDecaysTheOscillationAtItsExactRate) {
    // The hanging particle released at rest length: y'' + (c/m) y' + (k/m) y = 0 about the
    // equilibrium, y(0) = -m g / k, y'(0) = 0, so y(t) = y(0) e^{-βt} (cos ω_d t +
    // (β/ω_d) sin ω_d t) with β = c / 2m. XPBD adds its own damping of about h ω² / 2
    // (0.08 /s at 40 substeps, against β = 2.5 /s): the trajectory follows the exact one to
    // a few per cent of y(0). A dashpot left out, or doubled, misses by more than 5 %.
    const double mass = 0.1, stiffness = 40.0, damping = 0.5, rest_length = 0.1;
    const Simulation simulation(hanging_chain(2, mass, stiffness, damping, rest_length));
    XpbdCloth xpbd(simulation.cloth(), simulation.force_field());
    const double y0 = -mass * g / stiffness, beta = damping / (2 * mass);
    const double omega_d = std::sqrt(stiffness / mass - beta * beta);
    const Vec3 equilibrium = simulation.cloth().positions[0] - Vec3(0.0, rest_length - y0, 0.0);
    for (int f = 1; f <= 30; ++f) {  // 0.5 s
        xpbd.step_frame(frame, 40);
        const double t = f * frame;
        const double exact = y0 * std::exp(-beta * t) *
                             (std::cos(omega_d * t) + beta / omega_d * std::sin(omega_d * t));
        const double y = -(xpbd.positions()[1].y - equilibrium.y);  // stretch beyond equilibrium
        ASSERT_NEAR(y, exact, 0.03 * std::abs(y0)) << "t = " << t;
    }
}

TEST(XpbdCloth, AirDragBringsAFreeParticleToItsTerminalVelocity) {
    // A lone free particle: m dv/dt = m g - a (v - wind), terminal v = wind + m g / a. Drag
    // is applied as the exact decay over each substep, after gravity: the terminal velocity
    // of that recurrence is off by h a / 2m relative (0.8 % here). Float adds its own: the
    // velocity is (x - p) / h, so each substep's rounding of x (an ulp, 2.4e-7 m within
    // 2.5 m of the origin) is a velocity error of ulp / h, which drag takes 1 / (h a / m)
    // substeps to forget: about 1 % of the speed. So 3 %: a missing wind, a drag rate off by
    // its mass or a decay of the wrong sign misses by far more.
    Scene scene;
    scene.cloth.rows = scene.cloth.cols = 1;
    scene.cloth.particle_mass = 0.02;
    scene.cloth.pin_preset = PinPreset::none;
    scene.forces.air_drag = 0.2;           // N·s/m: time constant m / a = 0.1 s
    scene.forces.wind = {1.0, 0.0, -2.0};  // m/s
    const Simulation simulation(scene);
    const double fall = 0.02 * g / 0.2;  // m/s, relative to the wind
    const Vec3 terminal(1.0, -fall, -2.0);
    Cloth cloth = simulation.cloth();
    cloth.positions[0] = -terminal;  // passes the origin half way through the 2 s
    XpbdCloth xpbd(cloth, simulation.force_field());
    for (int f = 0; f < 120; ++f) xpbd.step_frame(frame, 10);  // 20 time constants
    EXPECT_LT(glm::length(xpbd.velocities()[0] - terminal), 0.03 * glm::length(terminal))
        << xpbd.velocities()[0].x << " " << xpbd.velocities()[0].y << " " << xpbd.velocities()[0].z;
}

TEST(XpbdCloth, FreeSheetKeepsItsLinearMomentum) {
    // No gravity, no drag, no pins: only the constraints act, and each moves its two ends
    // by w_i Δλ and w_j Δλ, opposite impulses Δλ / h. Unequal masses make a wrong split show.
    Scene scene;
    scene.cloth.rows = scene.cloth.cols = 6;
    scene.cloth.spacing = 0.05;
    scene.cloth.pin_preset = PinPreset::none;
    scene.shear.enabled = scene.bend.enabled = true;
    scene.forces.gravity = {0.0, 0.0, 0.0};
    const Simulation simulation(scene);
    Cloth cloth = simulation.cloth();
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> offset(-0.01, 0.01), speed(-1.0, 1.0), scale(0.5, 2.0);
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        cloth.positions[p] += Vec3(offset(rng), offset(rng), offset(rng));
        cloth.velocities[p] = Vec3(speed(rng), speed(rng), speed(rng));
        cloth.edit_topology().masses[p] *= scale(rng);
        cloth.edit_topology().inverse_masses[p] = 1.0 / cloth.edit_topology().masses[p];
    }
    XpbdCloth xpbd(cloth, simulation.force_field());
    const Vec3 before = xpbd.momentum();
    double momentum_scale = 0.0;  // Σ m |v|, kg·m/s
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        momentum_scale += cloth.topology().masses[p] * glm::length(cloth.velocities[p]);
    for (int f = 0; f < 60; ++f) xpbd.step_frame(frame, 10);
    // Float rounding of positions (about 1e-8 m here) over h = 1/600 s, in a random walk
    // over 600 substeps and 36 particles: far below 1e-4 of Σ m |v|.
    EXPECT_LT(glm::length(xpbd.momentum() - before), 1e-4 * momentum_scale);
    EXPECT_GT(glm::length(before), 1e-3 * momentum_scale);  // a momentum worth keeping
}

}  // namespace
}  // namespace weft::bench
