// SPDX-License-Identifier: MIT
// Words in messages: "did you mean" suggestions for misspelt keys and values,
// lists, articles. Used by the scene reader and the validator.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace litkit::detail {

std::string lower_case(std::string_view text);

// Levenshtein distance: insertions, deletions and substitutions.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate the user most likely meant by `word`, if any is close: the
// same word in another case ("Phong"), a known synonym ("refraction_index"
// for "ior"), a small typo ("positon", "half_lambert"), or the unique
// candidate `word` begins ("blinn").
std::optional<std::string_view> closest_word(std::string_view word,
                                             std::span<const std::string_view> candidates);

// "; did you mean 'phong'?", or "" when nothing is close.
std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates);

std::string join(std::span<const std::string_view> words, std::string_view separator);
bool contains(std::span<const std::string_view> words, std::string_view word);

// "a point light", "an ambient light", "an object type".
std::string with_article(std::string_view noun);

}  // namespace litkit::detail
