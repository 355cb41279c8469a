// SPDX-License-Identifier: MIT
#include "scene/nesting.hpp"

#include <cstdint>

#include "litkit/error.hpp"

namespace litkit::detail {

void check_nesting(std::string_view text, const std::string& name) {
    std::uint32_t line = 1;
    std::uint32_t column = 0;
    std::string open;       // '[' and '{' not yet closed, innermost last (at most the limit)
    int dots = 0;           // dots in the current key or header
    bool in_value = false;  // after '=' (or in an array) until the pair ends
    for (std::size_t at = 0; at < text.size(); ++at) {
        const char c = text[at];
        ++column;
        auto fail = [&] {
            throw IoError(name,
                          "nested deeper than " + std::to_string(max_toml_nesting) +
                              " levels (tables, arrays and dotted keys; docs/reliability.md)",
                          FileLoc{name, line, column});
        };
        auto newline = [&] {
            ++line;
            column = 0;
        };
        if (c == '\n') {
            newline();
            dots = 0;
            if (open.empty()) in_value = false;
            continue;
        }
        if (c == '#') {  // a comment, to the end of the line
            while (at + 1 < text.size() && text[at + 1] != '\n') ++at;
            continue;
        }
        if (c == '"' || c == '\'') {
            // Strings, one-line or multi-line ("""…""" and '''…'''), skipped;
            // only basic strings have escapes.
            const std::string_view triple = c == '"' ? "\"\"\"" : "'''";
            const bool multi = text.substr(at, 3) == triple;
            const std::string_view closing = multi ? triple : triple.substr(0, 1);
            const std::size_t quote_length = closing.size();
            at += quote_length;
            column += static_cast<std::uint32_t>(quote_length - 1);
            while (at < text.size()) {
                if (c == '"' && text[at] == '\\') {
                    at += 2;
                    column += 2;
                    continue;
                }
                if (text.substr(at, quote_length) == closing) {
                    at += quote_length - 1;
                    column += static_cast<std::uint32_t>(quote_length);
                    break;
                }
                if (text[at] == '\n') {
                    if (!multi) break;  // an unterminated string: toml++ reports it
                    newline();
                } else {
                    ++column;
                }
                ++at;
            }
            continue;
        }
        switch (c) {
            case '[':  // an array in a value, else a table header
            case '{':
                open += c;
                dots = 0;
                if (c == '{') in_value = false;  // keys follow
                break;
            case ']':
            case '}':
                if (!open.empty()) open.pop_back();
                dots = 0;
                in_value = !open.empty();
                break;
            case '=':
                in_value = true;
                dots = 0;
                break;
            case ',':  // in an inline table, a key follows; in an array, a value
                dots = 0;
                in_value = open.empty() || open.back() == '[';
                break;
            case '.':
                if (!in_value) ++dots;
                break;
            default:
                break;
        }
        if (static_cast<int>(open.size()) + dots > max_toml_nesting) fail();
    }
}

}  // namespace litkit::detail
