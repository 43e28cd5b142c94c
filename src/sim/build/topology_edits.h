// Edits of the cloth's topology: removing springs (tearing, the cut tool) together with the
// triangles they held, and pinning or freeing particles. Triangles are kept consistent with
// the springs here, in sim, so everything downstream (drawing, picking) sees intact cloth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sim/core/cloth.h"

namespace weft {

// The key of the undirected edge (a, b).
inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
    return a < b ? (static_cast<std::uint64_t>(a) << 32) | b
                 : (static_cast<std::uint64_t>(b) << 32) | a;
}

// After springs were removed: removes every triangle one of whose edges is in
// `removed_edges` (keys from edge_key; sorted here), and colours the springs anew.
void after_springs_removed(Cloth& cloth, std::vector<std::uint64_t>& removed_edges);

// Removes every spring for which `should_remove(spring)` is true, judging all of them on the
// current state before removing any, and then every triangle one of whose edges was a
// removed spring. Survivors keep their order. Returns the number of springs removed.
// A template so the per-spring test inlines: tearing runs this over every spring each step.
template <class Predicate>
std::size_t remove_springs_if(Cloth& cloth, Predicate should_remove) {
    // Judged on the topology as it is, shared or not: most steps remove nothing, and only a
    // step that does makes the cloth its own copy (Cloth::edit_topology). Removals are rare (a
    // few springs in a step that tears), so they go into small vectors; the common case of no
    // removal allocates nothing.
    std::vector<std::uint64_t> removed_edges;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> removed;  // (group, spring), in order
    const std::vector<SpringGroup>& groups = cloth.topology().spring_groups;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const std::vector<Spring>& springs = groups[g].springs;
        for (std::size_t s = 0; s < springs.size(); ++s) {
            if (!should_remove(springs[s])) continue;
            removed_edges.push_back(edge_key(springs[s].i, springs[s].j));
            removed.emplace_back(static_cast<std::uint32_t>(g), static_cast<std::uint32_t>(s));
        }
    }
    if (removed.empty()) return 0;
    std::vector<SpringGroup>& own = cloth.edit_topology().spring_groups;
    std::size_t next = 0;  // the first of `removed` not yet erased
    for (std::size_t g = 0; g < own.size(); ++g) {
        std::vector<Spring>& springs = own[g].springs;
        std::size_t kept = 0;
        for (std::size_t s = 0; s < springs.size(); ++s) {
            if (next < removed.size() && removed[next].first == g && removed[next].second == s) {
                ++next;
                continue;
            }
            springs[kept++] = springs[s];
        }
        springs.resize(kept);
    }
    after_springs_removed(cloth, removed_edges);
    return removed_edges.size();
}

// Switching a spring family off and on while the cloth runs (the demo's panel). Off moves
// the family's group out of the cloth, so it costs nothing in the force pass; it comes back
// as it was, tears included. `fresh` is the family as the builder makes it for the intact
// sheet: only its springs whose ends are still joined through a common structural neighbour
// are added, so a family switched on after tearing does not sew torn cloth together again
// (shear and bend springs both span two structural springs, in either layout).
std::optional<SpringGroup> take_spring_family(Cloth& cloth, SpringFamily family);
void add_spring_family(Cloth& cloth, SpringGroup fresh);  // group order: by family

// Pins (inverse mass 0, velocity 0) or frees (inverse mass 1/m) one particle.
void set_pinned(Cloth& cloth, std::size_t particle, bool pinned);

}  // namespace weft
