// Symplectic Euler's fused grid step with its spring forces in float
// (SimulationOptions::single_precision_springs): it moves the sheet by far less than the
// method's own error at the same step, keeps the double step's determinism, and springs whose
// ends (nearly) meet push nowhere instead of making a NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "loaded_cloth.h"
#include "same_bits.h"
#include "sim/build/cloth_builder.h"
#include "sim/build/topology_edits.h"
#include "sim/core/simulation.h"
#include "sim/core/state_hash.h"
#include "sim/grid/grid_force_pass.h"
#include "sim/scene_io/scene_loader.h"
#include "test_scenes.h"

namespace weft {
namespace {

// cloth_128.toml's material (0.2 kg/m², stiff enough for about 1 % stretch) on a sheet of
// side² particles 1.15 m across, stepped by symplectic Euler at dt.
Scene cloth_material_sheet(int side, double dt) {
    const double spacing = 1.15 / (side - 1);
    const std::string n = std::to_string(side);
    SceneLoadResult loaded = load_scene_file(
        WEFT_SOURCE_DIR "/assets/scenes/cloth_128.toml",
        {"cloth.rows=" + n, "cloth.cols=" + n, "cloth.spacing=" + std::to_string(spacing),
         "cloth.particle_mass=" + std::to_string(0.2 * spacing * spacing),
         "solver.integrator=\"symplectic-euler\"", "solver.dt=" + std::to_string(dt)});
    EXPECT_TRUE(loaded.ok()) << loaded.error->message();
    return *loaded.scene;
}

SimulationOptions float_springs(SimulationOptions options = {}) {
    options.single_precision_springs = true;
    return options;
}

// The positions after `steps` steps, or nothing if the run diverged.
std::vector<Vec3> positions_after(const Scene& scene, const SimulationOptions& options,
                                  long long steps) {
    Simulation simulation(scene, options);
    if (!testing::run_steps(simulation, steps)) return {};
    return simulation.cloth().positions;
}

double rms_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double sum = 0.0;
    for (std::size_t p = 0; p < a.size(); ++p) {
        const Vec3 d = a[p] - b[p];
        sum += d.x * d.x + d.y * d.y + d.z * d.z;
    }
    return std::sqrt(sum / static_cast<double>(a.size()));
}

// 0.24 s of the fall from horizontal, at three quarters of the step-limit estimate: the
// float forces' change to the sheet against the first-order method's own error, estimated as
// the distance between the runs at dt and dt/2 (their errors are about e and e/2).
TEST(FloatSprings, MoveTheSheetFarLessThanTheMethodsOwnError) {
    const double dt = 3e-4;  // s
    const long long steps = 800;
    const std::vector<Vec3> at_dt = positions_after(cloth_material_sheet(48, dt), {}, steps);
    const std::vector<Vec3> at_half =
        positions_after(cloth_material_sheet(48, dt / 2), {}, 2 * steps);
    const std::vector<Vec3> with_float =
        positions_after(cloth_material_sheet(48, dt), float_springs(), steps);
    ASSERT_FALSE(at_dt.empty());
    ASSERT_FALSE(at_half.empty());
    ASSERT_FALSE(with_float.empty());
    const double method_error = rms_distance(at_dt, at_half);
    const double float_change = rms_distance(with_float, at_dt);
    EXPECT_GT(method_error, 1e-6);  // m: the sheet did fall and swing
    EXPECT_GT(float_change, 0.0);   // the option changed the arithmetic
    EXPECT_LT(float_change, 1e-3 * method_error) << float_change << " m against " << method_error;
}

TEST(FloatSprings, SameBitsOnAnyThreadCount) {
    // 72² particles: enough for the rows to be split between threads.
    const Scene scene = cloth_material_sheet(72, 3e-4);
    testing::expect_same_bits_on_any_thread_count([&](int threads) -> std::uint64_t {
        Simulation simulation(scene, float_springs());
        simulation.set_thread_count(threads);
        return testing::run_steps(simulation, 60) ? hash_state(simulation.cloth()) : 0;
    });
}

TEST(FloatSprings, SameBitsOnEveryKernelBuild) {
    const Scene scene = cloth_material_sheet(72, 3e-4);
    testing::expect_same_bits_on_every_kernel_build(
        [&](const SimulationOptions& options) -> std::uint64_t {
            Simulation simulation(scene, float_springs(options));
            return testing::run_steps(simulation, 60) ? hash_state(simulation.cloth()) : 0;
        });
}

// Ends 1e-21 m apart (their length squared is a subnormal float) and ends that meet: the
// spring between them exerts nothing, as if it were torn, and nothing turns NaN.
TEST(FloatSprings, SpringsWhoseEndsMeetPushNowhere) {
    Cloth start = testing::three_family_sheet(12, 10);
    testing::scramble(start, 5, 0.003);
    // (4, 4) and (4, 5) at the origin, where 1e-21 m is not lost to rounding; (6, 5) and (7, 5)
    start.positions[44] = Vec3(0.0);
    start.positions[45] = Vec3(1e-21, 0.0, 0.0);
    start.positions[75] = start.positions[65];
    Cloth torn = start;
    remove_springs_if(torn, [](const Spring& s) {
        const auto joins = [&](std::uint32_t a, std::uint32_t b) {
            return (s.i == a && s.j == b) || (s.i == b && s.j == a);
        };
        return joins(44, 45) || joins(65, 75);
    });
    ASSERT_EQ(torn.spring_count() + 2, start.spring_count());

    const auto stepped = [](Cloth cloth) {
        std::vector<Vec3> next_positions, next_velocities;
        EXPECT_TRUE(step_grid_symplectic_euler(cloth, testing::windy_field(), 2e-4, next_positions,
                                               next_velocities, nullptr, nullptr, nullptr,
                                               supported_simd_level(), nullptr, true));
        return cloth;
    };
    const Cloth with_springs = stepped(start);
    const Cloth without = stepped(torn);
    for (std::size_t p = 0; p < with_springs.particle_count(); ++p) {
        const Vec3& v = with_springs.velocities[p];
        ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) << p;
    }
    EXPECT_TRUE(testing::same_bits(with_springs.velocities, without.velocities));
    EXPECT_TRUE(testing::same_bits(with_springs.positions, without.positions));
}

}  // namespace
}  // namespace weft
