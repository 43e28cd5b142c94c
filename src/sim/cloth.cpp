#include "sim/cloth.h"

#include "sim/scene.h"

namespace weft {

const char* spring_family_name(SpringFamily family) {
    return spring_family_names[static_cast<std::size_t>(family)].data();
}

std::string particle_name(const Cloth& cloth, std::size_t p) {
    if (cloth.is_mesh()) return "vertex " + std::to_string(p + 1);
    const auto cols = static_cast<std::size_t>(std::max(cloth.cols, 1));
    return "particle (row " + std::to_string(p / cols) + ", col " + std::to_string(p % cols) + ")";
}

std::size_t Cloth::spring_count() const {
    std::size_t count = 0;
    for (const SpringGroup& group : spring_groups) count += group.springs.size();
    return count;
}

const SpringGroup* Cloth::find_group(SpringFamily family) const {
    for (const SpringGroup& group : spring_groups)
        if (group.family == family) return &group;
    return nullptr;
}

}  // namespace weft
