// SPDX-License-Identifier: MIT
// The scene reader's typed values (scene/reader.hpp): each returns nothing,
// and reports why, when the value is absent or unusable.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "scene/reader.hpp"
#include "scene/words.hpp"

namespace litkit::detail {

namespace {

std::string number_text(double value) {
    char buffer[64];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (error != std::errc()) return "?";
    return std::string(buffer, end);
}

}  // namespace

std::string describe(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::string:
            return "string";
        case toml::node_type::integer:
            return "integer " + std::to_string(node.as_integer()->get());
        case toml::node_type::floating_point: {
            // "float 1.0", not "float 1": the file wrote a float, and the
            // message must not look as if it had found an integer.
            std::string text = number_text(node.as_floating_point()->get());
            if (text.find_first_not_of("-0123456789") == std::string::npos) text += ".0";
            return "float " + text;
        }
        case toml::node_type::boolean:
            return node.as_boolean()->get() ? "boolean true" : "boolean false";
        case toml::node_type::array: {
            std::size_t size = node.as_array()->size();
            return "array of " + std::to_string(size) + (size == 1 ? " value" : " values");
        }
        case toml::node_type::table:
            return "table";
        case toml::node_type::date:
            return "date";
        case toml::node_type::time:
            return "time";
        case toml::node_type::date_time:
            return "date-time";
        case toml::node_type::none:
            break;
    }
    return "nothing";
}

void SceneReader::check_keys(const Site& site, std::span<const std::string_view> allowed) {
    for (auto&& [key, node] : site.table) {
        if (contains(allowed, key.str())) continue;
        std::string message = site.subject.empty() && site.key_prefix.empty()
                                  ? "unknown top-level key '" + std::string(key.str()) + "'"
                                  : "unknown key '" + key_name(site, key.str()) + "'";
        auto match = closest_word(key.str(), allowed);
        if (match) message += "; did you mean '" + key_name(site, *match) + "'?";
        error(key.source(), site, message);
    }
}

// The keys of a light or an object: its family's common keys plus those of
// its own type. A key of another type is reported as such ("'cutoff' does
// not belong to a point light"); when the type itself is missing or wrong,
// any key of the family passes.
void SceneReader::check_family_keys(const Site& site, const Family& family, const TypeKeys* type) {
    std::vector<std::string_view> allowed = family.common_keys;
    if (type) {
        allowed.insert(allowed.end(), type->keys.begin(), type->keys.end());
    } else {
        for (const TypeKeys& t : family.types)
            for (std::string_view key : t.keys)
                if (!contains(allowed, key)) allowed.push_back(key);
    }
    for (auto&& [key, node] : site.table) {
        if (contains(allowed, key.str())) continue;
        std::vector<std::string_view> owners;
        for (const TypeKeys& t : family.types)
            if (contains(t.keys, key.str())) owners.push_back(t.type);
        if (!owners.empty()) {
            error(key.source(), site,
                  "key '" + std::string(key.str()) + "' does not belong to " +
                      with_article(type->type) + " " + std::string(family.noun) +
                      " (only to: " + join(owners, ", ") + ")");
            continue;
        }
        error(key.source(), site,
              "unknown key '" + std::string(key.str()) + "'" + did_you_mean(key.str(), allowed));
    }
}

std::optional<float> SceneReader::number_value(const toml::node& node, const Site& site,
                                               const std::string& name) {
    double value = 0.0;
    if (const auto* integer = node.as_integer()) {
        value = static_cast<double>(integer->get());  // an integer is fine where a float belongs
    } else if (const auto* floating = node.as_floating_point()) {
        value = floating->get();
    } else {
        error(node.source(), site, name + " must be a number, found " + describe(node));
        return std::nullopt;
    }
    if (!std::isfinite(value)) {
        error(node.source(), site, name + " must be a finite number, found " + number_text(value));
        return std::nullopt;
    }
    if (std::abs(value) > static_cast<double>(std::numeric_limits<float>::max())) {
        error(node.source(), site, name + " " + number_text(value) + " is too large");
        return std::nullopt;
    }
    // Scenes hold 32-bit floats: a value that is not 0 but becomes 0 would
    // be reported later as "found 0", which the file never said.
    if (value != 0.0 && static_cast<float>(value) == 0.0f) {
        error(node.source(), site,
              name + " " + number_text(value) + " is too small (closest to 0 a scene holds: " +
                  number_text(static_cast<double>(std::numeric_limits<float>::denorm_min())) +
                  "; write 0 for zero)");
        return std::nullopt;
    }
    return static_cast<float>(value);
}

std::optional<int> SceneReader::integer_value(const toml::node& node, const Site& site,
                                              const std::string& name) {
    const auto* integer = node.as_integer();
    if (!integer) {
        error(node.source(), site, name + " must be an integer, found " + describe(node));
        return std::nullopt;
    }
    std::int64_t value = integer->get();
    if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
        error(node.source(), site,
              name + " " + std::to_string(value) + " is too large for an integer here");
        return std::nullopt;
    }
    return static_cast<int>(value);
}

std::optional<float> SceneReader::read_number(const Site& site, std::string_view key) {
    const toml::node* node = lookup(site, key);
    return node ? number_value(*node, site, key_name(site, key)) : std::nullopt;
}

std::optional<int> SceneReader::read_integer(const Site& site, std::string_view key) {
    const toml::node* node = lookup(site, key);
    return node ? integer_value(*node, site, key_name(site, key)) : std::nullopt;
}

std::optional<glm::vec3> SceneReader::read_vec3(const Site& site, std::string_view key) {
    const toml::node* node = lookup(site, key);
    if (!node) return std::nullopt;
    const std::string name = key_name(site, key);
    const toml::array* array = node->as_array();
    if (!array || array->size() != 3) {
        error(node->source(), site,
              name + " must be an array of 3 numbers, found " + describe(*node));
        return std::nullopt;
    }
    glm::vec3 result{0.0f};
    bool valid = true;
    for (int i = 0; i < 3; ++i) {
        auto value = number_value(*array->get(static_cast<std::size_t>(i)), site,
                                  name + "[" + std::to_string(i) + "]");
        if (value)
            result[i] = *value;
        else
            valid = false;
    }
    return valid ? std::optional(result) : std::nullopt;
}

// docs/spec.md §5: [r, g, b] integers 0–255 or "#rrggbb". The range is part of the
// format here (a background is stored in bytes), so it is checked now.
std::optional<Rgb8> SceneReader::read_color(const Site& site, std::string_view key) {
    const toml::node* node = lookup(site, key);
    if (!node) return std::nullopt;
    const std::string name = key_name(site, key);
    const std::string expected = " must be [r, g, b] with integers 0-255 or a \"#rrggbb\" string";
    if (const auto* text = node->as_string()) {
        const std::string& value = text->get();
        auto hex_digit = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
        if (value.size() != 7 || value[0] != '#' ||
            !std::all_of(value.begin() + 1, value.end(), hex_digit)) {
            error(node->source(), site, name + expected + ", found \"" + value + "\"");
            return std::nullopt;
        }
        Rgb8 color{};
        for (std::size_t i = 0; i < 3; ++i)
            color[i] =
                static_cast<std::uint8_t>(std::stoi(value.substr(1 + 2 * i, 2), nullptr, 16));
        return color;
    }
    const toml::array* array = node->as_array();
    if (!array || array->size() != 3) {
        error(node->source(), site, name + expected + ", found " + describe(*node));
        return std::nullopt;
    }
    Rgb8 color{};
    bool valid = true;
    for (std::size_t i = 0; i < 3; ++i) {
        const toml::node& channel = *array->get(i);
        const std::string channel_name = name + "[" + std::to_string(i) + "]";
        const auto* integer = channel.as_integer();
        if (!integer) {
            error(channel.source(), site,
                  channel_name + " must be an integer 0-255, found " + describe(channel));
            valid = false;
        } else if (integer->get() < 0 || integer->get() > 255) {
            error(channel.source(), site,
                  channel_name + " must be an integer 0-255, found " + describe(channel));
            valid = false;
        } else {
            color[i] = static_cast<std::uint8_t>(integer->get());
        }
    }
    return valid ? std::optional(color) : std::nullopt;
}

std::optional<std::string> SceneReader::read_string(const Site& site, std::string_view key) {
    const toml::node* node = lookup(site, key);
    if (!node) return std::nullopt;
    if (const auto* text = node->as_string()) return text->get();
    error(node->source(), site,
          key_name(site, key) + " must be a string, found " + describe(*node));
    return std::nullopt;
}

// A value from a closed set of lower-case words (docs/spec.md §6: `"Phong"` and
// `"blinn"` are errors, with a suggestion).
std::optional<std::string_view> SceneReader::read_choice(const Site& site, std::string_view key,
                                                         std::span<const std::string_view> choices,
                                                         std::string_view what) {
    const toml::node* node = lookup(site, key);
    if (!node) return std::nullopt;
    const std::string name = key_name(site, key);
    const auto* text = node->as_string();
    if (!text) {
        error(node->source(), site,
              name + " must be a string (one of " + join(choices, ", ") + "), found " +
                  describe(*node));
        return std::nullopt;
    }
    for (std::string_view choice : choices)
        if (choice == text->get()) return choice;
    error(node->source(), site,
          name + " \"" + text->get() + "\" is not " + with_article(what) + " (one of " +
              join(choices, ", ") + ")" + did_you_mean(text->get(), choices));
    return std::nullopt;
}

const toml::table* SceneReader::as_table(const toml::node& node, const Site& site,
                                         std::string_view key) {
    if (const toml::table* table = node.as_table()) return table;
    error(node.source(), site, key_name(site, key) + " must be a table, found " + describe(node));
    return nullptr;
}

}  // namespace litkit::detail
