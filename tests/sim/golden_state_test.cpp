// Golden states, as Box2D pins one: each integrator's state after a fixed run of the shipped
// default sheet, hashed (state_hash.h) and pinned here. Every result is the same bits on any
// thread count and kernel build, so a hash that moves means the numbers changed: if that was
// meant, renew the hash in the same commit and say why there; if not, it is a regression.
// The recorded sessions in assets/sessions pin the hand, tearing and implicit Euler's splits
// on larger sheets (cli.headless replays them).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "sim/core/simulation.h"
#include "sim/core/state_hash.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

struct Golden {
    const char* integrator;
    const char* dt;  // s: within the method's stability on this sheet
    std::uint64_t hash;
};

std::string hex(std::uint64_t value) {
    char text[24];
    std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(value));
    return text;
}

TEST(GoldenState, EachIntegratorEndsTheDefaultSheetsRunInItsPinnedState) {
    const Golden goldens[] = {
        {"explicit-euler", "0.0001", 0xcde01f80edb3cffcull},
        {"symplectic-euler", "0.00025", 0xdcae566467f546c9ull},
        {"verlet", "0.00025", 0x0002293ff85b63b7ull},
        {"velocity-verlet", "0.00025", 0x6b5c65f84f26bda6ull},
        {"rk4", "0.0005", 0x0e6f16082e3cd9feull},
        {"implicit-euler", "0.004", 0xd86b0e8986f4ebddull},
    };
    for (const Golden& golden : goldens) {
        const SceneLoadResult loaded =
            load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/hanging_sheet.toml",
                            {std::string("solver.integrator=") + golden.integrator,
                             std::string("solver.dt=") + golden.dt});
        ASSERT_TRUE(loaded.ok()) << loaded.error->message();
        for (const int threads : {1, 3}) {
            Simulation simulation(*loaded.scene);
            simulation.set_thread_count(threads);
            // 0.2 s of simulated time: the sheet has fallen and swings.
            const int steps = static_cast<int>(0.2 / loaded.scene->solver.dt + 0.5);
            for (int step = 0; step < steps; ++step)
                ASSERT_FALSE(simulation.step().diverged()) << golden.integrator << " at " << step;
            EXPECT_EQ(hex(hash_state(simulation.cloth())), hex(golden.hash))
                << golden.integrator << " on " << threads << " threads";
        }
    }
}

}  // namespace
}  // namespace weft
