#include "sim/core/cloth.h"

#include <atomic>

#include "sim/scene/scene.h"

namespace weft {

const char* spring_family_name(SpringFamily family) {
    return spring_family_names[static_cast<std::size_t>(family)].data();
}

std::string particle_name(const Cloth& cloth, std::size_t p) {
    if (cloth.is_mesh()) return "vertex " + std::to_string(p + 1);
    const auto cols = static_cast<std::size_t>(std::max(cloth.cols, 1));
    return "particle (row " + std::to_string(p / cols) + ", col " + std::to_string(p % cols) + ")";
}

std::size_t ClothTopology::spring_count() const {
    std::size_t count = 0;
    for (const SpringGroup& group : spring_groups) count += group.springs.size();
    return count;
}

const SpringGroup* ClothTopology::find_group(SpringFamily family) const {
    for (const SpringGroup& group : spring_groups)
        if (group.family == family) return &group;
    return nullptr;
}

ClothTopology& Cloth::edit_topology() {
    // Versions come from one counter for every cloth, so no two topologies that ever
    // differed share one.
    static std::atomic<std::uint64_t> next_version{1};
    if (topology_.use_count() > 1) topology_ = std::make_shared<ClothTopology>(*topology_);
    topology_->version = next_version.fetch_add(1, std::memory_order_relaxed);
    return *topology_;
}

}  // namespace weft
