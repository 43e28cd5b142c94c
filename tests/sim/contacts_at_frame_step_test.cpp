// The bar for contacts at frame-sized steps: the shipped 128² cloth dropped on a ball at one
// implicit step per 60 Hz frame (assets/scenes/drape_sphere_128.toml) passes through neither
// the ball nor the ground nor itself, measured as penetration depths over every particle's
// straight path through each step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "sim/core/simulation.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

// The closest approach of two straight paths over a step (start → end, both together).
double closest_approach(const Vec3& start, const Vec3& end) {
    const Vec3 change = end - start;
    const double change_squared = glm::dot(change, change);
    const double t = change_squared > 0.0
                         ? std::clamp(-glm::dot(start, change) / change_squared, 0.0, 1.0)
                         : 1.0;
    return glm::length(start + t * change);
}

// The least closest approach, over the step, of two particles not joined by a spring, among
// those whose paths pass within `reach`: sweep and prune on x over the paths' boxes (an
// algorithm of its own, not the pass's hash).
double closest_unjoined_approach(const Cloth& cloth, const std::vector<Vec3>& start, double reach) {
    std::vector<std::uint64_t> joined;
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs)
            joined.push_back((std::uint64_t{std::min(spring.i, spring.j)} << 32) |
                             std::max(spring.i, spring.j));
    std::sort(joined.begin(), joined.end());
    const std::size_t count = cloth.particle_count();
    std::vector<std::uint32_t> order(count);
    for (std::uint32_t p = 0; p < count; ++p) order[p] = p;
    auto low = [&](std::uint32_t p) { return glm::min(start[p], cloth.positions[p]); };
    auto high = [&](std::uint32_t p) { return glm::max(start[p], cloth.positions[p]); };
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return low(a).x < low(b).x; });
    double closest = reach;
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t a = order[k];
        const Vec3 low_a = low(a) - Vec3(reach), high_a = high(a) + Vec3(reach);
        for (std::size_t m = k + 1; m < count && low(order[m]).x <= high_a.x; ++m) {
            const std::uint32_t b = order[m];
            const Vec3 low_b = low(b), high_b = high(b);
            if (low_b.y > high_a.y || high_b.y < low_a.y || low_b.z > high_a.z ||
                high_b.z < low_a.z)
                continue;
            const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
            if (std::binary_search(joined.begin(), joined.end(), key)) continue;
            closest = std::min(closest, closest_approach(start[b] - start[a],
                                                         cloth.positions[b] - cloth.positions[a]));
        }
    }
    return closest;
}

TEST(ContactsAtTheFrameStep, A128SheetOnABallPassesThroughNeitherBallGroundNorItself) {
    SceneLoadResult loaded =
        load_scene_file(std::string(WEFT_SOURCE_DIR) + "/assets/scenes/drape_sphere_128.toml");
    ASSERT_TRUE(loaded.ok()) << loaded.error->message();
    const Scene& scene = *loaded.scene;
    ASSERT_EQ(scene.cloth.rows, 128);
    ASSERT_EQ(scene.solver.dt, 1.0 / 60.0);
    const double thickness = *scene.self_collision_thickness;
    const ColliderSpec& ball = scene.colliders[0];
    const Vec3 center(ball.center[0], ball.center[1], ball.center[2]);
    Simulation simulation(scene);
    double ball_depth = 0.0, path_depth = 0.0, ground_depth = 0.0, closest = thickness;
    for (int s = 0; s < 75; ++s) {  // 1.25 s: the fall, the drape and the folds on the ground
        const std::vector<Vec3> start = simulation.cloth().positions;
        const StepReport report = simulation.step();
        ASSERT_FALSE(report.diverged()) << "step " << s << ": " << report.divergence.value_or("");
        const Cloth& cloth = simulation.cloth();
        for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
            const Vec3& x = cloth.positions[p];
            ball_depth = std::max(ball_depth, ball.radius - glm::length(x - center));
            ground_depth = std::max(ground_depth, -x.y);
            // The deepest point of the particle's path inside the ball: a path that cut
            // through its edge between two frames.
            const Vec3 path = x - start[p];
            const double length_squared = glm::dot(path, path);
            const double t =
                length_squared > 0.0
                    ? std::clamp(glm::dot(center - start[p], path) / length_squared, 0.0, 1.0)
                    : 0.0;
            path_depth =
                std::max(path_depth, ball.radius - glm::length(start[p] + t * path - center));
        }
        closest = std::min(closest, closest_unjoined_approach(cloth, start, thickness));
    }
    EXPECT_LT(ball_depth, 1e-6);    // m: every particle ends the step outside the ball
    EXPECT_LT(path_depth, 0.5e-3);  // m: and no path cut into it (measured 0.01 mm)
    EXPECT_LT(ground_depth, 1e-6);  // m
    // No two unjoined particles came closer than 3/4 of the thickness on their way through a
    // step (measured 0.999 of it over 3 s): at the thickness (3/4 of the spacing), a particle
    // crossing the sheet passes within the spacing / √2 of a corner of the triangle it
    // crosses, so such a crossing would have shown here.
    EXPECT_GT(closest, 0.75 * thickness);
}

}  // namespace
}  // namespace weft
