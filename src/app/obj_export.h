// The cloth as it is now, as Wavefront OBJ, for a modeller (Blender) or weft's own reader:
// one `v` line per particle in the --dump file's order (metres, at full double precision, so
// the numbers are the dump's), then one `f` line per triangle still intact, counter-clockwise
// seen from the front, vertices counted from 1. A tear or a cut removes the triangles along
// it, so the pieces come out apart; particles left in no triangle stay as `v` lines, so the
// numbering always matches the dump.
#pragma once

#include <ostream>
#include <string>

#include "sim/core/cloth.h"

namespace weft::app {

void write_cloth_obj(const Cloth& cloth, const std::string& name, std::ostream& out);

}  // namespace weft::app
