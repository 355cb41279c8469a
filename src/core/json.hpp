// SPDX-License-Identifier: MIT
// The one JSON writer of `litkit explain --json` (teach/explain_format.cpp)
// and the playground's answers (web/src/playground.cpp): strings and numbers
// as JSON text, which the callers join with their own punctuation.
//
// Numbers are the shortest text that reads back as the same value (a float
// as a float, a double as a double). JSON has no NaN or infinity, so a
// non-finite number is written `null`: every answer stays valid JSON, which
// any parser (Python's json, JavaScript's JSON.parse) reads.
#pragma once

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <type_traits>

namespace litkit::json {

// `text` as a JSON string, quoted: `"` and `\` escaped, and control
// characters as \u00XX. Other bytes (UTF-8 included) are copied as they are.
inline void append_string(std::string& out, std::string_view text) {
    static constexpr char hex[] = "0123456789abcdef";
    out += '"';
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (byte < 0x20) {
            out += "\\u00";
            out += hex[byte >> 4];
            out += hex[byte & 15];
        } else {
            out += c;
        }
    }
    out += '"';
}

inline std::string string(std::string_view text) {
    std::string out;
    append_string(out, text);
    return out;
}

// The shortest text that reads back as `value`; `null` where it is not finite.
template <class Number>
std::string number(Number value) {
    static_assert(std::is_floating_point_v<Number>);
    if (!std::isfinite(value)) return "null";
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : std::string("null");
}

}  // namespace litkit::json
