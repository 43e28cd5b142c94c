#include "sim/build/topology_edits.h"

#include <algorithm>

#include "sim/build/spring_coloring.h"

namespace weft {

void after_springs_removed(Cloth& cloth, std::vector<std::uint64_t>& removed_edges) {
    // Removal kept the order, but the colour boundaries moved; colouring again is cheap next
    // to the event that removed the springs.
    ClothTopology& topology = cloth.edit_topology();
    for (SpringGroup& group : topology.spring_groups) colour_springs(group, cloth.particle_count());
    build_grid_stencil(cloth);  // the removed springs become masked, dead stencil entries
    std::sort(removed_edges.begin(), removed_edges.end());
    auto removed = [&](std::uint32_t a, std::uint32_t b) {
        return std::binary_search(removed_edges.begin(), removed_edges.end(), edge_key(a, b));
    };
    std::erase_if(cloth.edit_topology().triangles, [&](const Triangle& t) {
        return removed(t.a, t.b) || removed(t.b, t.c) || removed(t.c, t.a);
    });
}

std::optional<SpringGroup> take_spring_family(Cloth& cloth, SpringFamily family) {
    auto& groups = cloth.edit_topology().spring_groups;
    auto at = std::find_if(groups.begin(), groups.end(),
                           [&](const SpringGroup& g) { return g.family == family; });
    if (at == groups.end()) return std::nullopt;
    SpringGroup taken = std::move(*at);
    groups.erase(at);
    build_grid_stencil(cloth);  // the structured pass must not read the family any more
    return taken;
}

void add_spring_family(Cloth& cloth, SpringGroup fresh) {
    if (const SpringGroup* structural = cloth.find_group(SpringFamily::structural);
        structural && fresh.family != SpringFamily::structural) {
        // Structural neighbours of every particle, then keep (i, j) if some neighbour k of i
        // has j as a neighbour too.
        std::vector<std::vector<std::uint32_t>> neighbours(cloth.particle_count());
        for (const Spring& s : structural->springs) {
            neighbours[s.i].push_back(s.j);
            neighbours[s.j].push_back(s.i);
        }
        auto joined_through_one = [&](std::uint32_t i, std::uint32_t j) {
            for (std::uint32_t k : neighbours[i]) {
                const auto& of_k = neighbours[k];
                if (std::find(of_k.begin(), of_k.end(), j) != of_k.end()) return true;
            }
            return false;
        };
        std::erase_if(fresh.springs,
                      [&](const Spring& s) { return !joined_through_one(s.i, s.j); });
    }
    colour_springs(fresh, cloth.particle_count());
    auto& groups = cloth.edit_topology().spring_groups;
    auto at = std::find_if(groups.begin(), groups.end(),
                           [&](const SpringGroup& g) { return g.family > fresh.family; });
    groups.insert(at, std::move(fresh));
    build_grid_stencil(cloth);
}

void set_pinned(Cloth& cloth, std::size_t particle, bool pinned) {
    if (pinned) cloth.velocities[particle] = Vec3(0.0);
    if (cloth.is_pinned(particle) == pinned) return;  // nothing to change: no new version
    ClothTopology& topology = cloth.edit_topology();
    topology.inverse_masses[particle] = pinned ? 0.0 : 1.0 / topology.masses[particle];
    const auto index = static_cast<std::uint32_t>(particle);
    auto at = std::lower_bound(topology.pinned.begin(), topology.pinned.end(), index);
    const bool listed = at != topology.pinned.end() && *at == index;
    if (pinned && !listed) topology.pinned.insert(at, index);
    if (!pinned && listed) topology.pinned.erase(at);
}

}  // namespace weft
