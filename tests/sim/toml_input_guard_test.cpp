// The guard in front of toml++ 3.3's undefined behaviour on non-ASCII input (see
// toml_input_guard.h): inputs the fuzzer found are refused with a position; non-ASCII text
// where TOML allows it (strings, comments) still loads.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "sim/scene_io/scene_loader.h"
#include "sim/scene_io/toml_input_guard.h"

namespace weft {
namespace {

std::string read_file(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

TEST(TomlInputGuard, RefusesNonAsciiWhereTheParserWouldClassifyIt) {
    auto unsafe = find_unsafe_non_ascii("rows = 6\xc3\x97\n");  // "6×"
    ASSERT_TRUE(unsafe.has_value());
    EXPECT_EQ(unsafe->line, 1);
    EXPECT_EQ(unsafe->column, 9);
    // A quote the parser does not take as a string start (right after a number).
    EXPECT_TRUE(find_unsafe_non_ascii("a = 0\"x\xcb\x9a\"\n").has_value());
    // A quote inside a bare token where a value is read: the parser's number scan reads on
    // through it to a blank, , ] } or #, on any line of an array.
    EXPECT_TRUE(find_unsafe_non_ascii("a = 1.\"\xc3\xa9\"\n").has_value());
    EXPECT_TRUE(find_unsafe_non_ascii("a=1{'\xc3\xa9'\n").has_value());
    EXPECT_TRUE(find_unsafe_non_ascii("a = [\n1.=\"\xc3\xa9\"]\n").has_value());
    // The first character after a line-ending backslash in a multi-line basic string.
    EXPECT_TRUE(find_unsafe_non_ascii("s = \"\"\"\\\n\xc2\xa7\"\"\"\n").has_value());
    // The character after an escaping backslash in a multi-line basic string, and after the
    // blanks that follow one: the parser asks whether it is whitespace.
    unsafe = find_unsafe_non_ascii("s = \"\"\"a\\\xef\xbb\xbf\"\"\"\n");  // "\" then U+FEFF
    ASSERT_TRUE(unsafe.has_value());
    EXPECT_EQ(unsafe->column, 10);
    EXPECT_TRUE(find_unsafe_non_ascii("s = \"\"\"\\  \xe3\x80\x80\n\"\"\"\n").has_value());
    // A stray byte of broken UTF-8 at the top level.
    EXPECT_TRUE(find_unsafe_non_ascii("\xcc\xaa").has_value());
}

TEST(TomlInputGuard, AcceptsNonAsciiInStringsAndComments) {
    EXPECT_FALSE(find_unsafe_non_ascii("name = \"Drap\xc3\xa9\"  # N\xc2\xb7s/m\n").has_value());
    EXPECT_FALSE(
        find_unsafe_non_ascii("name = 'caf\xc3\xa9'\ns = \"\"\"\n\xc2\xa7\"\"\"\n").has_value());
    EXPECT_FALSE(find_unsafe_non_ascii("a = [\"\xc3\xa9\", '\xc3\xa9']\n").has_value());
    EXPECT_FALSE(
        find_unsafe_non_ascii("a=[1,\n\"\xc3\xa9\"]\nb = { c = '\xc3\xa9' }\n").has_value());
    EXPECT_FALSE(find_unsafe_non_ascii("[t.\"\xc3\xa9\"]\nx.\"\xc3\xa9\" = 1\n").has_value());
    SceneLoadResult loaded =
        load_scene_text("name = \"Drap\xc3\xa9\"  # 25\xc3\x97 stiffer\n", "t.toml");
    ASSERT_TRUE(loaded.ok()) << loaded.error->message();
    EXPECT_EQ(loaded.scene->name, "Drap\xc3\xa9");
}

TEST(TomlInputGuard, FuzzerFindingsAreRefusedWithAPosition) {
    for (const char* name :
         {"toml-unreachable-value.toml", "toml-unreachable-after-number.toml",
          "toml-unreachable-after-escape.toml", "toml-unreachable-quote-inside-a-number.toml"}) {
        const std::string path = std::string(WEFT_SOURCE_DIR "/fuzz/regressions/") + name;
        SceneLoadResult loaded = load_scene_text(read_file(path), "fuzz.toml");
        ASSERT_FALSE(loaded.ok()) << name;
        EXPECT_NE(loaded.error->what.find("non-ASCII"), std::string::npos)
            << loaded.error->message();
        EXPECT_EQ(loaded.error->where.rfind("fuzz.toml:", 0), 0u) << loaded.error->where;
    }
}

}  // namespace
}  // namespace weft
