#include "sim/scene_io/toml_input_guard.h"

namespace weft {
namespace {

enum class Context { code, comment, basic, literal, multiline_basic, multiline_literal };

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

}  // namespace

std::optional<TextPosition> find_unsafe_non_ascii(std::string_view text) {
    Context context = Context::code;
    TextPosition position;
    // Inside a multi-line basic string, after a backslash that ends its line: the parser
    // trims the whitespace that follows, classifying each character.
    bool trimming = false;
    // The last significant character of code on this line. A quote opens a string only where
    // the parser expects a key or a value (line start, or after = [ , { .); anywhere else the
    // parser fails on the quote, and its error path classifies the characters after it.
    char last_code = '\n';
    auto opens_string = [&] {
        return last_code == '\n' || last_code == '=' || last_code == '[' || last_code == ',' ||
               last_code == '{' || last_code == '.';
    };
    // Where a value is read, a quote inside a bare token ("1.", "x{") is read on by the
    // parser's number scan, which classifies each character up to a value terminator (blank,
    // line end, , ] } #): there the quote opens no string. Keys are read segment by segment,
    // so a quote after a dot in a key does open one.
    bool in_key = true;           // before a line's key-value '=' outside any bracket
    bool in_value_token = false;  // inside a run of bare characters where a value is read
    int bracket_depth = 0;        // open [ and { in code
    auto ends_value_token = [](char c) {
        return is_blank(c) || c == '\n' || c == ',' || c == ']' || c == '}';
    };
    auto is_opener = [](char c) { return c == '=' || c == '[' || c == '{' || c == '.'; };
    auto at_token = [&](std::size_t at, std::string_view token) {
        return text.substr(at, token.size()) == token;
    };
    std::size_t skip = 0;  // bytes of a multi-byte token already accounted for
    for (std::size_t at = 0; at < text.size(); ++at) {
        const char c = text[at];
        const bool non_ascii = static_cast<unsigned char>(c) >= 0x80;
        if (skip > 0) {
            --skip;
        } else {
            switch (context) {
                case Context::code:
                    if (non_ascii) return position;
                    if (c == '#') {
                        context = Context::comment;
                    } else if ((c == '"' || c == '\'') && opens_string() &&
                               (in_key || !in_value_token)) {
                        const bool triple = at_token(at, c == '"' ? "\"\"\"" : "'''");
                        if (triple) skip = 2;
                        context = c == '"'
                                      ? (triple ? Context::multiline_basic : Context::basic)
                                      : (triple ? Context::multiline_literal : Context::literal);
                        last_code = 'v';  // after a string comes no value
                    } else {
                        if (c == '[' || c == '{') ++bracket_depth;
                        if ((c == ']' || c == '}') && bracket_depth > 0) --bracket_depth;
                        if (ends_value_token(c) || (c == '=' && in_key)) {
                            in_value_token = false;
                            if (c == '=') in_key = false;
                        } else if (!in_key && !is_opener(c)) {
                            in_value_token = true;
                        }
                        if (!is_blank(c) && c != '\n') last_code = c;
                    }
                    break;
                case Context::comment:
                    if (c == '\n') context = Context::code;
                    break;
                case Context::basic:
                    if (c == '\\' && at + 1 < text.size() && text[at + 1] != '\n')
                        skip = 1;  // an escape
                    else if (c == '"' || c == '\n')
                        context = Context::code;
                    break;
                case Context::literal:
                    if (c == '\'' || c == '\n') context = Context::code;
                    break;
                case Context::multiline_basic:
                    if (trimming) {
                        if (non_ascii) return position;
                        if (!is_blank(c) && c != '\n') trimming = false;
                    }
                    if (trimming) break;
                    if (c == '\\') {
                        std::size_t next = at + 1;
                        while (next < text.size() && is_blank(text[next])) ++next;
                        // The parser classifies the code point after the backslash, and
                        // after any blanks that follow it, as possible whitespace. A
                        // non-ASCII one there is an invalid escape in TOML anyway.
                        if (next < text.size() && static_cast<unsigned char>(text[next]) >= 0x80)
                            return TextPosition{position.line,
                                                position.column + static_cast<int>(next - at)};
                        if (next < text.size() && text[next] == '\n')
                            trimming = true;
                        else
                            skip = 1;  // an ordinary escape
                    } else if (at_token(at, "\"\"\"")) {
                        context = Context::code;
                        skip = 2;
                    }
                    break;
                case Context::multiline_literal:
                    if (at_token(at, "'''")) {
                        context = Context::code;
                        skip = 2;
                    }
                    break;
            }
        }
        if (c == '\n') {
            if (context == Context::code) {
                last_code = '\n';
                in_key = bracket_depth == 0;
                in_value_token = false;
            }
            ++position.line;
            position.column = 1;
        } else {
            ++position.column;
        }
    }
    return std::nullopt;
}

}  // namespace weft
