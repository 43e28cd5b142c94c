// Self-collision: the hash finds exactly the close, unjoined pairs a brute-force search
// finds, torn neighbours count as unjoined, and resolved pairs end at the thickness.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <random>

#include "sim/build/cloth_builder.h"
#include "sim/build/topology_edits.h"
#include "sim/collision/self_collision.h"
#include "sim/core/simulation.h"
#include "sim/guards/sweep_watch.h"

namespace weft {
namespace {

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

Pairs brute_force_pairs(const Cloth& cloth, double thickness) {
    Pairs pairs;
    auto joined = [&](std::uint32_t a, std::uint32_t b) {
        for (const SpringGroup& g : cloth.topology().spring_groups)
            for (const Spring& s : g.springs)
                if ((s.i == a && s.j == b) || (s.i == b && s.j == a)) return true;
        return false;
    };
    for (std::uint32_t a = 0; a < cloth.particle_count(); ++a)
        for (std::uint32_t b = a + 1; b < cloth.particle_count(); ++b)
            if (glm::length(cloth.positions[b] - cloth.positions[a]) < thickness && !joined(a, b))
                pairs.emplace_back(a, b);
    return pairs;
}

// A sheet crumpled at random into a small box: many close pairs.
Cloth crumpled_sheet(unsigned seed, int side = 12) {
    Scene scene;
    scene.cloth.rows = side;
    scene.cloth.cols = side;
    scene.shear.enabled = true;
    Cloth cloth = build_grid_cloth(scene);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coordinate(-0.05, 0.05);
    for (Vec3& x : cloth.positions) x = Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
    return cloth;
}

TEST(SelfCollision, HashFindsExactlyTheBruteForcePairs) {
    for (unsigned seed : {1u, 2u, 3u}) {
        const Cloth cloth = crumpled_sheet(seed);
        SelfCollision pass(0.02);
        Pairs found;
        pass.find_pairs(cloth, found);
        const Pairs expected = brute_force_pairs(cloth, 0.02);
        ASSERT_GT(expected.size(), 10u);
        EXPECT_EQ(found, expected);
    }
}

// Calls the pass `calls` times on a crumpled sheet of seed `seed`, moving every particle by
// `carry` plus a random nudge of up to `nudge_size` between calls; each call must find exactly
// what brute force finds. Returns the pairs compared (so a test can ask for enough of them).
std::size_t compare_kept_list_with_brute_force(SelfCollision& pass, unsigned seed, int calls,
                                               const Vec3& carry, double nudge_size) {
    Cloth cloth = crumpled_sheet(seed);
    std::mt19937 rng(seed + 6);
    std::uniform_real_distribution<double> nudge(-nudge_size / std::sqrt(3.0),
                                                 nudge_size / std::sqrt(3.0));
    std::size_t compared_pairs = 0;
    for (int call = 0; call < calls; ++call) {
        Pairs found;
        pass.find_pairs(cloth, found);
        const Pairs expected = brute_force_pairs(cloth, pass.thickness());
        EXPECT_EQ(found, expected) << "call " << call;
        if (found != expected) break;
        compared_pairs += expected.size();
        for (Vec3& x : cloth.positions) x += carry + Vec3(nudge(rng), nudge(rng), nudge(rng));
    }
    return compared_pairs;
}

TEST(SelfCollision, TheKeptListFindsExactlyTheBruteForcePairsAsParticlesMove) {
    // The pass keeps its candidate list between calls while no two particles can have come
    // closer by more than its margin: random moves of up to 0.2 thickness a call (so some
    // calls keep the list and some rebuild it) must find exactly what brute force finds.
    const double thickness = 0.02;
    SelfCollision pass(thickness);
    EXPECT_GT(compare_kept_list_with_brute_force(pass, 5, 40, Vec3(0.0), 0.2 * thickness), 400u);
}

TEST(SelfCollision, TheListIsKeptAndExactWhileTheSheetMovesAsAWhole) {
    // What bounds a pair's approach is the difference of its two displacements, not either
    // one: a crumpled sheet carried 0.6 thickness a call as a whole (far past the margin
    // after a few calls), each particle also nudged by up to 0.05 thickness, must find
    // exactly what brute force finds, and keep its list for most calls. The particles'
    // moves relative to each other reach half the margin (0.75 thickness) after 15 calls at
    // the soonest; their own, measured from zero, after 2 (which rebuilt the list on nearly
    // every call).
    const double thickness = 0.02;
    SelfCollision pass(thickness);
    const int calls = 40;
    const Vec3 carry = 0.6 * thickness * glm::normalize(Vec3(1.0, -2.0, 0.5));
    EXPECT_GT(compare_kept_list_with_brute_force(pass, 7, calls, carry, 0.05 * thickness), 400u);
    EXPECT_LE(pass.list_builds(), static_cast<std::size_t>(calls / 4));
}

TEST(SelfCollision, OneTwoAndThreeThreadsFindTheSamePairsAsBruteForce) {
    // 4096 particles: enough for the list's rebuild to be split between threads.
    const Cloth cloth = crumpled_sheet(6, 64);
    const double thickness = 0.004;
    const Pairs expected = brute_force_pairs(cloth, thickness);
    ASSERT_GT(expected.size(), 100u);
    for (const int threads : {1, 2, 3}) {
        WorkerPool pool(threads);
        SelfCollision pass(thickness);
        Pairs found;
        pass.find_pairs(cloth, found, &pool);
        EXPECT_EQ(found, expected) << threads << " threads";
    }
}

TEST(SelfCollision, TornNeighboursCollideAgain) {
    Cloth cloth = crumpled_sheet(4);
    SelfCollision pass(0.5);  // everything is within reach
    Pairs before, after;
    pass.find_pairs(cloth, before);
    remove_springs_if(cloth, [](const Spring& s) { return s.i == 0 && s.j == 1; });
    pass.find_pairs(cloth, after);
    EXPECT_EQ(after.size(), before.size() + 1);
    EXPECT_NE(std::find(after.begin(), after.end(), std::make_pair(0u, 1u)), after.end());
}

TEST(SelfCollision, ResolvedPairsEndAtTheThicknessAndConserveMomentum) {
    Scene scene;
    scene.cloth.rows = 1;
    scene.cloth.cols = 3;
    scene.cloth.spacing = 1.0;
    scene.cloth.pin_preset = PinPreset::none;
    Cloth cloth = build_grid_cloth(scene);
    // Particles 0 and 2 are not joined (no bend springs); bring them close, approaching.
    cloth.positions[2] = cloth.positions[0] + Vec3(0.0, 0.004, 0.0);
    cloth.velocities[0] = {0.0, 1.0, 0.0};
    cloth.velocities[2] = {0.0, -1.0, 0.0};
    SelfCollision pass(0.01);
    EXPECT_EQ(pass.resolve(cloth), 1u);
    EXPECT_NEAR(glm::length(cloth.positions[2] - cloth.positions[0]), 0.01, 1e-15);
    EXPECT_NEAR(cloth.velocities[0].y, 0.0, 1e-15);  // the approach is gone
    EXPECT_NEAR(cloth.velocities[2].y, 0.0, 1e-15);
}

TEST(SelfCollision, AFoldingSheetDoesNotPassThroughItself) {
    Scene scene;
    scene.cloth.rows = 16;
    scene.cloth.cols = 16;
    scene.cloth.spacing = 0.04;
    scene.cloth.orientation = Orientation::horizontal;
    scene.cloth.origin = {-0.3, 0.3, -0.3};
    scene.cloth.pin_preset = PinPreset::none;
    scene.shear.enabled = true;
    scene.bend = {true, 20.0, 0.05};
    scene.self_collision_thickness = 0.02;
    ColliderSpec ground;
    ground.type = ColliderType::plane;
    ground.point = {0.0, 0.0, 0.0};
    ground.normal = {0.0, 1.0, 0.0};
    ColliderSpec ball;
    ball.center = {0.0, 0.1, 0.0};
    ball.radius = 0.1;
    scene.colliders = {ground, ball};  // the sheet drapes over a ball and folds down to the ground
    Simulation simulation(scene);
    SelfCollision checker(0.02);
    Pairs close;
    double closest = 1.0;
    for (int s = 0; s < 3000; ++s) {
        ASSERT_FALSE(simulation.step().diverged());
        checker.find_pairs(simulation.cloth(), close);
        for (const auto& [a, b] : close)
            closest = std::min(closest, glm::length(simulation.cloth().positions[b] -
                                                    simulation.cloth().positions[a]));
    }
    // Pairs are resolved one after another, so a later push can undo part of an earlier
    // one; no two unjoined particles ever end a step closer than half the thickness.
    EXPECT_GT(closest, 0.01);
}

// A layer of unjoined particles (no springs) on a grid of `side`² at `spacing`, at height y.
Cloth loose_layer(int side, double spacing, double y) {
    Scene scene;
    scene.cloth.rows = side;
    scene.cloth.cols = side;
    scene.cloth.spacing = spacing;
    scene.cloth.orientation = Orientation::horizontal;
    scene.cloth.origin = {0.0, y, 0.0};
    scene.cloth.pin_preset = PinPreset::none;
    Cloth cloth = build_grid_cloth(scene);
    cloth.edit_topology().spring_groups.clear();
    return cloth;
}

TEST(SelfCollision, APairThatWentThroughEachOtherInOneStepIsPutBackOnItsSide) {
    // Two unjoined particles 3 thicknesses apart swap sides within one step: their ends are
    // 3 thicknesses apart again, so a check of the ends sees nothing. The swept pass sees
    // the paths cross and puts them back on the sides they came from, a thickness apart.
    Cloth cloth = loose_layer(1, 1.0, 0.0);
    cloth.positions.resize(2);
    cloth.velocities.assign(2, Vec3(0.0));
    cloth.edit_topology().masses.assign(2, 0.01);
    cloth.edit_topology().inverse_masses.assign(2, 100.0);
    const double thickness = 0.01;
    const std::vector<Vec3> start = {Vec3(0.0, 0.0, 0.0), Vec3(0.0, 3 * thickness, 0.0)};
    cloth.positions = {Vec3(0.001, 3 * thickness, 0.0), Vec3(-0.001, 0.0, 0.0)};
    cloth.velocities = {Vec3(0.0, 1.8, 0.0), Vec3(0.0, -1.8, 0.0)};
    SelfCollision plain(thickness);
    Cloth unchecked = cloth;
    EXPECT_EQ(plain.resolve(unchecked), 0u);  // the ends are far apart
    SelfCollision swept(thickness);
    EXPECT_EQ(swept.resolve(cloth, {}, nullptr, start), 1u);
    const Vec3 separation = cloth.positions[1] - cloth.positions[0];
    EXPECT_NEAR(separation.y, thickness, 1e-12);  // back above, a thickness apart
    EXPECT_NEAR(cloth.positions[0].y + cloth.positions[1].y, 3 * thickness, 1e-12);  // momentum
    EXPECT_LE(cloth.velocities[1].y - cloth.velocities[0].y, 1e-12);  // no longer approaching
}

TEST(SelfCollision, AFastLayerDoesNotPassThroughAStillOneInOneStep) {
    // A free layer falls 6 cm in one step through a pinned one 2 cm below it (a frame-sized
    // step at 3.6 m/s), the particles of one over the gaps of the other: every particle of
    // the free layer must end above the pinned layer.
    const int side = 8;
    const double spacing = 0.01, thickness = 0.0075;  // three quarters of the spacing
    Cloth below = loose_layer(side, spacing, 0.0);
    Cloth cloth = loose_layer(side, spacing, 0.02);
    const std::size_t half = below.particle_count();
    for (Vec3& x : cloth.positions) x += Vec3(0.5 * spacing, 0.0, 0.5 * spacing);
    std::vector<Vec3> start = below.positions;
    start.insert(start.end(), cloth.positions.begin(), cloth.positions.end());
    std::vector<Vec3> end = below.positions;
    for (const Vec3& x : cloth.positions) end.push_back(x - Vec3(0.0, 0.06, 0.0));
    Cloth both = below;
    both.positions = end;
    both.velocities.assign(2 * half, Vec3(0.0));
    for (std::size_t p = half; p < 2 * half; ++p) both.velocities[p] = Vec3(0.0, -3.6, 0.0);
    both.edit_topology().masses.assign(2 * half, 0.001);
    both.edit_topology().inverse_masses.assign(2 * half, 1000.0);
    for (std::size_t p = 0; p < half; ++p) both.edit_topology().inverse_masses[p] = 0.0;  // pinned
    SelfCollision pass(thickness);
    EXPECT_GT(pass.resolve(both, {}, nullptr, start), 0u);
    for (std::size_t p = half; p < 2 * half; ++p) {
        EXPECT_GT(both.positions[p].y, 0.0) << "particle " << p;
        // Each collision takes the approach along its pair's line, which is slanted.
        EXPECT_GT(both.velocities[p].y, -1.0) << "particle " << p;
    }
    for (std::size_t p = 0; p < half; ++p) EXPECT_EQ(both.positions[p], below.positions[p]);
}

TEST(SelfCollision, ItChecksThePairsItPushesForTheDivergenceGuard) {
    // Two unjoined particles of a 4 x 4 sheet laid on each other: the pass pushes them
    // apart by the thickness, and a watch whose limit is under that sees it (sweep_watch.h);
    // one whose limit is over it, or one left out of the pass, sees nothing.
    Scene scene;
    scene.cloth.rows = 4;
    scene.cloth.cols = 4;
    const double thickness = 0.5 * scene.cloth.spacing;
    Cloth cloth = build_grid_cloth(scene);
    cloth.positions[15] = cloth.positions[0] + Vec3(0.0, 0.0, 0.1 * thickness);
    const std::vector<Vec3> before = cloth.positions;
    for (double limit : {0.2 * thickness, 2.0 * thickness}) {
        Cloth overlapping = cloth;
        SweepWatch watch(SweepRequest{before.data(), limit * limit}, ParticleSweep{});
        SelfCollision pass(thickness);
        ASSERT_EQ(pass.resolve(overlapping, {}, nullptr, {}, &watch), 1u);
        EXPECT_EQ(watch.result().moved, limit < thickness) << "limit " << limit;
        EXPECT_FALSE(watch.result().non_finite);
    }
    Cloth overlapping = cloth;
    overlapping.velocities[15].x = std::numeric_limits<double>::infinity();
    SweepWatch watch(SweepRequest{before.data(), 1.0}, ParticleSweep{});
    SelfCollision(thickness).resolve(overlapping, {}, nullptr, {}, &watch);
    EXPECT_TRUE(watch.result().non_finite);
}

}  // namespace
}  // namespace weft
