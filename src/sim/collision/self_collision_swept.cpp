// The swept self-collision pass (self_collision.h): for steps that move particles further
// than half the thickness, where two particles can pass through each other between the
// step's two ends.
//
// Broad phase: each particle's path over the step, start to end, boxed and grown by the
// thickness, is entered in every cell of a grid it overlaps (cells sized to the largest move,
// so a box covers a few cells a side), through a hash table like the list's. A pair is
// looked at in one cell only: the lowest corner of the overlap of their boxes of cells.
// Narrow phase, every pass: the closest approach of the two straight paths. A pair that
// ends closer than the thickness, still approaching, is pushed apart along its separation
// at the end (as the plain pass does); a pair that came closer within the step and is
// moving apart again, possibly through each other, is put back on the side it started on:
// its separation along its start direction made the thickness again, so its path never
// crosses. Both lose the approaching part of their relative velocity.
//
// Why particle pairs are enough to keep a sheet from passing through itself: a particle
// crossing a triangle of the sheet does so at a point within the triangle, which is at most
// its circumradius from a corner: spacing / √2 on an unstretched square grid. A thickness
// above that (the shipped self-collision scenes use 0.75 spacing) makes a crossing bring the
// pair within the thickness, and the pass sees it.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "sim/collision/self_collision.h"
#include "sim/guards/sweep_watch.h"

namespace weft {

std::size_t SelfCollision::resolve_swept(Cloth& cloth, std::span<const Collider> colliders,
                                         std::span<const Vec3> step_start, double largest_move,
                                         WorkerPool* pool, SweepWatch* watch) {
    find_swept_candidates(cloth, step_start, largest_move);
    std::size_t first_pass_pairs = 0;
    for (int pass = 0; pass < max_passes; ++pass) {
        std::size_t close_pairs = 0;
        const double deepest = separate_swept_pairs(cloth, step_start, close_pairs, watch);
        if (pass == 0) first_pass_pairs = close_pairs;
        if (close_pairs == 0) break;
        if (!colliders.empty()) push_out_of_impulse_colliders(colliders, cloth, pool, watch);
        if (deepest < settled_overlap * thickness_) break;
    }
    return first_pass_pairs;
}

void SelfCollision::find_swept_candidates(const Cloth& cloth, std::span<const Vec3> step_start,
                                          double largest_move) {
    refresh_joined_partners(cloth);
    const std::size_t count = cloth.particle_count();
    // Grown by the thickness each: two paths within the thickness overlap with half of it
    // to spare, room for the passes' pushes.
    const double grow = thickness_;
    const double cell = std::max(2.0 * thickness_, 0.5 * largest_move);  // m
    auto box = [&](std::size_t p, Vec3& low, Vec3& high) {
        low = glm::min(step_start[p], cloth.positions[p]) - Vec3(grow);
        high = glm::max(step_start[p], cloth.positions[p]) + Vec3(grow);
    };
    swept_low_.resize(count);
    swept_high_.resize(count);
    std::size_t entries = 0;
    for (std::size_t p = 0; p < count; ++p) {
        Vec3 low, high;
        box(p, low, high);
        for (int axis = 0; axis < 3; ++axis) {
            swept_low_[p][axis] = cell_coordinate(low[axis], cell);
            swept_high_[p][axis] = cell_coordinate(high[axis], cell);
        }
        std::size_t cells = 1;
        for (int axis = 0; axis < 3; ++axis)
            cells *= static_cast<std::size_t>(swept_high_[p][axis] - swept_low_[p][axis] + 1);
        entries += cells;
    }
    std::size_t slots = 1;
    while (slots < 2 * entries) slots *= 2;
    const std::size_t mask = slots - 1;
    auto for_each_cell = [&](std::size_t p, auto&& visit) {
        const auto& low = swept_low_[p];
        const auto& high = swept_high_[p];
        for (long long x = low[0]; x <= high[0]; ++x)
            for (long long y = low[1]; y <= high[1]; ++y)
                for (long long z = low[2]; z <= high[2]; ++z) visit(x, y, z);
    };
    // Counting sort of the entries by slot; within a slot, ascending particles (a particle
    // twice in a slot, for two cells that share it, sits twice in a row).
    swept_cell_start_.assign(slots + 1, 0);
    swept_slots_.clear();
    for (std::size_t p = 0; p < count; ++p)
        for_each_cell(p, [&](long long x, long long y, long long z) {
            const auto slot = static_cast<std::uint32_t>(hash_cell(x, y, z, mask));
            swept_slots_.push_back(slot);
            ++swept_cell_start_[slot];
        });
    for (std::size_t c = 1; c < swept_cell_start_.size(); ++c)
        swept_cell_start_[c] += swept_cell_start_[c - 1];
    swept_entries_.resize(swept_slots_.size());
    for (std::size_t p = count, e = swept_slots_.size(); p-- > 0;) {
        std::size_t cells = 1;
        for (int axis = 0; axis < 3; ++axis)
            cells *= static_cast<std::size_t>(swept_high_[p][axis] - swept_low_[p][axis] + 1);
        for (std::size_t k = 0; k < cells; ++k)
            swept_entries_[--swept_cell_start_[swept_slots_[--e]]] = static_cast<std::uint32_t>(p);
    }
    swept_candidates_.clear();
    for (std::size_t p = 0; p < count; ++p) {
        Vec3 low_p, high_p;
        box(p, low_p, high_p);
        for_each_cell(p, [&](long long x, long long y, long long z) {
            const std::size_t slot = hash_cell(x, y, z, mask);
            std::uint32_t previous = static_cast<std::uint32_t>(-1);
            for (std::uint32_t e = swept_cell_start_[slot]; e < swept_cell_start_[slot + 1]; ++e) {
                const std::uint32_t q = swept_entries_[e];
                if (q <= p || q == previous) continue;
                previous = q;
                const auto& low_q = swept_low_[q];
                const auto& high_q = swept_high_[q];
                // This cell must be in q's box too, and be the pair's lowest shared cell.
                const long long cell_of_pair[3] = {std::max(swept_low_[p][0], low_q[0]),
                                                   std::max(swept_low_[p][1], low_q[1]),
                                                   std::max(swept_low_[p][2], low_q[2])};
                if (x != cell_of_pair[0] || y != cell_of_pair[1] || z != cell_of_pair[2] ||
                    x > high_q[0] || y > high_q[1] || z > high_q[2])
                    continue;
                Vec3 low_b, high_b;
                box(q, low_b, high_b);
                if (glm::any(glm::greaterThan(low_b, high_p)) ||
                    glm::any(glm::greaterThan(low_p, high_b)))
                    continue;
                if (!joined(static_cast<std::uint32_t>(p), q))
                    swept_candidates_.emplace_back(static_cast<std::uint32_t>(p), q);
            }
        });
    }
}

double SelfCollision::separate_swept_pairs(Cloth& cloth, std::span<const Vec3> step_start,
                                           std::size_t& close_pairs, SweepWatch* watch) const {
    double deepest = 0.0;
    for (const auto& [a, b] : swept_candidates_) {
        if (cloth.topology().inverse_masses[a] + cloth.topology().inverse_masses[b] == 0.0)
            continue;
        const Vec3 start = step_start[b] - step_start[a];
        const Vec3 end = cloth.positions[b] - cloth.positions[a];
        // Closest approach of the straight paths: start + t (end - start), t in [0, 1].
        const Vec3 change = end - start;
        const double change_squared = glm::dot(change, change);
        const double t = change_squared > 0.0
                             ? std::clamp(-glm::dot(start, change) / change_squared, 0.0, 1.0)
                             : 1.0;
        const Vec3 closest = start + t * change;
        if (glm::dot(closest, closest) >= thickness_ * thickness_) continue;
        const double end_distance = glm::length(end);
        const double start_distance = glm::length(start);
        Vec3 n;
        double overlap;
        if (t >= 1.0 || start_distance == 0.0) {
            // Closest at the end: approaching still, as in the plain pass.
            n = end_distance > 0.0 ? end / end_distance : Vec3(0.0, 1.0, 0.0);
            overlap = thickness_ - end_distance;
        } else {
            // They came closer within the step: back to the side they started on.
            n = start / start_distance;
            overlap = thickness_ - glm::dot(end, n);
        }
        if (overlap <= 0.0) continue;
        ++close_pairs;
        deepest = std::max(deepest, overlap);
        push_apart(cloth, a, b, n, overlap, watch);
    }
    return deepest;
}

}  // namespace weft
