// A guard in front of toml++ 3.3 (Debian 12's version). Its whitespace classifier reaches
// __builtin_unreachable() — undefined behaviour — for many non-ASCII code points where the
// parser expects whitespace: anywhere outside strings and comments, and at the start of a
// line after a line-ending backslash in a multi-line basic string (fixed upstream in 2026:
// github.com/marzer/tomlplusplus/issues/190 and /295). Found by weft's scene fuzzer.
//
// TOML 1.0 allows non-ASCII text only inside strings and comments, so refusing it elsewhere
// costs nothing valid except that one multi-line-string corner, which is refused with a
// message instead of risking undefined behaviour.
#pragma once

#include <optional>
#include <string_view>

namespace weft {

struct TextPosition {
    int line = 1;    // 1-based
    int column = 1;  // 1-based, in bytes
};

// The first non-ASCII byte the parser would classify as possible whitespace, or nothing.
std::optional<TextPosition> find_unsafe_non_ascii(std::string_view toml_text);

}  // namespace weft
