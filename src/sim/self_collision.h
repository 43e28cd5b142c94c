// Self-collision: particles closer than the cloth's thickness push apart, unless a spring
// joins them (neighbours are meant to be that close). Candidate pairs come from a spatial
// hash of cells one thickness wide (Teschner et al. 2003; Müller's Ten Minute Physics), so
// the cost stays linear in the number of particles. The pass keeps its tables between
// steps and allocates only when the cloth grows or its springs change (tearing, cutting),
// when the list of joined pairs is rebuilt — so it stays correct across tearing.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "sim/cloth.h"

namespace weft {

class SelfCollision {
  public:
    explicit SelfCollision(double thickness) : thickness_(thickness) {}

    double thickness() const { return thickness_; }  // m

    // Every pair (i < j) closer than the thickness and not joined by a spring, ascending.
    void find_pairs(const Cloth& cloth,
                    std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs);

    // Pushes each close pair apart to the thickness (half each, or all to the free one) and
    // removes their approaching relative normal velocity. Returns the pairs resolved.
    std::size_t resolve(Cloth& cloth);

  private:
    void rebuild_hash(const Cloth& cloth);
    void rebuild_joined_pairs(const Cloth& cloth);
    bool joined(std::uint32_t a, std::uint32_t b) const;
    std::size_t cell_of(const Vec3& x) const;
    std::size_t hash_cell(long long cx, long long cy, long long cz) const;

    double thickness_;
    std::vector<std::uint32_t> cell_start_;    // prefix sums over the hash table, size + 1
    std::vector<std::uint32_t> cell_entries_;  // particle indices sorted by cell
    std::vector<std::uint64_t> joined_pairs_;  // sorted edge keys of the live springs
    std::size_t joined_spring_count_ = static_cast<std::size_t>(-1);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
};

}  // namespace weft
