#include "sim/topology_edits.h"

#include <algorithm>

#include "sim/spring_coloring.h"

namespace weft {

void after_springs_removed(Cloth& cloth, std::vector<std::uint64_t>& removed_edges) {
    // Removal kept the order, but the colour boundaries moved; colouring again is cheap next
    // to the event that removed the springs.
    for (SpringGroup& group : cloth.spring_groups) colour_springs(group, cloth.particle_count());
    build_grid_stencil(cloth);  // the removed springs become masked, dead stencil entries
    std::sort(removed_edges.begin(), removed_edges.end());
    auto removed = [&](std::uint32_t a, std::uint32_t b) {
        return std::binary_search(removed_edges.begin(), removed_edges.end(), edge_key(a, b));
    };
    std::erase_if(cloth.triangles, [&](const Triangle& t) {
        return removed(t.a, t.b) || removed(t.b, t.c) || removed(t.c, t.a);
    });
}

void set_pinned(Cloth& cloth, std::size_t particle, bool pinned) {
    cloth.inverse_masses[particle] = pinned ? 0.0 : 1.0 / cloth.masses[particle];
    if (pinned) cloth.velocities[particle] = Vec3(0.0);
    const auto index = static_cast<std::uint32_t>(particle);
    auto at = std::lower_bound(cloth.pinned.begin(), cloth.pinned.end(), index);
    const bool listed = at != cloth.pinned.end() && *at == index;
    if (pinned && !listed) cloth.pinned.insert(at, index);
    if (!pinned && listed) cloth.pinned.erase(at);
}

}  // namespace weft
