#include "sim/collision/self_collision.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>

#include "sim/collision/particle_pairs_sse2.h"
#include "sim/guards/sweep_watch.h"

namespace weft {

namespace {

// Work below this many particles stays on the calling thread (the hand-off costs more).
constexpr std::size_t min_particles_for_threads = 4096;

// The thirteen neighbour cells ahead of a cell, in (x, y, z) order: one of each opposite pair
// of the 26 around it.
constexpr std::array<std::array<int, 3>, 13> cells_ahead = {{{1, -1, -1},
                                                             {1, -1, 0},
                                                             {1, -1, 1},
                                                             {1, 0, -1},
                                                             {1, 0, 0},
                                                             {1, 0, 1},
                                                             {1, 1, -1},
                                                             {1, 1, 0},
                                                             {1, 1, 1},
                                                             {0, 1, -1},
                                                             {0, 1, 0},
                                                             {0, 1, 1},
                                                             {0, 0, 1}}};

using Moves = SelfCollision::Moves;

// One pass, no branch, every running value in a register of its own: a serial loop with an
// early exit took 10 µs over the 64² drape (a thread hand-off costs more than that).
void measure_moves(const Vec3* x, const Vec3* x0, std::size_t begin, std::size_t end,
                   Moves& moves) {
    double low_x = moves.low.x, low_y = moves.low.y, low_z = moves.low.z;
    double high_x = moves.high.x, high_y = moves.high.y, high_z = moves.high.z;
    double largest = moves.largest_squared;  // m²
    unsigned non_finite = moves.finite ? 0u : 1u;
    std::size_t p = begin;
#if defined(__SSE2__)
    // Two particles a round (particle_pairs_sse2.h): the box is three pairs of minima and
    // maxima. Each operation is the scalar loop's, lane by lane (min_pd(a, b) is
    // a < b ? a : b; each square sums x² + y², then z²): the same bits, in half the
    // instructions.
    if (end - p >= 2) {
        sse2::ParticlePair low_two = sse2::splat(Vec3(low_x, low_y, low_z));
        sse2::ParticlePair high_two = sse2::splat(Vec3(high_x, high_y, high_z));
        __m128d largest_two = _mm_set1_pd(largest);
        __m128d bad = _mm_setzero_pd();
        for (; p + 2 <= end; p += 2) {
            const sse2::ParticlePair d = sse2::load_pair(x, p) - sse2::load_pair(x0, p);  // m
            low_two = {_mm_min_pd(d.xy, low_two.xy), _mm_min_pd(d.zx, low_two.zx),
                       _mm_min_pd(d.yz, low_two.yz)};
            high_two = {_mm_max_pd(d.xy, high_two.xy), _mm_max_pd(d.zx, high_two.zx),
                        _mm_max_pd(d.yz, high_two.yz)};
            const __m128d squared = sse2::component_sums(d * d);  // m²
            largest_two = _mm_max_pd(squared, largest_two);
            bad = _mm_or_pd(bad, _mm_cmpneq_pd(_mm_sub_pd(squared, squared), _mm_setzero_pd()));
        }
        // Minima and maxima of numbers (no NaN is ever taken into them) in any order.
        using sse2::lane;
        low_x = std::min(lane(low_two.xy, 0), lane(low_two.zx, 1));
        low_y = std::min(lane(low_two.xy, 1), lane(low_two.yz, 0));
        low_z = std::min(lane(low_two.zx, 0), lane(low_two.yz, 1));
        high_x = std::max(lane(high_two.xy, 0), lane(high_two.zx, 1));
        high_y = std::max(lane(high_two.xy, 1), lane(high_two.yz, 0));
        high_z = std::max(lane(high_two.zx, 0), lane(high_two.yz, 1));
        largest = std::max(lane(largest_two, 0), lane(largest_two, 1));
        non_finite |= _mm_movemask_pd(bad) != 0 ? 1u : 0u;
    }
#endif
    for (; p < end; ++p) {
        const double dx = x[p].x - x0[p].x, dy = x[p].y - x0[p].y, dz = x[p].z - x0[p].z;  // m
        low_x = dx < low_x ? dx : low_x;
        low_y = dy < low_y ? dy : low_y;
        low_z = dz < low_z ? dz : low_z;
        high_x = dx > high_x ? dx : high_x;
        high_y = dy > high_y ? dy : high_y;
        high_z = dz > high_z ? dz : high_z;
        const double squared = dx * dx + dy * dy + dz * dz;  // m²
        largest = squared > largest ? squared : largest;
        // x - x is 0 for a finite x, NaN otherwise: a non-finite move, or one whose square
        // overflowed.
        non_finite |= squared - squared == 0.0 ? 0u : 1u;
    }
    moves.low = Vec3(low_x, low_y, low_z);
    moves.high = Vec3(high_x, high_y, high_z);
    moves.largest_squared = largest;
    moves.finite = non_finite == 0;
}

// The moves from each of `from` (each as long as `to`) to `to`, in one hand-off to the
// pool's threads: chunk by chunk, each chunk of `to` measured against every `from` while it
// is in cache. Minima, maxima and an "any" are exact whatever
// the order they are taken in, so the split never shows in the result.
template <std::size_t N>
std::array<Moves, N> measure_moves(std::span<const Vec3> to,
                                   const std::array<std::span<const Vec3>, N>& from,
                                   WorkerPool* pool) {
    constexpr std::size_t chunks = 8;
    std::array<std::array<Moves, N>, chunks> partial;
    const std::size_t count = to.size();
    parallel_for_if(pool, count >= min_particles_for_threads, chunks,
                    [&](std::size_t first_chunk, std::size_t last_chunk) {
                        for (std::size_t c = first_chunk; c < last_chunk; ++c)
                            for (std::size_t r = 0; r < N; ++r)
                                measure_moves(to.data(), from[r].data(), count * c / chunks,
                                              count * (c + 1) / chunks, partial[c][r]);
                    });
    std::array<Moves, N> total;
    for (std::size_t r = 0; r < N; ++r)
        for (const std::array<Moves, N>& chunk : partial) total[r].take_in(chunk[r]);
    return total;
}

// Whether the kept list may miss a pair, given the moves since it was built. A pair's
// separation changes by the difference of its two displacements since the list was built,
// Δb - Δa, and that difference is the same measured from any common motion T:
// (Δb - T) - (Δa - T). Take T the middle of the box that holds every displacement, of
// half-widths h: then |Δb - Δa| <= 2 |h|, and a pair closer than the thickness now was closer
// than thickness + 2 |h| then. So the list holds while 2 |h| <= margin. A sheet falling or
// sliding as a whole keeps its list; measuring each displacement from zero (|Δ| <= margin / 2
// for all) rebuilt it every 40 steps of the drape's fall, at 1.4 ms a rebuild.
bool outlived(const Moves& since_built, double margin) {
    if (!since_built.finite) return true;
    // 1e-6 spare: rounding in the displacements and the distances is parts in 1e16.
    return !(since_built.half_width_squared() <= 0.25 * margin * margin * (1.0 - 1e-6));
}

}  // namespace

long long SelfCollision::cell_coordinate(double position, double cell_size) {
    return static_cast<long long>(std::clamp(std::floor(position / cell_size), -1e15, 1e15));
}

std::size_t SelfCollision::hash_cell(long long cx, long long cy, long long cz, std::size_t mask) {
    // Large primes spread neighbouring cells over the table; collisions only add candidates.
    // Unsigned arithmetic: wrapping is the intent. The table size is a power of two, so the
    // slot is a mask, not a division (this runs 14 times per particle and pass).
    const std::uint64_t h = (static_cast<std::uint64_t>(cx) * 92837111u) ^
                            (static_cast<std::uint64_t>(cy) * 689287499u) ^
                            (static_cast<std::uint64_t>(cz) * 283923481u);
    return static_cast<std::size_t>(h & mask);
}

void SelfCollision::rebuild_hash(const Cloth& cloth, WorkerPool* pool) {
    const std::size_t count = cloth.particle_count();
    // At least twice as many slots as particles keeps the chains short.
    std::size_t slots = 1;
    while (slots < 2 * count) slots *= 2;
    slot_mask_ = slots - 1;
    cell_start_.assign(slots + 1, 0);
    cell_entries_.resize(count);
    cells_.resize(count);
    slots_.resize(count);
    parallel_for_if(
        pool, count >= min_particles_for_threads, count, [&](std::size_t begin, std::size_t end) {
            for (std::size_t p = begin; p < end; ++p) {
                const Vec3& x = cloth.positions[p];
                cells_[p] = {cell_coordinate(x.x, reach()), cell_coordinate(x.y, reach()),
                             cell_coordinate(x.z, reach())};
                slots_[p] = static_cast<std::uint32_t>(
                    hash_cell(cells_[p][0], cells_[p][1], cells_[p][2], slot_mask_));
            }
        });
    for (std::size_t p = 0; p < count; ++p) ++cell_start_[slots_[p]];
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    // Fill from the back so each cell's entries end up in ascending particle order.
    for (std::size_t p = count; p-- > 0;)
        cell_entries_[--cell_start_[slots_[p]]] = static_cast<std::uint32_t>(p);
}

void SelfCollision::rebuild_joined_partners(const Cloth& cloth) {
    // Each particle's partners in a compressed row (counted, prefix-summed, filled): a
    // lookup reads the dozen or so entries of one particle, contiguous, where a binary
    // search over all 24 000 springs of a 64² sheet missed the cache at every level and
    // took most of a list rebuild's time.
    const std::size_t count = cloth.particle_count();
    joined_start_.assign(count + 1, 0);
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs) {
            ++joined_start_[spring.i + 1];
            ++joined_start_[spring.j + 1];
        }
    for (std::size_t p = 1; p <= count; ++p) joined_start_[p] += joined_start_[p - 1];
    joined_partners_.resize(joined_start_[count]);
    joined_fill_.assign(joined_start_.begin(), joined_start_.end() - 1);
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs) {
            joined_partners_[joined_fill_[spring.i]++] = spring.j;
            joined_partners_[joined_fill_[spring.j]++] = spring.i;
        }
    joined_spring_count_ = cloth.spring_count();
}

bool SelfCollision::refresh_joined_partners(const Cloth& cloth) {
    if (cloth.spring_count() == joined_spring_count_ &&
        joined_start_.size() == cloth.particle_count() + 1)
        return false;
    rebuild_joined_partners(cloth);
    return true;
}

bool SelfCollision::joined(std::uint32_t a, std::uint32_t b) const {
    const std::uint32_t* partner = joined_partners_.data() + joined_start_[a];
    const std::uint32_t* const end = joined_partners_.data() + joined_start_[a + 1];
    for (; partner != end; ++partner)
        if (*partner == b) return true;
    return false;
}

bool SelfCollision::moved_beyond_margin(const Cloth& cloth, WorkerPool* pool) const {
    if (built_at_.size() != cloth.particle_count()) return true;
    return outlived(measure_moves<1>(cloth.positions, {built_at_}, pool)[0], margin());
}

void SelfCollision::rebuild_candidates(const Cloth& cloth, WorkerPool* pool) {
    candidates_.clear();
    rebuild_hash(cloth, pool);
    const double reach_squared = reach() * reach();
    // Each pair of particles in neighbouring cells is looked at once: from the particle
    // whose cell the other's is ahead of (the thirteen cells ahead: half of the 26, one of
    // each opposite pair), or, in one cell, from the lower index. A slot of the hash table
    // can hold other cells too (hash collisions), so a particle counts only in its own cell:
    // no pair is found twice.
    auto look_at = [&](std::vector<std::pair<std::uint32_t, std::uint32_t>>& found, std::size_t p,
                       const std::array<long long, 3>& cell, bool same_cell) {
        const std::size_t slot = hash_cell(cell[0], cell[1], cell[2], slot_mask_);
        for (std::uint32_t e = cell_start_[slot]; e < cell_start_[slot + 1]; ++e) {
            const std::uint32_t q = cell_entries_[e];
            const std::array<long long, 3>& q_cell = cells_[q];
            if ((same_cell && q <= p) || q_cell[0] != cell[0] || q_cell[1] != cell[1] ||
                q_cell[2] != cell[2])
                continue;
            const Vec3 d = cloth.positions[q] - cloth.positions[p];
            if (glm::dot(d, d) >= reach_squared) continue;
            const auto a = static_cast<std::uint32_t>(std::min<std::size_t>(p, q));
            const auto b = static_cast<std::uint32_t>(std::max<std::size_t>(p, q));
            if (!joined(a, b)) found.emplace_back(a, b);
        }
    };
    // The particles in a fixed number of chunks, each with its own list, so threads never
    // share one; the lists are joined in chunk order and sorted, the same for any split.
    const std::size_t count = cloth.particle_count();
    found_by_chunk_.resize(search_chunks);
    parallel_for_if(
        pool, count >= min_particles_for_threads, search_chunks,
        [&](std::size_t first_chunk, std::size_t last_chunk) {
            for (std::size_t chunk = first_chunk; chunk < last_chunk; ++chunk) {
                std::vector<std::pair<std::uint32_t, std::uint32_t>>& found =
                    found_by_chunk_[chunk];
                found.clear();
                for (std::size_t p = count * chunk / search_chunks;
                     p < count * (chunk + 1) / search_chunks; ++p) {
                    const std::array<long long, 3>& cell = cells_[p];
                    look_at(found, p, cell, true);
                    for (const std::array<int, 3>& ahead : cells_ahead)
                        look_at(found, p,
                                {cell[0] + ahead[0], cell[1] + ahead[1], cell[2] + ahead[2]},
                                false);
                }
            }
        });
    for (const auto& found : found_by_chunk_)
        candidates_.insert(candidates_.end(), found.begin(), found.end());
    // In ascending order, the order the Gauss–Seidel pass resolves them in.
    std::sort(candidates_.begin(), candidates_.end());
    built_at_ = cloth.positions;
    ++list_builds_;
}

void SelfCollision::find_pairs(const Cloth& cloth,
                               std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                               WorkerPool* pool) {
    find_pairs(cloth, pairs, pool, std::nullopt);
}

void SelfCollision::find_pairs(const Cloth& cloth,
                               std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                               WorkerPool* pool, std::optional<bool> list_outlived) {
    pairs.clear();
    if (cloth.particle_count() == 0) return;
    // Torn or cut springs: their ends may collide now.
    const bool springs_changed = refresh_joined_partners(cloth);
    if (springs_changed || (list_outlived ? *list_outlived : moved_beyond_margin(cloth, pool)))
        rebuild_candidates(cloth, pool);
    const double thickness_squared = thickness_ * thickness_;
    for (const auto& [a, b] : candidates_) {
        const Vec3 d = cloth.positions[b] - cloth.positions[a];
        if (glm::dot(d, d) < thickness_squared) pairs.emplace_back(a, b);
    }
}

void SelfCollision::Moves::take_in(const Moves& part) {
    // Minima, maxima and an "and" of numbers (no NaN is ever taken into them): exact in any
    // order, so the split into parts never shows.
    low = glm::min(low, part.low);
    high = glm::max(high, part.high);
    largest_squared = std::max(largest_squared, part.largest_squared);
    finite = finite && part.finite;
}

void SelfCollision::measure_step_moves(const Vec3* positions, const Vec3* step_start,
                                       std::size_t begin, std::size_t end,
                                       MeasuredMoves& into) const {
    Moves from_start, since_built;
    measure_moves(positions, step_start, begin, end, from_start);
    const bool list_fits = built_at_.size() == into.particle_count;
    if (list_fits) measure_moves(positions, built_at_.data(), begin, end, since_built);
    std::lock_guard lock(into.mutex);
    into.from_start.take_in(from_start);
    into.since_built.take_in(since_built);
    into.list_fits = list_fits;
}

std::size_t SelfCollision::resolve(Cloth& cloth, std::span<const Collider> colliders,
                                   WorkerPool* pool, std::span<const Vec3> step_start,
                                   SweepWatch* watch, const MeasuredMoves* measured) {
    // Whether the kept list outlived its margin, when measured here with the step's moves
    // (both in one hand-off to the threads), or by the caller on its way.
    std::optional<bool> list_outlived;
    if (step_start.size() == cloth.particle_count() && cloth.particle_count() > 0) {
        Moves moves;
        if (measured) {
            moves = measured->from_start;
            if (measured->list_fits) list_outlived = outlived(measured->since_built, margin());
        } else if (built_at_.size() == cloth.particle_count()) {
            const std::array<Moves, 2> both =
                measure_moves<2>(cloth.positions, {step_start, built_at_}, pool);
            moves = both[0];
            list_outlived = outlived(both[1], margin());
        } else {
            moves = measure_moves<1>(cloth.positions, {step_start}, pool)[0];
        }
        // A diverged step is the guard's to report, not swept here.
        const bool finite = moves.finite;
        const double largest_move_squared = moves.largest_squared;
        // Two particles' relative move is at most twice the half-width h of the box that holds
        // every particle's move (the same measure the kept list uses): while 2|h| is under the
        // thickness, two that end the step apart were never closer than the thickness minus
        // their relative move, so they cannot have passed through each other (they were apart
        // at its start): the end check holds. Measured from the common motion, a sheet that
        // moves as a whole, however fast, needs no swept pass (a diverging step that flings
        // the whole sheet took the swept pass to all pairs: a fuzzer's timeout).
        if (finite && moves.half_width_squared() > 0.25 * thickness_ * thickness_) {
            // The list's positions are stale after this; the next plain pass rebuilds it.
            built_at_.clear();
            return resolve_swept(cloth, colliders, step_start, std::sqrt(largest_move_squared),
                                 pool, watch);
        }
    }
    std::size_t first_pass_pairs = 0;
    for (int pass = 0; pass < max_passes; ++pass) {
        find_pairs(cloth, pairs_, pool, pass == 0 ? list_outlived : std::nullopt);
        if (pass == 0) first_pass_pairs = pairs_.size();
        if (pairs_.empty()) break;
        const double deepest = separate_pairs(cloth, watch);
        if (!colliders.empty()) push_out_of_impulse_colliders(colliders, cloth, pool, watch);
        // Corrections this small (and the push out of a solid, which is no larger) cannot
        // have left an overlap worth another pass.
        if (deepest < settled_overlap * thickness_) break;
    }
    return first_pass_pairs;
}

double SelfCollision::separate_pairs(Cloth& cloth, SweepWatch* watch) const {
    double deepest = 0.0;
    for (const auto& [a, b] : pairs_) {
        const double wa = cloth.topology().inverse_masses[a],
                     wb = cloth.topology().inverse_masses[b];
        if (wa + wb == 0.0) continue;
        Vec3 d = cloth.positions[b] - cloth.positions[a];
        double distance = glm::length(d);
        if (distance >= thickness_) continue;  // an earlier correction already separated them
        // Coincident particles: separate along an arbitrary fixed axis.
        const Vec3 n = distance > 0.0 ? d / distance : Vec3(0.0, 1.0, 0.0);
        const double overlap = thickness_ - distance;
        deepest = std::max(deepest, overlap);
        push_apart(cloth, a, b, n, overlap, watch);
    }
    return deepest;
}

void SelfCollision::push_apart(Cloth& cloth, std::uint32_t a, std::uint32_t b, const Vec3& n,
                               double overlap, SweepWatch* watch) {
    const double wa = cloth.topology().inverse_masses[a], wb = cloth.topology().inverse_masses[b];
    const double share_a = wa / (wa + wb), share_b = wb / (wa + wb);
    cloth.positions[a] -= share_a * overlap * n;
    cloth.positions[b] += share_b * overlap * n;
    // Perfectly inelastic along n: the approaching part of the relative velocity goes.
    const double approach = glm::dot(cloth.velocities[b] - cloth.velocities[a], n);
    if (approach < 0.0) {
        cloth.velocities[a] += share_a * approach * n;
        cloth.velocities[b] -= share_b * approach * n;
    }
    if (watch) {
        watch->check(a, cloth.positions[a], cloth.velocities[a]);
        watch->check(b, cloth.positions[b], cloth.velocities[b]);
    }
}

}  // namespace weft
