// SPDX-License-Identifier: MIT
// What the PLY and STL readers share: words of a text file with their
// line and column, numbers read exactly (std::from_chars: no locale, so a
// decimal comma is never a point), and little- or big-endian values of a
// binary file, each read with the byte offset where it stands.
#pragma once

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>

#include "litkit/error.hpp"

namespace litkit::detail {

// One whitespace-separated word and where it starts (1-based).
struct MeshWord {
    std::string_view text;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
};

// The words of a text, in order; `next_word` is empty at the end.
class MeshWords {
  public:
    explicit MeshWords(std::string_view text) : text_(text) {}
    // The words from `offset` on, which is at the start of line `line`.
    MeshWords(std::string_view text, std::size_t offset, std::uint32_t line)
        : text_(text), at_(offset), line_start_(offset), line_(line) {}

    MeshWord next_word() {
        skip_space();
        const std::size_t start = at_;
        const std::uint32_t column = static_cast<std::uint32_t>(start - line_start_ + 1);
        while (at_ < text_.size() && !is_space(text_[at_])) ++at_;
        return {text_.substr(start, at_ - start), line_, column};
    }
    // The words left on the current line (after the last word read).
    bool line_has_more() {
        while (at_ < text_.size() && text_[at_] != '\n' && is_space(text_[at_])) ++at_;
        return at_ < text_.size() && text_[at_] != '\n';
    }
    // Where the next word would start: for "missing" errors at the end.
    MeshWord here() {
        skip_space();
        return {{}, line_, static_cast<std::uint32_t>(at_ - line_start_ + 1)};
    }
    std::size_t offset() const { return at_; }

  private:
    static bool is_space(char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
    }
    void skip_space() {
        while (at_ < text_.size() && is_space(text_[at_])) {
            if (text_[at_] == '\n') {
                ++line_;
                line_start_ = at_ + 1;
            }
            ++at_;
        }
    }

    std::string_view text_;
    std::size_t at_ = 0;
    std::size_t line_start_ = 0;
    std::uint32_t line_ = 1;
};

// The whole word as a finite double; the reason it is not one otherwise
// ("is not a number", "is not a finite number"), empty on success.
inline std::string read_finite(std::string_view word, double& value) {
    std::string_view digits = word;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end != digits.data() + digits.size() || digits.empty()) {
        return word.find(',') != std::string_view::npos
                   ? "is not a number (write the decimal separator as a point: '.')"
                   : "is not a number";
    }
    if (error == std::errc::result_out_of_range)
        return "is beyond the range of numbers litkit reads";
    if (error != std::errc() || !std::isfinite(value)) return "is not a finite number";
    if (!std::isfinite(static_cast<float>(value)))
        return "is beyond the range of numbers litkit reads";
    return {};
}

// A word shown in a message: quoted, cut short, control bytes as '?'.
inline std::string quoted_word(std::string_view word) {
    std::string text = "'";
    for (std::size_t i = 0; i < word.size() && i < 40; ++i) {
        const unsigned char c = static_cast<unsigned char>(word[i]);
        text += c < 0x20 || c == 0x7f ? '?' : static_cast<char>(c);
    }
    return text + (word.size() > 40 ? "…'" : "'");
}

// Bytes of a binary file read as numbers of either byte order.
struct BinaryBytes {
    std::string_view bytes;
    bool big_endian = false;

    template <typename T>
    T read(std::size_t offset) const {
        unsigned char raw[sizeof(T)];
        std::memcpy(raw, bytes.data() + offset, sizeof(T));
        if (big_endian != (std::endian::native == std::endian::big)) {
            for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
                std::swap(raw[i], raw[sizeof(T) - 1 - i]);
        }
        T value;
        std::memcpy(&value, raw, sizeof(T));
        return value;
    }
};

// "byte N" for a message about a binary file.
inline std::string at_byte(std::size_t offset) { return " (byte " + std::to_string(offset) + ")"; }

}  // namespace litkit::detail
