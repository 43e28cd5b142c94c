#include "sim/cloth.h"

namespace weft {

const char* spring_family_name(SpringFamily family) {
    switch (family) {
        case SpringFamily::structural:
            return "structural";
        case SpringFamily::shear:
            return "shear";
        case SpringFamily::bend:
            return "bend";
    }
    return "unknown";
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
