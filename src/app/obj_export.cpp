#include "app/obj_export.h"

#include <cstdio>

namespace weft::app {
namespace {

// An OBJ name is one token on its line: anything but visible ASCII becomes '_'.
std::string obj_name(const std::string& name) {
    std::string token = name.empty() ? std::string("cloth") : name;
    for (char& c : token)
        if (c <= ' ' || c > '~') c = '_';
    return token;
}

}  // namespace

void write_cloth_obj(const Cloth& cloth, const std::string& name, std::ostream& out) {
    out << "# weft: " << cloth.particle_count() << " particles, "
        << cloth.topology().triangles.size() << " triangles\n";
    out << "o " << obj_name(name) << "\n";
    char line[160];
    for (const Vec3& x : cloth.positions) {
        // %.17g round-trips every double exactly, as in the dump.
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", x.x, x.y, x.z);
        out << line;
    }
    for (const Triangle& t : cloth.topology().triangles) {
        std::snprintf(line, sizeof line, "f %u %u %u\n", t.a + 1, t.b + 1, t.c + 1);
        out << line;
    }
}

}  // namespace weft::app
