// The plain float step of weft-bench (bench/weft_bench/plain_baseline.h) must be the
// same method as weft's symplectic Euler, differing only by single-precision rounding, or
// the speed ratio the realtime study reports between them would compare different work.
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/geometric.hpp>

#include "sim/core/simulation.h"
#include "weft_bench/plain_baseline.h"

namespace weft::bench {
namespace {

TEST(PlainFloatCloth, FollowsWeftsSymplecticEulerToFloatPrecision) {
    // An 8x8 sheet with every spring family, damping, drag and wind, from the flat start.
    Scene scene;
    scene.cloth.rows = scene.cloth.cols = 8;
    scene.cloth.spacing = 0.05;
    scene.shear.enabled = scene.bend.enabled = true;
    scene.forces.air_drag = 0.02;
    scene.forces.wind = {0.5, 0.0, 1.0};
    scene.solver = {Integrator::symplectic_euler, 1e-3};
    Simulation weft_run(scene);
    PlainFloatCloth plain(weft_run.cloth(), weft_run.force_field());
    const std::vector<Vec3> start = weft_run.cloth().positions;
    for (int s = 0; s < 50; ++s) {
        ASSERT_FALSE(weft_run.step().diverged());
        plain.step_symplectic_euler(1e-3f);
    }
    const std::vector<Vec3> exact = weft_run.cloth().positions, single = plain.positions();
    double largest_difference = 0.0, largest_motion = 0.0;
    for (std::size_t p = 0; p < exact.size(); ++p) {
        largest_difference = std::max(largest_difference, glm::length(single[p] - exact[p]));
        largest_motion = std::max(largest_motion, glm::length(exact[p] - start[p]));
    }
    // Positions of about 0.4 m carry float rounding of 3e-8 m; 50 steps of it, amplified by
    // the stiff springs' oscillation, stay far below 1e-5 m. A different force or update
    // (a missing dashpot, drag or wind term) moves the sheet by millimetres in 50 ms.
    EXPECT_LT(largest_difference, 1e-5);
    EXPECT_GT(largest_motion, 1e-3);  // the sheet moved: the comparison is not vacuous
    for (std::uint32_t pinned : weft_run.cloth().topology().pinned)  // where float put it, exactly
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(single[pinned][k], double(static_cast<float>(start[pinned][k])));
}

}  // namespace
}  // namespace weft::bench
