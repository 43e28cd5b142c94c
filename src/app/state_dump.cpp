#include "app/state_dump.h"

#include <cstdio>

namespace weft {

void write_state_csv(const Cloth& cloth, std::ostream& out) {
    out << "row,col,x,y,z,vx,vy,vz\n";
    char line[256];
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        const Vec3& x = cloth.positions[p];
        const Vec3& v = cloth.velocities[p];
        // %.17g round-trips every double exactly.
        std::snprintf(line, sizeof line, "%zu,%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                      p / cloth.cols, p % cloth.cols, x.x, x.y, x.z, v.x, v.y, v.z);
        out << line;
    }
}

}  // namespace weft
