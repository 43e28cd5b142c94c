#include "sim/core/force_pass.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "sim/grid/grid_force_pass.h"

namespace weft {

namespace {

// A colour is split between threads only when it is big enough to pay for the hand-off.
constexpr std::size_t min_springs_per_parallel_colour = 2048;

void apply_springs(const SpringGroup& group, std::size_t begin, std::size_t end, const Vec3* x,
                   const Vec3* v, Vec3* f) {
    // Hoist the group's material and the base pointers out of the loop.
    const double stiffness = group.stiffness;
    const double damping = group.damping;
    const Spring* springs = group.springs.data();
    for (std::size_t s = begin; s < end; ++s) {
        const Spring& spring = springs[s];
        const Vec3 d = x[spring.j] - x[spring.i];
        const double length = std::sqrt(glm::dot(d, d));
        if (length <= 0.0) continue;  // coincident ends: no direction to push along
        const Vec3 u = d / length;
        // Hooke's law plus a dashpot on the rate of change of length, (v_j - v_i) · u.
        const double tension = stiffness * (length - spring.rest_length) +
                               damping * glm::dot(v[spring.j] - v[spring.i], u);
        const Vec3 force_on_i = tension * u;
        f[spring.i] += force_on_i;
        f[spring.j] -= force_on_i;
    }
}

}  // namespace

void accumulate_spring_forces(const SpringGroup& group, std::span<const Vec3> positions,
                              std::span<const Vec3> velocities, std::span<Vec3> forces,
                              WorkerPool* pool) {
    const Vec3* x = positions.data();
    const Vec3* v = velocities.data();
    Vec3* f = forces.data();
    if (group.colour_starts.empty()) {
        apply_springs(group, 0, group.springs.size(), x, v, f);
        return;
    }
    const bool threaded = pool && pool->thread_count() > 1;
    for (std::size_t k = 0; k + 1 < group.colour_starts.size(); ++k) {
        const std::size_t begin = group.colour_starts[k], end = group.colour_starts[k + 1];
        if (threaded && end - begin >= min_springs_per_parallel_colour) {
            pool->parallel_for(end - begin, [&](std::size_t lo, std::size_t hi) {
                apply_springs(group, begin + lo, begin + hi, x, v, f);
            });
        } else {
            apply_springs(group, begin, end, x, v, f);
        }
    }
    apply_springs(group, group.colour_starts.back(), group.springs.size(), x, v, f);
}

void accumulate_forces(const Cloth& cloth, const ForceField& field, std::span<const Vec3> positions,
                       std::span<const Vec3> velocities, std::span<Vec3> forces, WorkerPool* pool,
                       SimdLevel level) {
    const std::size_t count = positions.size();
    const double* mass = cloth.topology().masses.data();
    const Vec3* v = velocities.data();
    Vec3* f = forces.data();
    // A plain grid takes the structured pass (grid_force_pass.h): gravity, drag and springs
    // per direction over rows. Anything else takes the general one, spring by spring.
    if (!accumulate_grid_forces(cloth, field, positions, velocities, forces, pool, level)) {
        // External forces first: they also initialise the accumulator.
        if (field.air_drag != 0.0) {
            for (std::size_t p = 0; p < count; ++p)
                f[p] = mass[p] * field.gravity - field.air_drag * (v[p] - field.wind);
        } else {
            for (std::size_t p = 0; p < count; ++p) f[p] = mass[p] * field.gravity;
        }
        for (const SpringGroup& group : cloth.topology().spring_groups)
            accumulate_spring_forces(group, positions, velocities, forces, pool);
    }
    if (!field.colliders.empty())
        accumulate_repulsion_forces(field.colliders, cloth, positions, velocities, forces);
}

}  // namespace weft
