// A cloth state far from rest, and a field with every external force on, shared by the force
// pass tests: every spring loaded and moving, so no term of the force can hide.
#pragma once

#include <cstring>
#include <random>
#include <vector>

#include "sim/build/cloth_builder.h"
#include "sim/core/cloth.h"
#include "sim/core/force_pass.h"
#include "sim/scene/scene.h"

namespace weft::testing {

// A rows × cols sheet `spacing` (m) apart with all three spring families, stiff and damped,
// its top corners pinned.
inline Scene three_family_scene(int rows, int cols, double spacing) {
    Scene scene;
    scene.cloth.rows = rows;
    scene.cloth.cols = cols;
    scene.cloth.spacing = spacing;
    scene.structural = {true, 800.0, 0.5};
    scene.shear = {true, 400.0, 0.3};
    scene.bend = {true, 100.0, 0.1};
    return scene;
}

// That sheet 0.02 m apart, built, at rest.
inline Cloth three_family_sheet(int rows, int cols) {
    return build_grid_cloth(three_family_scene(rows, cols, 0.02));
}

// Moves every particle up to `jitter` (m) per axis from where it is and gives it a random
// velocity of up to 1 m/s per axis.
inline void scramble(Cloth& cloth, unsigned seed, double jitter) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> offset(-jitter, jitter), speed(-1.0, 1.0);
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        cloth.positions[p] += Vec3(offset(rng), offset(rng), offset(rng));
        cloth.velocities[p] = Vec3(speed(rng), speed(rng), speed(rng));
    }
}

// Gravity off the vertical, air drag and wind: every external term non-zero in x, y and z.
inline ForceField windy_field() {
    ForceField field;
    field.gravity = {0.5, -9.81, 0.25};
    field.air_drag = 0.03;
    field.wind = {1.0, 0.0, 2.0};
    return field;
}

inline bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

}  // namespace weft::testing
