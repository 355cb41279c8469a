// Scene files (SPEC §5): reading TOML, merging several files, and turning the
// tables into a Scene. Problems in the input are collected, never thrown one
// at a time, so that a run reports all of them (SPEC §6).
//
// What this file checks: the shape of the input — types (a string where a
// number belongs, a float where an integer belongs), missing required keys,
// unknown keys and keys of another light or object type, misspelt values,
// NaN and infinities, numbers that do not fit the C++ type they go into, and
// colours (whose 0–255 range is part of their format). What it does not
// check: ranges and geometry (room sizes > 0, inside-the-room, overlaps, …);
// validate_scene (validate.hpp) does, from build_scene, on a well-formed scene.
//
// Required tables and keys (a decision SPEC §5 leaves open):
//   [room] with width, height, depth   — required: the room bounds the scene
//                                        (Table 1 of the requirements);
//   [observer] with position           — required: exactly one observer (AB3);
//   [lighting], [output]               — optional, every key has a default
//                                        ([lighting] keys stay "not given",
//                                        R11 lets the caller ask);
//   a light's `type`, a directional or spot light's `direction`, a point or
//   spot light's `position`, an object's `type`, a mesh object's `file`.
// A scene split over several files needs each table in exactly one of them.

#include "litkit/scene.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numeric>
#include <system_error>
#include <utility>

#include "litkit/shapes.hpp"
#include "litkit/validate.hpp"
#include "validate_internal.hpp"

namespace litkit {

std::string_view shape_type_name(const Shape& shape) {
    struct Name {
        std::string_view operator()(const CubeShape&) const { return "cube"; }
        std::string_view operator()(const SphereShape&) const { return "sphere"; }
        std::string_view operator()(const TorusShape&) const { return "torus"; }
        std::string_view operator()(const TeapotShape&) const { return "teapot"; }
        std::string_view operator()(const MeshFileShape&) const { return "mesh"; }
    };
    return std::visit(Name{}, shape);
}

FileLoc Scene::location_of(std::string_view path) const {
    auto found = locations.find(path);
    return found == locations.end() ? FileLoc{} : found->second;
}

namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------
// Words: suggestions for misspelt keys and values.

std::string lower_case(std::string_view text) {
    std::string result(text);
    for (char& c : result)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return result;
}

// Levenshtein distance: insertions, deletions and substitutions.
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

// The candidate the user most likely meant by `word`, if any is close: the
// same word in another case ("Phong"), a small typo ("positon",
// "half_lambert"), or the unique candidate `word` begins ("blinn").
std::optional<std::string_view> closest_word(std::string_view word,
                                             std::span<const std::string_view> candidates) {
    const std::string folded = lower_case(word);
    std::optional<std::string_view> best;
    std::size_t best_distance = std::numeric_limits<std::size_t>::max();
    for (std::string_view candidate : candidates) {
        std::size_t distance = edit_distance(folded, candidate);
        if (distance < best_distance) {
            best = candidate;
            best_distance = distance;
        }
    }
    const std::size_t allowed = folded.size() <= 3 ? 1 : 2;
    if (best && best_distance <= allowed && best_distance < folded.size()) return best;

    std::optional<std::string_view> prefix_match;
    int prefix_matches = 0;
    for (std::string_view candidate : candidates) {
        // "blinn" → "blinn-phong", and "spotlight" → "spot".
        if (folded.size() >= 3 && (candidate.starts_with(folded) ||
                                   (candidate.size() >= 3 && folded.starts_with(candidate)))) {
            prefix_match = candidate;
            ++prefix_matches;
        }
    }
    if (prefix_matches == 1) return prefix_match;
    return std::nullopt;
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

// "a point light", "an ambient light", "an object type".
std::string with_article(std::string_view noun) {
    const bool vowel = !noun.empty() && std::string_view("aeiou").find(noun[0]) != noun.npos;
    return (vowel ? "an " : "a ") + std::string(noun);
}

// ---------------------------------------------------------------------------
// Describing TOML values in messages.

std::string number_text(double value) {
    char buffer[64];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (error != std::errc()) return "?";
    return std::string(buffer, end);
}

// What was found where something else belongs: "string", "float 3.5",
// "array of 2 values".
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

// ---------------------------------------------------------------------------
// The names of the closed sets in scene files.

constexpr std::array<std::string_view, 6> top_level_keys{"room",   "observer", "lighting",
                                                         "output", "lights",   "objects"};
constexpr std::array<std::string_view, 3> room_keys{"width", "height", "depth"};
constexpr std::array<std::string_view, 6> observer_keys{"position", "look_at", "up",
                                                        "fov",      "near",    "far"};
constexpr std::array<std::string_view, 2> lighting_keys{"reflection", "shading"};
constexpr std::array<std::string_view, 4> output_keys{"width", "height", "background", "gamma"};
constexpr std::array<std::string_view, 5> material_keys{"color", "ka", "kd", "ks", "shininess"};

constexpr std::array<std::string_view, 4> reflection_names{"lambert", "half-lambert", "phong",
                                                           "blinn-phong"};
constexpr std::array<std::string_view, 3> shading_names{"flat", "gouraud", "phong"};

// A light or object type and the keys only it has (SPEC §2 and §4 tables).
struct TypeKeys {
    std::string_view type;
    std::vector<std::string_view> keys;
};

// Keys every light or object has, and the keys of each type.
struct Family {
    std::string_view noun;  // "light", "object"
    std::vector<std::string_view> common_keys;
    std::vector<TypeKeys> types;

    std::vector<std::string_view> type_names() const {
        std::vector<std::string_view> names;
        for (const TypeKeys& t : types) names.push_back(t.type);
        return names;
    }
    const TypeKeys* find(std::string_view type) const {
        for (const TypeKeys& t : types)
            if (t.type == type) return &t;
        return nullptr;
    }
};

const Family& light_family() {
    static const Family family{
        "light",
        {"name", "type", "color", "intensity"},
        {
            {"ambient", {}},
            {"directional", {"direction"}},
            {"point", {"position", "attenuation"}},
            {"spot", {"position", "attenuation", "direction", "cutoff", "exponent"}},
        }};
    return family;
}

const Family& object_family() {
    static const Family family{
        "object",
        {"name", "type", "position", "rotation", "scale", "material", "reflection", "shading"},
        {
            {"cube", {"size"}},
            {"sphere", {"radius", "segments", "rings"}},
            {"torus", {"major_radius", "minor_radius", "segments", "sides"}},
            {"teapot", {"size", "subdivisions"}},
            {"mesh", {"file"}},
        }};
    return family;
}

// ---------------------------------------------------------------------------
// Reading the tables of one scene.

// One scene file, parsed.
struct ParsedFile {
    std::string name;  // as given, for messages
    fs::path folder;   // resolves relative mesh paths
    toml::table root;
};

// A table being read, and how messages and locations name it.
struct Site {
    const toml::table& table;
    std::string path;        // location key: "lights[0]", "objects[1].material"
    std::string subject;     // message prefix: "lights[0] 'key'"; empty at top level
    std::string key_prefix;  // key names in messages: "" or "material."
};

class SceneReader {
public:
    explicit SceneReader(Scene& scene) : scene_(scene) {}

    void read_file(const ParsedFile& file);
    void check_required_tables(std::span<const ParsedFile> files);
    std::vector<Diagnostic> take_diagnostics() { return std::move(diagnostics_); }
    const BrokenEntities& broken_entities() const { return broken_; }

private:
    // Reporting.
    FileLoc location(const toml::source_region& region) const {
        return FileLoc{file_->name, region.begin.line, region.begin.column};
    }
    void error(const toml::source_region& where, const Site& site, const std::string& message) {
        std::string text = site.subject.empty() ? message : site.subject + ": " + message;
        diagnostics_.push_back(Diagnostic{location(where), Severity::Error, std::move(text)});
        // The entity ("lights[0]", "observer"; "" for the file as a whole)
        // now holds a default in place of a bad value.
        broken_.insert(site.path.substr(0, site.path.find('.')));
    }
    std::string key_name(const Site& site, std::string_view key) const {
        return site.key_prefix + std::string(key);
    }

    // Looking values up. Every value found is recorded in Scene::locations.
    const toml::node* lookup(const Site& site, std::string_view key) {
        const toml::node* node = site.table.get(key);
        if (node) scene_.locations[site.path + "." + std::string(key)] = location(node->source());
        return node;
    }
    void require(const Site& site, std::string_view key, std::string_view hint = {}) {
        if (site.table.contains(key)) return;
        std::string message = "missing required key '" + key_name(site, key) + "'";
        if (!hint.empty()) message += " (" + std::string(hint) + ")";
        error(site.table.source(), site, message);
    }
    void check_keys(const Site& site, std::span<const std::string_view> allowed);
    void check_family_keys(const Site& site, const Family& family, const TypeKeys* type);

    // Typed values: each returns nothing (and reports why) when the value is
    // absent or unusable, so the caller keeps its default.
    std::optional<float> number_value(const toml::node& node, const Site& site,
                                      const std::string& name);
    std::optional<int> integer_value(const toml::node& node, const Site& site,
                                     const std::string& name);
    std::optional<float> read_number(const Site& site, std::string_view key);
    std::optional<int> read_integer(const Site& site, std::string_view key);
    std::optional<glm::vec3> read_vec3(const Site& site, std::string_view key);
    std::optional<Rgb8> read_color(const Site& site, std::string_view key);
    std::optional<std::string> read_string(const Site& site, std::string_view key);
    std::optional<std::string_view> read_choice(const Site& site, std::string_view key,
                                                std::span<const std::string_view> choices,
                                                std::string_view what);
    template <typename Enum, typename Parse>
    std::optional<Enum> read_enum(const Site& site, std::string_view key,
                                  std::span<const std::string_view> names, std::string_view what,
                                  Parse parse) {
        auto name = read_choice(site, key, names, what);
        return name ? parse(*name) : std::nullopt;
    }

    // Tables.
    bool claim_table(const Site& root, std::string_view key, const toml::node& node);
    const toml::table* as_table(const toml::node& node, const Site& site, std::string_view key);
    void read_room(const Site& site);
    void read_observer(const Site& site);
    void read_lighting(const Site& site);
    void read_output(const Site& site);
    void read_lights(const Site& root, const toml::node& node);
    void read_objects(const Site& root, const toml::node& node);
    void read_light(const Site& site);
    void read_object(const Site& site);
    void read_material(const Site& object_site, Material& material);
    const TypeKeys* read_type(const Site& site, const Family& family);
    std::string entity_subject(const toml::table& table, const std::string& path);

    Scene& scene_;
    std::vector<Diagnostic> diagnostics_;
    BrokenEntities broken_;
    const ParsedFile* file_ = nullptr;
    std::map<std::string, FileLoc, std::less<>> defined_tables_;  // top-level table → where
};

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

// SPEC §5: [r, g, b] integers 0–255 or "#rrggbb". The range is part of the
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
            color[i] = static_cast<std::uint8_t>(std::stoi(value.substr(1 + 2 * i, 2), nullptr, 16));
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

glm::vec3 unit_color(const Rgb8& color) {
    return glm::vec3(color[0], color[1], color[2]) / 255.0f;
}

std::optional<std::string> SceneReader::read_string(const Site& site, std::string_view key) {
    const toml::node* node = lookup(site, key);
    if (!node) return std::nullopt;
    if (const auto* text = node->as_string()) return text->get();
    error(node->source(), site,
          key_name(site, key) + " must be a string, found " + describe(*node));
    return std::nullopt;
}

// A value from a closed set of lower-case words (SPEC §6: `"Phong"` and
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
    error(node.source(), site,
          key_name(site, key) + " must be a table, found " + describe(node));
    return nullptr;
}

// A top-level table other than `lights` and `objects` may appear in one file
// only (SPEC §5). Returns false when another file already has it.
bool SceneReader::claim_table(const Site& root, std::string_view key, const toml::node& node) {
    FileLoc here = location(node.source());
    auto [existing, inserted] = defined_tables_.try_emplace(std::string(key), here);
    if (inserted) return true;
    error(node.source(), root,
          "[" + std::string(key) + "] is defined twice: here and at " +
              existing->second.to_string());
    return false;
}

void SceneReader::read_file(const ParsedFile& file) {
    file_ = &file;
    const std::size_t first_diagnostic = diagnostics_.size();
    const Site root{file.root, "", "", ""};
    check_keys(root, top_level_keys);

    using Reader = void (SceneReader::*)(const Site&);
    const std::array<std::pair<std::string_view, Reader>, 4> tables{{
        {"room", &SceneReader::read_room},
        {"observer", &SceneReader::read_observer},
        {"lighting", &SceneReader::read_lighting},
        {"output", &SceneReader::read_output},
    }};
    for (const auto& [key, reader] : tables) {
        const toml::node* node = file.root.get(key);
        if (!node || !claim_table(root, key, *node)) continue;
        scene_.locations[std::string(key)] = location(node->source());
        if (const toml::table* table = as_table(*node, root, key))
            (this->*reader)(Site{*table, std::string(key), std::string(key), ""});
    }
    if (const toml::node* lights = file.root.get("lights")) read_lights(root, *lights);
    if (const toml::node* objects = file.root.get("objects")) read_objects(root, *objects);

    // toml++ keeps keys sorted by name; report in the order of the file.
    auto by_position = [](const Diagnostic& a, const Diagnostic& b) {
        return std::pair(a.location.line, a.location.column) <
               std::pair(b.location.line, b.location.column);
    };
    std::stable_sort(diagnostics_.begin() + static_cast<std::ptrdiff_t>(first_diagnostic),
                     diagnostics_.end(), by_position);
    file_ = nullptr;
}

void SceneReader::check_required_tables(std::span<const ParsedFile> files) {
    for (std::string_view key : {std::string_view("room"), std::string_view("observer")}) {
        if (defined_tables_.contains(key)) continue;
        FileLoc where;
        std::string message = "missing required table [" + std::string(key) + "]";
        if (files.size() == 1) {
            where.file = files[0].name;
        } else {
            std::vector<std::string_view> names;
            for (const ParsedFile& file : files) names.push_back(file.name);
            message += names.empty() ? " (no scene files were given)"
                                     : " (in none of " + join(names, ", ") + ")";
        }
        diagnostics_.push_back(Diagnostic{where, Severity::Error, message});
        broken_.insert(std::string(key));
    }
}

void SceneReader::read_room(const Site& site) {
    check_keys(site, room_keys);
    for (std::string_view key : room_keys) require(site, key);
    if (auto width = read_number(site, "width")) scene_.room.width = *width;
    if (auto height = read_number(site, "height")) scene_.room.height = *height;
    if (auto depth = read_number(site, "depth")) scene_.room.depth = *depth;
}

void SceneReader::read_observer(const Site& site) {
    check_keys(site, observer_keys);
    require(site, "position");
    Observer& observer = scene_.observer;
    if (auto position = read_vec3(site, "position")) observer.position = *position;
    if (auto look_at = read_vec3(site, "look_at")) observer.look_at = *look_at;
    if (auto up = read_vec3(site, "up")) observer.up = *up;
    if (auto fov = read_number(site, "fov")) observer.fov_degrees = *fov;
    if (auto near = read_number(site, "near")) observer.near = *near;
    if (auto far = read_number(site, "far")) observer.far = *far;
}

void SceneReader::read_lighting(const Site& site) {
    check_keys(site, lighting_keys);
    scene_.reflection = read_enum<Reflection>(site, "reflection", reflection_names,
                                              "reflection model", parse_reflection);
    scene_.shading = read_enum<Shading>(site, "shading", shading_names, "shading model",
                                        parse_shading);
}

void SceneReader::read_output(const Site& site) {
    check_keys(site, output_keys);
    OutputSettings& output = scene_.output;
    if (auto width = read_integer(site, "width")) output.width = *width;
    if (auto height = read_integer(site, "height")) output.height = *height;
    if (auto background = read_color(site, "background")) output.background = *background;
    if (auto gamma = read_number(site, "gamma")) output.gamma = *gamma;
}

void SceneReader::read_lights(const Site& root, const toml::node& node) {
    const toml::array* array = node.as_array();
    if (!array) {
        error(node.source(), root, "lights must be an array of tables ([[lights]]), found " +
                                       describe(node));
        return;
    }
    for (const toml::node& element : *array) {
        std::string path = "lights[" + std::to_string(scene_.lights.size()) + "]";
        scene_.lights.emplace_back();  // keeps the numbering even if this one is unusable
        scene_.locations[path] = location(element.source());
        if (const toml::table* table = element.as_table()) {
            read_light(Site{*table, path, entity_subject(*table, path), ""});
        } else {
            error(element.source(), root, path + " must be a table, found " + describe(element));
        }
    }
}

void SceneReader::read_objects(const Site& root, const toml::node& node) {
    const toml::array* array = node.as_array();
    if (!array) {
        error(node.source(), root, "objects must be an array of tables ([[objects]]), found " +
                                       describe(node));
        return;
    }
    for (const toml::node& element : *array) {
        std::string path = "objects[" + std::to_string(scene_.objects.size()) + "]";
        scene_.objects.emplace_back();
        scene_.locations[path] = location(element.source());
        if (const toml::table* table = element.as_table()) {
            read_object(Site{*table, path, entity_subject(*table, path), ""});
        } else {
            error(element.source(), root, path + " must be a table, found " + describe(element));
        }
    }
}

// "lights[0] 'key'" when the light has a name, "lights[0]" otherwise.
std::string SceneReader::entity_subject(const toml::table& table, const std::string& path) {
    const toml::node* name = table.get("name");
    if (name && name->is_string() && !name->as_string()->get().empty())
        return path + " '" + name->as_string()->get() + "'";
    return path;
}

const TypeKeys* SceneReader::read_type(const Site& site, const Family& family) {
    const std::vector<std::string_view> names = family.type_names();
    require(site, "type", "one of " + join(names, ", "));
    auto type = read_choice(site, "type", names, std::string(family.noun) + " type");
    return type ? family.find(*type) : nullptr;
}

void SceneReader::read_light(const Site& site) {
    const Family& family = light_family();
    const TypeKeys* type = read_type(site, family);
    check_family_keys(site, family, type);

    SceneLight& light = scene_.lights.back();
    if (auto name = read_string(site, "name")) light.name = *name;
    if (auto color = read_color(site, "color")) light.light.color = unit_color(*color);
    if (auto intensity = read_number(site, "intensity")) light.light.intensity = *intensity;
    if (!type) return;

    if (type->type == "ambient") {
        light.light.kind = AmbientLight{};
    } else if (type->type == "directional") {
        DirectionalLight directional;
        require(site, "direction");
        if (auto direction = read_vec3(site, "direction")) directional.direction = *direction;
        light.light.kind = directional;
    } else if (type->type == "point") {
        PointLight point;
        require(site, "position");
        if (auto position = read_vec3(site, "position")) point.position = *position;
        if (auto attenuation = read_vec3(site, "attenuation")) point.attenuation = *attenuation;
        light.light.kind = point;
    } else {
        SpotLight spot;
        require(site, "position");
        require(site, "direction");
        if (auto position = read_vec3(site, "position")) spot.position = *position;
        if (auto attenuation = read_vec3(site, "attenuation")) spot.attenuation = *attenuation;
        if (auto direction = read_vec3(site, "direction")) spot.direction = *direction;
        if (auto cutoff = read_number(site, "cutoff")) spot.cutoff_degrees = *cutoff;
        if (auto exponent = read_number(site, "exponent")) spot.exponent = *exponent;
        light.light.kind = spot;
    }
}

void SceneReader::read_object(const Site& site) {
    const Family& family = object_family();
    const TypeKeys* type = read_type(site, family);
    check_family_keys(site, family, type);

    SceneObject& object = scene_.objects.back();
    if (auto name = read_string(site, "name")) object.name = *name;
    if (auto position = read_vec3(site, "position")) object.position = *position;
    if (auto rotation = read_vec3(site, "rotation")) object.rotation_degrees = *rotation;
    if (auto scale = read_number(site, "scale")) object.scale = *scale;
    object.reflection = read_enum<Reflection>(site, "reflection", reflection_names,
                                              "reflection model", parse_reflection);
    object.shading =
        read_enum<Shading>(site, "shading", shading_names, "shading model", parse_shading);
    read_material(site, object.material);
    if (!type) return;

    if (type->type == "cube") {
        CubeShape cube;
        if (auto size = read_number(site, "size")) cube.size = *size;
        object.shape = cube;
    } else if (type->type == "sphere") {
        SphereShape sphere;
        if (auto radius = read_number(site, "radius")) sphere.radius = *radius;
        if (auto segments = read_integer(site, "segments")) sphere.segments = *segments;
        if (auto rings = read_integer(site, "rings")) sphere.rings = *rings;
        object.shape = sphere;
    } else if (type->type == "torus") {
        TorusShape torus;
        if (auto major = read_number(site, "major_radius")) torus.major_radius = *major;
        if (auto minor = read_number(site, "minor_radius")) torus.minor_radius = *minor;
        if (auto segments = read_integer(site, "segments")) torus.segments = *segments;
        if (auto sides = read_integer(site, "sides")) torus.sides = *sides;
        object.shape = torus;
    } else if (type->type == "teapot") {
        TeapotShape teapot;
        if (auto size = read_number(site, "size")) teapot.size = *size;
        if (auto subdivisions = read_integer(site, "subdivisions"))
            teapot.subdivisions = *subdivisions;
        object.shape = teapot;
    } else {
        MeshFileShape mesh;
        require(site, "file");
        if (auto file = read_string(site, "file")) {
            if (file->empty()) {
                error(site.table.get("file")->source(), site, "file must not be empty");
            } else {
                // SPEC §5: relative to the file that names it.
                fs::path path(*file);
                mesh.file = path.is_absolute() ? path : file_->folder / path;
            }
        }
        object.shape = mesh;
    }
}

void SceneReader::read_material(const Site& object_site, Material& material) {
    const toml::node* node = lookup(object_site, "material");
    if (!node) return;
    const toml::table* table = as_table(*node, object_site, "material");
    if (!table) return;
    const Site site{*table, object_site.path + ".material", object_site.subject, "material."};
    check_keys(site, material_keys);
    if (auto color = read_color(site, "color")) material.color = unit_color(*color);
    if (auto ka = read_number(site, "ka")) material.ka = *ka;
    if (auto kd = read_number(site, "kd")) material.kd = *kd;
    if (auto ks = read_number(site, "ks")) material.ks = *ks;
    if (auto shininess = read_number(site, "shininess")) material.shininess = *shininess;
}

// ---------------------------------------------------------------------------
// Files.

// Parses TOML text; a syntax error or invalid UTF-8 makes the file one that
// cannot be read (SPEC §6), located where parsing stopped.
toml::table parse_toml(std::string_view text, const std::string& name) {
    try {
        return toml::parse(text, std::string_view(name));
    } catch (const toml::parse_error& failure) {
        const toml::source_position& where = failure.source().begin;
        throw IoError(name, std::string(failure.description()),
                      FileLoc{name, where.line, where.column});
    }
}

std::string read_bytes(const fs::path& path) {
    struct Closer {
        void operator()(std::FILE* file) const { std::fclose(file); }
    };
    errno = 0;
    std::unique_ptr<std::FILE, Closer> file(std::fopen(path.c_str(), "rb"));
    if (!file) throw IoError(path.string(), std::generic_category().message(errno));
    std::string bytes;
    char buffer[1 << 16];
    std::size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, file.get())) > 0)
        bytes.append(buffer, count);
    // Reading a directory fails here, with EISDIR.
    if (std::ferror(file.get())) throw IoError(path.string(), std::generic_category().message(errno));
    return bytes;
}

Scene build_scene(std::span<const ParsedFile> files) {
    Scene scene;
    SceneReader reader(scene);
    for (const ParsedFile& file : files) reader.read_file(file);
    reader.check_required_tables(files);
    std::vector<Diagnostic> diagnostics = reader.take_diagnostics();

    // The value and geometry rules (validate.hpp) run too, so that one run
    // reports every problem; entities with shape errors hold defaults in
    // place of their bad values and are left out of the geometric checks.
    for (Diagnostic& diagnostic : validate_scene(scene, reader.broken_entities())) {
        if (diagnostic.severity == Severity::Warning)
            scene.warnings.push_back(std::move(diagnostic));
        else
            diagnostics.push_back(std::move(diagnostic));
    }
    // A failed load still carries its warnings, for the caller to show.
    if (!diagnostics.empty()) throw SceneError(std::move(diagnostics), std::move(scene.warnings));
    return scene;
}

}  // namespace

Scene load_scene(std::span<const std::filesystem::path> files) {
    std::vector<ParsedFile> parsed;
    parsed.reserve(files.size());
    for (const fs::path& path : files) {
        std::string name = path.string();
        toml::table root = parse_toml(read_bytes(path), name);
        parsed.push_back(ParsedFile{std::move(name), path.parent_path(), std::move(root)});
    }
    return build_scene(parsed);
}

Scene parse_scene(std::string_view toml_text, const std::filesystem::path& source_name) {
    std::string name = source_name.string();
    ParsedFile file{name, source_name.parent_path(), parse_toml(toml_text, name)};
    return build_scene(std::span(&file, 1));
}

std::string_view default_scene_toml() {
    return R"toml(# litkit scene: the built-in default scene.
#
# `litkit init` writes this file as a starting point; `litkit render` with no
# scene draws it. Change a number, render again, and see what it does.
# Coordinates: right-handed, +y is up, units are metres. Lines starting with
# '#' are comments.

# The room is a box centred at the origin: here x, y and z each run from -5
# to 5. It is not drawn; everything in the scene must fit inside it.
[room]
width = 10
height = 10
depth = 10

# The camera. It stands at `position` and looks at `look_at`; `fov` is the
# vertical field of view in degrees. (Also possible: `up`, `near`, `far`.)
[observer]
position = [3.5, 1, 4]
look_at = [-2, -3, -2]      # the centre of the cube
fov = 30

# How light is computed. Try the other models and compare:
#   reflection: lambert | half-lambert | phong | blinn-phong
#   shading:    flat | gouraud | phong
[lighting]
reflection = "phong"
shading = "phong"

# The picture: its size in pixels and the colour where no object is.
[output]
width = 800
height = 600
background = [25, 28, 36]   # colours are [red, green, blue], 0-255, or "#rrggbb"

# One point light at the centre of the room. Its light fades with the square
# of the distance, so it needs some intensity to reach the cube about 4 m away.
# Other light types: ambient, directional, spot.
[[lights]]
name = "bulb"
type = "point"
position = [0, 0, 0]
color = [255, 255, 255]
intensity = 15

# One cube, below and behind the light so that the three faces you see are lit.
# `rotation` turns it about x, then y, then z (degrees). Other object types:
# sphere, torus, teapot, and mesh (an OBJ file).
[[objects]]
name = "cube"
type = "cube"
size = 2
position = [-2, -3, -2]
rotation = [0, 30, 0]
# ka: ambient, kd: diffuse (matte), ks: specular (shine), shininess: how
# small and sharp the highlight is.
material = { color = [200, 80, 60], ka = 0.1, kd = 0.7, ks = 0.5, shininess = 32 }
)toml";
}

Scene default_scene() { return parse_scene(default_scene_toml(), "default.toml"); }

glm::mat4 object_to_world(const SceneObject& object) {
    // SPEC §2: world = T(position) · Rz · Ry · Rx · S(scale); each glm call
    // multiplies on the right, so the calls read in the formula's order.
    glm::mat4 transform = glm::translate(glm::mat4(1.0f), object.position);
    transform = glm::rotate(transform, glm::radians(object.rotation_degrees.z), {0.0f, 0.0f, 1.0f});
    transform = glm::rotate(transform, glm::radians(object.rotation_degrees.y), {0.0f, 1.0f, 0.0f});
    transform = glm::rotate(transform, glm::radians(object.rotation_degrees.x), {1.0f, 0.0f, 0.0f});
    return glm::scale(transform, glm::vec3(object.scale));
}

Mesh object_mesh(const SceneObject& object) {
    struct Build {
        Mesh operator()(const CubeShape& cube) const { return make_cube(cube.size); }
        Mesh operator()(const SphereShape& sphere) const {
            return make_sphere(sphere.radius, sphere.segments, sphere.rings);
        }
        Mesh operator()(const TorusShape& torus) const {
            return make_torus(torus.major_radius, torus.minor_radius, torus.segments, torus.sides);
        }
        Mesh operator()(const TeapotShape& teapot) const {
            return make_teapot(teapot.size, teapot.subdivisions);
        }
        Mesh operator()(const MeshFileShape& mesh) const { return load_obj(mesh.file); }
    };
    return std::visit(Build{}, object.shape);
}

WorldMesh world_mesh(const SceneObject& object) {
    Mesh mesh = object_mesh(object);
    const std::vector<glm::vec3> local_normals = vertex_normals(mesh);
    const glm::mat4 model = object_to_world(object);
    const glm::mat3 rotation = glm::mat3(model) * (1.0f / object.scale);

    WorldMesh world;
    world.positions.reserve(mesh.positions.size());
    world.normals.reserve(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        world.positions.push_back(glm::vec3(model * glm::vec4(mesh.positions[i], 1.0f)));
        const glm::vec3 n = rotation * local_normals[i];
        const float length = glm::length(n);
        world.normals.push_back(length > 0.0f ? n / length : n);
    }
    world.triangles = std::move(mesh.triangles);
    return world;
}

}  // namespace litkit
