// Scene writing: a Scene as the TOML text the loader reads back to the same Scene, every
// number to the last bit. The demo saves its current parameters through this, and sessions
// record their scene with it. (The panel's live edits are typed edits, checked by the same
// rules as a scene file's values: scene_edit.h, scene_rules.h.)
#pragma once

#include <string>

#include "sim/scene/scene.h"

namespace weft {

// Every key of the format, defaults included, so a saved scene does not depend on defaults
// that a later version might change. Doubles are written with 17 significant digits.
std::string scene_to_toml(const Scene& scene);

// `value` as a TOML float that reads back to the same double: %.17g, with ".0" added where it
// would otherwise read as an integer.
std::string toml_number(double value);

// `text` as a TOML basic string: quoted, with quotes, backslashes and control characters
// escaped (for other files weft writes in TOML, such as session recordings).
std::string toml_string(const std::string& text);

}  // namespace weft
