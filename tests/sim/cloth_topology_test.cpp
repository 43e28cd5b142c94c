// Topology apart from state: copies of a cloth (recovery snapshots, rollbacks, runs side by
// side) share one ClothTopology until one of them changes it.
//
// Truths: a copy holds the very same topology object (no new one is allocated) however long
// both step; a tear, a cut or a pin gives only the cloth that made it a topology of its own,
// with a new version, and leaves every other copy's as it was; a rollback shares again.
#include <gtest/gtest.h>

#include "sim/core/simulation.h"

namespace weft {
namespace {

Scene hanging_sheet() {
    Scene scene;
    scene.cloth.rows = 10;
    scene.cloth.cols = 10;
    scene.shear.enabled = true;
    return scene;
}

TEST(ClothTopology, ACopySharesItsTopologyUntilASpringTears) {
    Simulation original(hanging_sheet());
    Simulation copy = original;
    const ClothTopology* shared = &original.cloth().topology();
    const std::uint64_t version = shared->version;
    EXPECT_EQ(&copy.cloth().topology(), shared);
    EXPECT_EQ(original.cloth().topology_holders(), 2);
    for (int s = 0; s < 300; ++s) {
        original.step();
        copy.step();
    }
    // Both moved (state is their own) and still share one topology, unchanged.
    EXPECT_NE(original.cloth().positions[55], Simulation(hanging_sheet()).cloth().positions[55]);
    EXPECT_EQ(original.cloth().positions, copy.cloth().positions);
    EXPECT_EQ(&copy.cloth().topology(), shared);
    EXPECT_EQ(shared->version, version);

    // The copy tears: springs sagging 0.05 % past rest give way.
    copy.set_tear_limit(1.0005);
    const std::size_t springs = original.cloth().spring_count();
    for (int s = 0; s < 2000 && copy.cloth().spring_count() == springs; ++s) copy.step();
    ASSERT_LT(copy.cloth().spring_count(), springs);
    EXPECT_NE(&copy.cloth().topology(), shared);
    EXPECT_NE(copy.cloth().topology().version, version);
    // The original kept its own, intact and of the same version, now held by it alone.
    EXPECT_EQ(&original.cloth().topology(), shared);
    EXPECT_EQ(original.cloth().spring_count(), springs);
    EXPECT_EQ(shared->version, version);
    EXPECT_EQ(original.cloth().topology_holders(), 1);
}

TEST(ClothTopology, ARollbackSharesTheSnapshotsTopologyAgain) {
    Simulation running(hanging_sheet());
    running.set_tear_limit(1.0005);
    const Simulation snapshot = running;
    const std::size_t springs = snapshot.cloth().spring_count();
    for (int s = 0; s < 2000 && running.cloth().spring_count() == springs; ++s) running.step();
    ASSERT_LT(running.cloth().spring_count(), springs);
    running = snapshot;  // rolled back
    EXPECT_EQ(&running.cloth().topology(), &snapshot.cloth().topology());
    EXPECT_EQ(running.cloth().spring_count(), springs);
}

TEST(ClothTopology, APinOrACutOnACopyLeavesTheOriginalAsItWas) {
    const Simulation original(hanging_sheet());
    const std::uint64_t version = original.cloth().topology().version;
    Simulation pinned = original;
    ASSERT_FALSE(original.cloth().is_pinned(55));
    pinned.set_pinned(55, true);
    EXPECT_TRUE(pinned.cloth().is_pinned(55));
    EXPECT_FALSE(original.cloth().is_pinned(55));
    EXPECT_EQ(original.cloth().topology().pinned.size(), 2u);
    EXPECT_EQ(original.cloth().topology().version, version);
    // Pinning what is pinned already changes nothing, so makes no copy.
    Simulation again = original;
    again.set_pinned(0, true);
    EXPECT_EQ(&again.cloth().topology(), &original.cloth().topology());

    Simulation cut = original;
    const std::size_t removed = cut.cut_springs([](const Spring& s) { return s.i == 44; });
    EXPECT_GT(removed, 0u);
    EXPECT_EQ(cut.cloth().spring_count() + removed, original.cloth().spring_count());
    EXPECT_EQ(original.cloth().topology().version, version);
    // A cut that removes nothing leaves the topology shared.
    Simulation missed = original;
    EXPECT_EQ(missed.cut_springs([](const Spring&) { return false; }), 0u);
    EXPECT_EQ(&missed.cloth().topology(), &original.cloth().topology());
}

TEST(ClothTopology, EveryEditGivesAVersionNoOtherTopologyHad) {
    Simulation a(hanging_sheet());
    Simulation b(hanging_sheet());
    // Two cloths built alike are still two topologies, told apart by version.
    EXPECT_NE(a.cloth().topology().version, b.cloth().topology().version);
    const std::uint64_t before = a.cloth().topology().version;
    a.set_pinned(55, true);
    const std::uint64_t pinned = a.cloth().topology().version;
    EXPECT_NE(pinned, before);
    a.set_pinned(55, false);
    EXPECT_NE(a.cloth().topology().version, pinned);
    EXPECT_NE(a.cloth().topology().version, before);
}

}  // namespace
}  // namespace weft
