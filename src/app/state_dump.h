// The --dump file: one line per particle, row-major, after the header
// `row,col,x,y,z,vx,vy,vz` (metres and metres per second, full double precision).
#pragma once

#include <ostream>

#include "sim/core/cloth.h"

namespace weft {

void write_state_csv(const Cloth& cloth, std::ostream& out);

}  // namespace weft
