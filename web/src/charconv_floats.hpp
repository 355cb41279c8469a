// SPDX-License-Identifier: MIT
// std::to_chars and std::from_chars for float and double, which the C++
// library of Debian's emscripten (3.1.6, libc++ of LLVM 14) declares only for
// integers. The library's sources use them to print numbers in messages and
// explanations (shortest text that reads back as the same value) and to read
// OBJ numbers; web/CMakeLists.txt includes this header first in each of them,
// and only where <version> says the standard library lacks them. Same
// results as the C++17 functions: the shortest digits that read back as the
// same value, written fixed or scientific, whichever is shorter (fixed on a
// tie); reading takes what from_chars takes (no leading '+' or space, no hex).
#pragma once

#include <charconv>
#include <version>

#if !defined(__cpp_lib_to_chars)

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace litkit_web_compat {

template <class T>
T read_back(const char* text) {
    if constexpr (sizeof(T) == sizeof(float))
        return std::strtof(text, nullptr);
    else
        return std::strtod(text, nullptr);
}

// Shortest round-trip text of a finite non-zero `value` (no sign).
template <class T>
std::string shortest(T value) {
    constexpr int max_digits = sizeof(T) == sizeof(float) ? 9 : 17;
    char scientific[48];
    for (int digits = 1; digits <= max_digits; ++digits) {
        std::snprintf(scientific, sizeof scientific, "%.*e", digits - 1,
                      static_cast<double>(value));
        if (read_back<T>(scientific) == value) break;
    }
    // "d.ddde±xx" → the digits without the point, and the exponent.
    std::string mantissa;
    const char* e = std::strchr(scientific, 'e');
    for (const char* c = scientific; c != e; ++c)
        if (*c != '.') mantissa += *c;
    while (mantissa.size() > 1 && mantissa.back() == '0') mantissa.pop_back();
    const int exponent = std::atoi(e + 1);
    const int n = static_cast<int>(mantissa.size());

    std::string sci = mantissa.substr(0, 1);
    if (n > 1) sci += "." + mantissa.substr(1);
    char exp_text[8];
    std::snprintf(exp_text, sizeof exp_text, "e%c%02d", exponent < 0 ? '-' : '+',
                  exponent < 0 ? -exponent : exponent);
    sci += exp_text;

    std::string fixed;
    if (exponent >= 0) {
        if (n - 1 <= exponent)
            fixed = mantissa + std::string(static_cast<std::size_t>(exponent - (n - 1)), '0');
        else
            fixed = mantissa.substr(0, static_cast<std::size_t>(exponent + 1)) + "." +
                    mantissa.substr(static_cast<std::size_t>(exponent + 1));
    } else {
        fixed = "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + mantissa;
    }
    return fixed.size() <= sci.size() ? fixed : sci;
}

template <class T>
std::to_chars_result to_chars(char* first, char* last, T value) {
    std::string text;
    if (std::isnan(value)) {
        text = std::signbit(value) ? "-nan" : "nan";
    } else if (std::isinf(value)) {
        text = value < 0 ? "-inf" : "inf";
    } else if (value == 0) {
        text = std::signbit(value) ? "-0" : "0";
    } else {
        text = (value < 0 ? "-" : "") + shortest<T>(value < 0 ? -value : value);
    }
    if (text.size() > static_cast<std::size_t>(last - first))
        return {last, std::errc::value_too_large};
    std::memcpy(first, text.data(), text.size());
    return {first + text.size(), std::errc()};
}

template <class T>
std::from_chars_result from_chars(const char* first, const char* last, T& value) {
    // from_chars's pattern: an optional '-', then digits with an optional
    // point and exponent, or inf/infinity/nan; strtod would also take a '+',
    // spaces and hexadecimal, so those stop here.
    const char* p = first;
    if (p != last && *p == '-') ++p;
    if (p == last || *p == '+' || *p == ' ' || *p == '\t' || *p == '\n' || *p == '\r' ||
        *p == '\f' || *p == '\v')
        return {first, std::errc::invalid_argument};
    std::string text(first, last);
    if (last - p >= 2 && p[0] == '0' && (p[1] == 'x' || p[1] == 'X'))
        text.resize(static_cast<std::size_t>(p - first) + 1);  // "0x…" reads as 0
    errno = 0;
    char* end = nullptr;
    T result;
    if constexpr (sizeof(T) == sizeof(float))
        result = std::strtof(text.c_str(), &end);
    else
        result = std::strtod(text.c_str(), &end);
    if (end == text.c_str()) return {first, std::errc::invalid_argument};
    const char* stop = first + (end - text.c_str());
    if (errno == ERANGE) return {stop, std::errc::result_out_of_range};
    value = result;
    return {stop, std::errc()};
}

}  // namespace litkit_web_compat

namespace std {
inline to_chars_result to_chars(char* first, char* last, float value) {
    return litkit_web_compat::to_chars(first, last, value);
}
inline to_chars_result to_chars(char* first, char* last, double value) {
    return litkit_web_compat::to_chars(first, last, value);
}
inline from_chars_result from_chars(const char* first, const char* last, float& value) {
    return litkit_web_compat::from_chars(first, last, value);
}
inline from_chars_result from_chars(const char* first, const char* last, double& value) {
    return litkit_web_compat::from_chars(first, last, value);
}
}  // namespace std

#endif
