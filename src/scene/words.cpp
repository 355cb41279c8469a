// SPDX-License-Identifier: MIT
#include "scene/words.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace litkit::detail {

std::string lower_case(std::string_view text) {
    std::string result(text);
    for (char& c : result)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return result;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> previous(b.size() + 1);
    std::vector<std::size_t> current(b.size() + 1);
    std::iota(previous.begin(), previous.end(), std::size_t{0});
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

namespace {

// Other names users give a key (from other renderers and the literature),
// which no spelling distance connects with litkit's.
constexpr std::pair<std::string_view, std::string_view> synonyms[] = {
    {"refraction_index", "ior"},
    {"refractive_index", "ior"},
    {"index_of_refraction", "ior"},
    {"transparency", "transmission"},
    {"max_bounces", "max_depth"},
    {"max_recursion_depth", "max_depth"},
    {"antialias", "samples"},
    {"antialiasing", "samples"},
    {"msaa", "samples"},
    {"spp", "samples"},
};

}  // namespace

std::optional<std::string_view> closest_word(std::string_view word,
                                             std::span<const std::string_view> candidates) {
    const std::string folded = lower_case(word);
    for (const auto& [synonym, meant] : synonyms) {
        if (folded != synonym) continue;
        for (std::string_view candidate : candidates)
            if (candidate == meant) return candidate;
    }
    std::optional<std::string_view> best;
    std::size_t best_distance = std::numeric_limits<std::size_t>::max();
    for (std::string_view candidate : candidates) {
        std::size_t distance = edit_distance(folded, candidate);
        if (distance < best_distance) {
            best = candidate;
            best_distance = distance;
        }
    }
    if (best && best_distance == 0) return best;  // only the case differs

    // The unique candidate the word begins ("blinn" → "blinn-phong", "cook"
    // → "cook-torrance", even where another name is a small edit away), or
    // the unique one it starts with ("spotlight" → "spot").
    const auto unique_match = [&](auto matches) -> std::optional<std::string_view> {
        std::optional<std::string_view> found;
        int count = 0;
        for (std::string_view candidate : candidates) {
            if (folded.size() >= 3 && matches(candidate)) {
                found = candidate;
                ++count;
            }
        }
        return count == 1 ? found : std::nullopt;
    };
    if (auto completion =
            unique_match([&](std::string_view candidate) { return candidate.starts_with(folded); }))
        return completion;

    const std::size_t allowed = folded.size() <= 3 ? 1 : 2;
    if (best && best_distance <= allowed && best_distance < folded.size()) return best;

    return unique_match([&](std::string_view candidate) {
        return candidate.size() >= 3 && std::string_view(folded).starts_with(candidate);
    });
}

std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates) {
    auto match = closest_word(word, candidates);
    return match ? "; did you mean '" + std::string(*match) + "'?" : std::string();
}

std::string join(std::span<const std::string_view> words, std::string_view separator) {
    std::string text;
    for (std::string_view word : words) {
        if (!text.empty()) text += separator;
        text += word;
    }
    return text;
}

bool contains(std::span<const std::string_view> words, std::string_view word) {
    return std::find(words.begin(), words.end(), word) != words.end();
}

std::string with_article(std::string_view noun) {
    const bool vowel = !noun.empty() && std::string_view("aeiou").find(noun[0]) != noun.npos;
    return (vowel ? "an " : "a ") + std::string(noun);
}

}  // namespace litkit::detail
