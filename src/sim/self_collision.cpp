#include "sim/self_collision.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "sim/topology_edits.h"

namespace weft {

namespace {

// Integer cell coordinate, clamped so that far-flung (but finite) particles cannot overflow
// the conversion; cells that far out only ever hold the particles that flew there.
long long cell_coordinate(double position, double cell_size) {
    return static_cast<long long>(std::clamp(std::floor(position / cell_size), -1e15, 1e15));
}

}  // namespace

std::size_t SelfCollision::hash_cell(long long cx, long long cy, long long cz) const {
    // Large primes spread neighbouring cells over the table; collisions only add candidates.
    // Unsigned arithmetic: wrapping is the intent.
    const std::uint64_t h = (static_cast<std::uint64_t>(cx) * 92837111u) ^
                            (static_cast<std::uint64_t>(cy) * 689287499u) ^
                            (static_cast<std::uint64_t>(cz) * 283923481u);
    // The table size is a power of two: a mask, not a 64-bit division, for each of the 27
    // cells around every particle. Which slot a cell lands in only changes the candidates,
    // never the pairs found (each is tested by distance, and the list is sorted).
    return static_cast<std::size_t>(h & (cell_start_.size() - 2));
}

std::size_t SelfCollision::cell_of(const Vec3& x) const {
    return hash_cell(cell_coordinate(x.x, thickness_), cell_coordinate(x.y, thickness_),
                     cell_coordinate(x.z, thickness_));
}

void SelfCollision::rebuild_hash(const Cloth& cloth) {
    const std::size_t count = cloth.particle_count();
    // At least twice as many slots as particles keeps the chains short; a power of two.
    std::size_t slots = 2;
    while (slots < 2 * count) slots *= 2;
    cell_start_.assign(slots + 1, 0);
    cell_entries_.resize(count);
    for (const Vec3& x : cloth.positions) ++cell_start_[cell_of(x)];
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    // Fill from the back so each cell's entries end up in ascending particle order.
    for (std::size_t p = count; p-- > 0;)
        cell_entries_[--cell_start_[cell_of(cloth.positions[p])]] = static_cast<std::uint32_t>(p);
}

void SelfCollision::rebuild_joined_pairs(const Cloth& cloth) {
    joined_pairs_.clear();
    for (const SpringGroup& group : cloth.spring_groups)
        for (const Spring& spring : group.springs)
            joined_pairs_.push_back(edge_key(spring.i, spring.j));
    std::sort(joined_pairs_.begin(), joined_pairs_.end());
    joined_spring_count_ = cloth.spring_count();
}

bool SelfCollision::joined(std::uint32_t a, std::uint32_t b) const {
    return std::binary_search(joined_pairs_.begin(), joined_pairs_.end(), edge_key(a, b));
}

void SelfCollision::find_pairs(const Cloth& cloth,
                               std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) {
    pairs.clear();
    if (cloth.particle_count() == 0) return;
    if (cloth.spring_count() != joined_spring_count_) rebuild_joined_pairs(cloth);
    rebuild_hash(cloth);
    const double thickness_squared = thickness_ * thickness_;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        const Vec3& x = cloth.positions[p];
        const long long cx = cell_coordinate(x.x, thickness_);
        const long long cy = cell_coordinate(x.y, thickness_);
        const long long cz = cell_coordinate(x.z, thickness_);
        const std::size_t first_pair = pairs.size();
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz) {
                    const std::size_t cell = hash_cell(cx + dx, cy + dy, cz + dz);
                    for (std::uint32_t e = cell_start_[cell]; e < cell_start_[cell + 1]; ++e) {
                        const std::uint32_t q = cell_entries_[e];
                        if (q <= p) continue;
                        const Vec3 d = cloth.positions[q] - x;
                        if (glm::dot(d, d) >= thickness_squared) continue;
                        if (joined(static_cast<std::uint32_t>(p), q)) continue;
                        pairs.emplace_back(static_cast<std::uint32_t>(p), q);
                    }
                }
        // Hash collisions can list a cell twice: sort and drop repeats of this particle's pairs.
        std::sort(pairs.begin() + static_cast<std::ptrdiff_t>(first_pair), pairs.end());
        pairs.erase(
            std::unique(pairs.begin() + static_cast<std::ptrdiff_t>(first_pair), pairs.end()),
            pairs.end());
    }
}

std::size_t SelfCollision::resolve(Cloth& cloth) {
    find_pairs(cloth, pairs_);
    for (const auto& [a, b] : pairs_) {
        const double wa = cloth.inverse_masses[a], wb = cloth.inverse_masses[b];
        if (wa + wb == 0.0) continue;
        Vec3 d = cloth.positions[b] - cloth.positions[a];
        double distance = glm::length(d);
        if (distance >= thickness_) continue;  // an earlier correction already separated them
        // Coincident particles: separate along an arbitrary fixed axis.
        const Vec3 n = distance > 0.0 ? d / distance : Vec3(0.0, 1.0, 0.0);
        const double share_a = wa / (wa + wb), share_b = wb / (wa + wb);
        const double overlap = thickness_ - distance;
        cloth.positions[a] -= share_a * overlap * n;
        cloth.positions[b] += share_b * overlap * n;
        // Perfectly inelastic along n: the approaching part of the relative velocity goes.
        const double approach = glm::dot(cloth.velocities[b] - cloth.velocities[a], n);
        if (approach < 0.0) {
            cloth.velocities[a] += share_a * approach * n;
            cloth.velocities[b] -= share_b * approach * n;
        }
    }
    return pairs_.size();
}

}  // namespace weft
