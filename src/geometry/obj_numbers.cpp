// SPDX-License-Identifier: MIT
#include "geometry/obj_numbers.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "litkit/error.hpp"

namespace litkit::detail {

namespace {

struct Word {
    std::string_view text;
    std::uint32_t column;  // 1-based
};

std::vector<Word> words_of(std::string_view line) {
    std::vector<Word> words;
    std::size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '\r')) ++at;
        const std::size_t start = at;
        while (at < line.size() && line[at] != ' ' && line[at] != '\t' && line[at] != '\r') ++at;
        if (at > start)
            words.push_back(
                {line.substr(start, at - start), static_cast<std::uint32_t>(start + 1)});
    }
    return words;
}

// The whole word as a number, or nothing (std::from_chars: no locale, so a
// decimal comma is never read as a point).
// `out_of_range`: a number, but beyond what a double holds (1e999, 1e-999).
bool read_number(std::string_view word, double& value, bool& out_of_range) {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    out_of_range = error == std::errc::result_out_of_range && end == word.data() + word.size();
    return error == std::errc() && end == word.data() + word.size();
}

bool read_integer(std::string_view word, long long& value) {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    return error == std::errc() && end == word.data() + word.size();
}

// Whether tinyobjloader's number reader (tryParseDouble) would overflow an
// int on `word`'s exponent: its guard lets 214748364 · 10 + 8 and + 9
// through, undefined behaviour (found by fuzz_obj). Its grammar, followed
// as it reads: [sign] (digits [. [digits]] | . [digits]) (e | E) [sign]
// digits.
bool exponent_overflows_reader(std::string_view word) {
    const auto digit = [&](std::size_t i) {
        return i < word.size() && word[i] >= '0' && word[i] <= '9';
    };
    std::size_t i = 0;
    if (i < word.size() && (word[i] == '+' || word[i] == '-')) ++i;
    if (!(i < word.size() && word[i] == '.')) {
        const std::size_t start = i;
        while (digit(i)) ++i;
        if (i == start) return false;
    }
    if (i < word.size() && word[i] == '.')
        for (++i; digit(i); ++i) {
        }
    if (!(i < word.size() && (word[i] == 'e' || word[i] == 'E'))) return false;
    ++i;
    if (i < word.size() && (word[i] == '+' || word[i] == '-')) ++i;
    while (i < word.size() && word[i] == '0') ++i;
    const std::string_view exponent = word.substr(i);
    return exponent.size() >= 10 && exponent.starts_with("214748364") && digit(i + 9) &&
           word[i + 9] >= '8';
}

// Beyond a float's range (what tinyobjloader stores every real as).
bool beyond_float(double value) {
    return std::isfinite(value) && std::abs(value) > std::numeric_limits<float>::max();
}

// The number tinyobjloader's reader (tryParseDouble) makes of `word`, by
// the same steps and the same arithmetic, which are not std::from_chars':
// the digits summed in a double (fractional ones times 10^-k), then
// mantissa · 5^e, scaled by 2^e. A zero mantissa with an exponent of 442
// or more is thus 0 · ∞, NaN, where from_chars reads 0 (found by fuzz_obj:
// "vw 0 1 in) 00e7066", a NaN joint made an int). Like the reader, it
// takes the longest number at the word's start and ignores the rest
// ("1x" is 1). False where the reader finds no number (it then stores its
// default) or its exponent overflows (exponent_overflows_reader).
bool reader_value(std::string_view word, double& value) {
    const std::size_t n = word.size();
    const auto digit = [&](std::size_t k) { return k < n && word[k] >= '0' && word[k] <= '9'; };
    std::size_t i = 0;
    bool negative = false;
    if (n > 0 && (word[0] == '+' || word[0] == '-')) {
        negative = word[0] == '-';
        ++i;
    } else if (!(digit(0) || (n > 0 && word[0] == '.'))) {
        return false;
    }
    double mantissa = 0.0;
    if (!(i < n && word[i] == '.')) {
        const std::size_t start = i;
        for (; digit(i); ++i) mantissa = mantissa * 10 + (word[i] - '0');
        if (i == start) return false;
    }
    long long exponent = 0;
    if (i < n && word[i] == '.') {
        static constexpr double tenths[] = {1.0,    0.1,     0.01,     0.001,
                                            0.0001, 0.00001, 0.000001, 0.0000001};
        ++i;
        for (int k = 1; digit(i); ++k, ++i)
            mantissa += (word[i] - '0') * (k < 8 ? tenths[k] : std::pow(10.0, -k));
    }
    if (i < n && (word[i] == 'e' || word[i] == 'E')) {
        ++i;
        bool exponent_negative = false;
        if (i < n && (word[i] == '+' || word[i] == '-'))
            exponent_negative = word[i++] == '-';
        else if (!digit(i))
            return false;
        const std::size_t start = i;
        for (; digit(i); ++i) {
            if (exponent > 214748364) return false;  // the reader's own guard: no number
            exponent = exponent * 10 + (word[i] - '0');
        }
        if (i == start || exponent > std::numeric_limits<int>::max()) return false;
        if (exponent_negative) exponent = -exponent;
    }
    const int e = static_cast<int>(exponent);
    value = (negative ? -1 : 1) * (e ? std::ldexp(mantissa * std::pow(5.0, e), e) : mantissa);
    return true;
}

// Whether tinyobjloader stores what it reads of `word` as a finite float:
// not NaN, not infinite, not beyond a float's range (undefined behaviour
// by the letter). A word it reads no number from is safe (its default).
bool reader_finite_float(std::string_view word) {
    double value = 0;
    return !reader_value(word, value) || (std::isfinite(value) && !beyond_float(value));
}

// A word tinyobjloader reads as a real that it cannot read safely: an
// exponent that overflows its reader, or a finite number beyond a float's
// range, as std::from_chars or as the reader reads it. (Not a number at
// all: it reads its default, safely; NaN and infinity, which a weight or a
// tag may become, are floats too, and litkit uses neither.)
bool beyond_reader(std::string_view word) {
    double value = 0, read = 0;
    bool out_of_range = false;
    if (exponent_overflows_reader(word)) return true;
    if (reader_value(word, read) && beyond_float(read)) return true;
    const bool number = read_number(word, value, out_of_range);
    return out_of_range || (number && beyond_float(value));
}

struct Counts {
    long long vertices = 0;
    long long texture_coordinates = 0;
    long long normals = 0;
};

}  // namespace

void check_obj_numbers(std::string_view text, const std::string& name) {
    // Positive face indices may refer to any vertex of the file; negative
    // ones count back from the last vertex read so far.
    Counts total;
    for (std::size_t at = 0; at < text.size();) {
        const std::string_view line = next_obj_line(text, at);
        std::size_t first = line.find_first_not_of(" \t");
        if (first != std::string_view::npos) {
            const std::string_view rest = line.substr(first);
            if (rest.starts_with("v ") || rest.starts_with("v\t")) ++total.vertices;
            if (rest.starts_with("vt ") || rest.starts_with("vt\t")) ++total.texture_coordinates;
            if (rest.starts_with("vn ") || rest.starts_with("vn\t")) ++total.normals;
        }
    }

    Counts seen;
    std::uint32_t line_number = 0;
    std::size_t face_number = 0;
    for (std::size_t at = 0; at < text.size();) {
        const std::string_view line = next_obj_line(text, at);
        ++line_number;
        const std::vector<Word> words = words_of(line);
        if (words.empty()) continue;
        auto fail = [&](std::uint32_t column, const std::string& reason) {
            throw IoError(name, reason, FileLoc{name, line_number, column});
        };
        const std::string_view keyword = words[0].text;
        auto check_coordinates = [&](const char* what, std::size_t needed, std::size_t checked) {
            static const char* const axes[] = {"x", "y", "z", "w", "", ""};
            if (words.size() - 1 < needed)
                fail(words.back().column + static_cast<std::uint32_t>(words.back().text.size()),
                     std::string(what) + " needs " + std::to_string(needed) + " coordinate" +
                         (needed == 1 ? "" : "s") + ", found " + std::to_string(words.size() - 1));
            for (std::size_t i = 1; i < words.size() && i <= checked; ++i) {
                double value = 0;
                const std::string word(words[i].text);
                const std::string axis =
                    i - 1 < 4 && *axes[i - 1] ? std::string(" ") + axes[i - 1] : "";
                bool out_of_range = false;
                if (exponent_overflows_reader(words[i].text) ||
                    (!read_number(words[i].text, value, out_of_range) && out_of_range)) {
                    fail(words[i].column, std::string(what) + axis + " coordinate '" + word +
                                              "' is beyond the range of numbers litkit reads");
                }
                if (!out_of_range && !read_number(words[i].text, value, out_of_range)) {
                    fail(words[i].column,
                         std::string(what) + axis + " coordinate '" + word + "' is not a number" +
                             (word.find(',') != std::string::npos
                                  ? " (write the decimal separator as a point: '.')"
                                  : ""));
                }
                if (!std::isfinite(value))
                    fail(words[i].column, std::string(what) + axis + " coordinate '" + word +
                                              "' is not a finite number");
                // Stored as a float: a double beyond its range has no float
                // to round to (undefined, not infinity, by the letter); and
                // what the reader makes of it must be that number too.
                if (beyond_float(value) || !reader_finite_float(words[i].text))
                    fail(words[i].column, std::string(what) + axis + " coordinate '" + word +
                                              "' is beyond the range of numbers litkit reads");
            }
        };
        if (keyword == "v") {
            // x y z, an optional w or an r g b colour (tinyobjloader's extension).
            check_coordinates("vertex", 3, 6);
            ++seen.vertices;
        } else if (keyword == "vn") {
            check_coordinates("normal", 3, 3);
            ++seen.normals;
        } else if (keyword == "vt") {
            check_coordinates("texture coordinate", 1, 3);
            ++seen.texture_coordinates;
        } else if (keyword == "vw") {
            // tinyobjloader's skin weights, "vw v j0 w0 j1 w1 ...": litkit
            // uses none, but the parser turns each joint j into an int
            // unchecked (undefined beyond an int's range; found by fuzz_obj).
            long long vertex = 0;
            if (words.size() < 2)
                fail(words[0].column + 2, "vertex weight needs a vertex number, found none");
            if (!read_integer(words[1].text, vertex) || vertex < 0 || vertex > 2147483647)
                fail(words[1].column, "vertex weight's vertex '" + std::string(words[1].text) +
                                          "' is not a vertex number (0 to 2147483647)");
            for (std::size_t i = 2; i < words.size(); i += 2) {
                double joint = 0;
                bool out_of_range = false;
                // Read as a double, stored as a float, made an int: the
                // float must be below 2^31 (2147483600 rounds up to it),
                // as read by std::from_chars and by the reader itself.
                double read = 0;
                const auto joint_number = [](double j) {
                    return j >= 0.0 && j <= 2147483647.0 && static_cast<float>(j) < 2147483648.0f;
                };
                if (exponent_overflows_reader(words[i].text) ||
                    !read_number(words[i].text, joint, out_of_range) || !joint_number(joint) ||
                    (reader_value(words[i].text, read) && !joint_number(read)))
                    fail(words[i].column, "vertex weight's joint '" + std::string(words[i].text) +
                                              "' is not a joint number (0 to 2147483520)");
                if (i + 1 < words.size() && beyond_reader(words[i + 1].text))
                    fail(words[i + 1].column, "vertex weight's weight '" +
                                                  std::string(words[i + 1].text) +
                                                  "' is beyond the range of numbers litkit reads");
            }
        } else if (keyword == "t") {
            // Tags ("t name ints/reals/strings", then the values): litkit
            // uses none, but the parser reads their reals too. Any value
            // that reads as a number is held to the reals' range.
            for (std::size_t i = 3; i < words.size(); ++i)
                if (beyond_reader(words[i].text))
                    fail(words[i].column, "tag value '" + std::string(words[i].text) +
                                              "' is beyond the range of numbers litkit reads");
        } else if (keyword == "f") {
            if (words.size() >= 4) ++face_number;
            for (std::size_t i = 1; i < words.size(); ++i) {
                // v, v/vt, v//vn or v/vt/vn
                std::string_view corner = words[i].text;
                std::uint32_t column = words[i].column;
                const char* const kinds[] = {"vertex", "texture coordinate", "normal"};
                const char* const plurals[] = {"vertices", "texture coordinates", "normals"};
                const long long defined[] = {total.vertices, total.texture_coordinates,
                                             total.normals};
                const long long before[] = {seen.vertices, seen.texture_coordinates, seen.normals};
                for (int part = 0; part < 3; ++part) {
                    const std::size_t slash = corner.find('/');
                    const std::string_view index_text = corner.substr(0, slash);
                    if (!index_text.empty() || part == 0) {
                        long long index = 0;
                        if (!read_integer(index_text, index) || index == 0)
                            fail(column, "face corner '" + std::string(words[i].text) + "': '" +
                                             std::string(index_text) + "' is not a " + kinds[part] +
                                             " number (1, 2, … or -1, -2, …)");
                        const bool in_range =
                            index > 0 ? index <= defined[part] : index >= -before[part];
                        if (!in_range) {
                            const std::string face = words.size() >= 4
                                                         ? "face " + std::to_string(face_number)
                                                         : std::string("face");
                            fail(column,
                                 face + " refers to " + kinds[part] + " " + std::to_string(index) +
                                     ", but the file defines " +
                                     std::to_string(index > 0 ? defined[part] : before[part]) +
                                     " " + plurals[part] + (index < 0 ? " before it" : ""));
                        }
                    }
                    if (slash == std::string_view::npos) break;
                    column += static_cast<std::uint32_t>(slash + 1);
                    corner.remove_prefix(slash + 1);
                }
            }
        }
    }
}

std::string_view next_obj_line(std::string_view text, std::size_t& at) {
    const std::size_t start = at;
    std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = text.size();
    at = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
    return text.substr(start, end - start);
}

}  // namespace litkit::detail
