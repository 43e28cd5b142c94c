// Self-collision: particles closer than the cloth's thickness push apart, unless a spring
// joins them (neighbours are meant to be that close).
//
// Candidate pairs are kept between steps, as a Verlet list (as molecular dynamics keeps its
// neighbour lists): every unjoined pair closer than the reach, thickness + margin, when the
// list was built. While no two particles can have come closer by more than the margin since
// then (self_collision.cpp bounds that from the box of all displacements), any pair
// now closer than the thickness was closer than the reach then, so it is on the list: the
// pass only measures the listed pairs. An explicit step moves a particle a small part of a
// spacing, so the list lasts many steps; it is rebuilt when particles have moved further
// relative to each other, when springs are torn or cut (their ends may now collide), or when the
// cloth changes size. The list is built from a spatial hash of cells one reach wide (Teschner et
// al. 2003; Müller's Ten Minute Physics), so the cost stays linear in the number of particles.
#pragma once

#include <array>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include <span>

#include "parallel/worker_pool.h"
#include "sim/collision/colliders.h"
#include "sim/core/cloth.h"

namespace weft {

class SelfCollision {
  public:
    explicit SelfCollision(double thickness) : thickness_(thickness) {}

    double thickness() const { return thickness_; }  // m
    // How many times the candidate list has been built (its cost: a spatial hash of the sheet).
    std::size_t list_builds() const { return list_builds_; }

    // Every pair (i < j) closer than the thickness and not joined by a spring, ascending.
    // The list's rebuild and its check are split between the pool's threads; the pairs are
    // the same for any thread count.
    void find_pairs(const Cloth& cloth, std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                    WorkerPool* pool = nullptr);

    // Pushes each close pair apart to the thickness (half each, or all to the free one) and
    // removes their approaching relative normal velocity. Returns the pairs resolved in the
    // first pass.
    //
    // One pass over the pairs is not enough: pairs are resolved one after another, so a later
    // push can undo part of an earlier one, and a push can drive a particle back into a solid
    // the contact pass has just moved it out of (a fold lying on the ground: the lower layer
    // is pushed into the ground). So the pass is repeated, Gauss–Seidel fashion, each time
    // followed by pushing particles back out of the impulse `colliders`, until no close pair
    // is left or `max_passes` are done. The solids go last: they are hard, never left
    // violated; what is left over is a small overlap between layers, which the next step's
    // passes take up.
    //
    // `step_start`: the positions at the start of the step just taken, when the caller has
    // them. A step that moved some particle further than half the thickness (a frame-sized
    // implicit step does) can carry two particles through each other between its two ends,
    // where no check of the end positions sees it. Then the pass is swept
    // (self_collision_swept.cpp): candidates are the pairs whose straight paths over the
    // step pass near each other, and a pair that came within the thickness is put back
    // apart on the side it started from.
    //
    // With a `watch`, every particle the passes move is checked for the divergence guard
    // (sweep_watch.h).
    //
    // `measured`: the step's moves, measured by the caller on its way (measure_step_moves below),
    // so resolve does not measure them again.
    struct MeasuredMoves;
    std::size_t resolve(Cloth& cloth, std::span<const Collider> colliders = {},
                        WorkerPool* pool = nullptr, std::span<const Vec3> step_start = {},
                        SweepWatch* watch = nullptr, const MeasuredMoves* measured = nullptr);

    // How particles moved between two states: the box holding every displacement, the
    // largest displacement, and whether all are finite.
    struct Moves {
        Vec3 low{std::numeric_limits<double>::infinity()};    // m, per component
        Vec3 high{-std::numeric_limits<double>::infinity()};  // m, per component
        double largest_squared = 0.0;                         // m²
        bool finite = true;
        double half_width_squared() const {  // m²: |h|², h the box's half-widths
            const Vec3 half_width = 0.5 * (high - low);
            return glm::dot(half_width, half_width);
        }
        void take_in(const Moves& part);  // the moves of both
    };
    // What resolve measures of a step, gathered from ranges of particles measured apart.
    struct MeasuredMoves {
        explicit MeasuredMoves(std::size_t particles) : particle_count(particles) {}
        std::size_t particle_count;
        Moves from_start;   // from the step's start
        Moves since_built;  // from the positions the kept list was built at
        bool list_fits = false;
        std::mutex mutex;
    };
    // Measures particles [begin, end) for resolve: from the step's start and from the kept
    // list's positions. Thread-safe; each particle once, after the contacts have moved it.
    void measure_step_moves(const Vec3* positions, const Vec3* step_start, std::size_t begin,
                            std::size_t end, MeasuredMoves& into) const;
    static constexpr int max_passes = 8;
    static constexpr double settled_overlap = 1e-3;  // × thickness: a pass this deep is the last

  private:
    // One Gauss–Seidel pass over pairs_; returns the deepest overlap it corrected (m).
    double separate_pairs(Cloth& cloth, SweepWatch* watch) const;
    // The swept pass (self_collision_swept.cpp).
    std::size_t resolve_swept(Cloth& cloth, std::span<const Collider> colliders,
                              std::span<const Vec3> step_start, double largest_move,
                              WorkerPool* pool, SweepWatch* watch);
    void find_swept_candidates(const Cloth& cloth, std::span<const Vec3> step_start,
                               double largest_move);
    // One swept Gauss–Seidel pass over swept_candidates_; the deepest correction (m).
    double separate_swept_pairs(Cloth& cloth, std::span<const Vec3> step_start,
                                std::size_t& close_pairs, SweepWatch* watch) const;
    // Moves b from a by `overlap` along n, shared by inverse mass (at least one is free),
    // and takes the approaching part of their relative velocity along n; checks both for
    // the `watch`, if any.
    static void push_apart(Cloth& cloth, std::uint32_t a, std::uint32_t b, const Vec3& n,
                           double overlap, SweepWatch* watch);
    // m: how far the list looks past the thickness. A wider margin lasts more steps but lists
    // more pairs: at 1.5 thicknesses the drapes' reach (2.5 × 0.75 spacing) stays inside
    // the nearest unjoined neighbours of a flat square grid (√5 spacings), which 2
    // thicknesses took in (14 000 listed pairs on the 64² drape against 60–280); 1.5 rebuilt
    // the list 70 times in the drape's first second, 1 thickness 109 times.
    double margin() const { return 1.5 * thickness_; }
    double reach() const { return thickness_ + margin(); }  // m: the list's radius
    // True when two particles may have come closer by more than the margin since the list
    // was built (or the list does not fit the cloth, or a position is not finite).
    bool moved_beyond_margin(const Cloth& cloth, WorkerPool* pool) const;
    // find_pairs, given whether the list outlived its margin when the caller measured it.
    void find_pairs(const Cloth& cloth, std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                    WorkerPool* pool, std::optional<bool> list_outlived);
    void rebuild_candidates(const Cloth& cloth, WorkerPool* pool);
    void rebuild_hash(const Cloth& cloth, WorkerPool* pool);
    static constexpr std::size_t search_chunks = 16;  // fixed: the split never shows
    void rebuild_joined_partners(const Cloth& cloth);
    // Rebuilds the partners when springs were torn or cut or the cloth changed size; true if so.
    bool refresh_joined_partners(const Cloth& cloth);
    bool joined(std::uint32_t a, std::uint32_t b) const;
    // Integer cell coordinate, clamped so that far-flung (but finite) particles cannot
    // overflow the conversion; cells that far out only ever hold the particles that flew there.
    static long long cell_coordinate(double position, double cell_size);
    // A cell's slot in a table of mask + 1 slots (a power of two).
    static std::size_t hash_cell(long long cx, long long cy, long long cz, std::size_t mask);

    double thickness_;
    std::size_t slot_mask_ = 0;                    // hash table size - 1 (a power of two)
    std::vector<std::array<long long, 3>> cells_;  // each particle's cell (x, y, z), reach wide
    std::vector<std::uint32_t> slots_;             // each particle's hash table slot
    std::vector<std::uint32_t> cell_start_;        // prefix sums over the hash table, size + 1
    std::vector<std::uint32_t> cell_entries_;      // particle indices sorted by cell
    // The live springs' ends, by particle: the partners of p are
    // joined_partners_[joined_start_[p] .. joined_start_[p + 1]).
    std::vector<std::uint32_t> joined_start_;
    std::vector<std::uint32_t> joined_partners_;
    std::vector<std::uint32_t> joined_fill_;  // where the next partner of each goes (building)
    std::size_t joined_spring_count_ = static_cast<std::size_t>(-1);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
    // The Verlet list: unjoined pairs closer than reach() at built_at_, ascending.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> candidates_;
    std::vector<Vec3> built_at_;  // m: the positions the list was built at
    std::size_t list_builds_ = 0;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found_by_chunk_;
    // The swept pass's: each particle's box of cells, its table of cells and its pairs.
    std::vector<std::array<long long, 3>> swept_low_, swept_high_;
    std::vector<std::uint32_t> swept_cell_start_;
    std::vector<std::uint32_t> swept_entries_;
    std::vector<std::uint32_t> swept_slots_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> swept_candidates_;
};

}  // namespace weft
