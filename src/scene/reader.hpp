// SPDX-License-Identifier: MIT
// The scene reader (docs/spec.md §5): turns the TOML tables of one or more files into
// a Scene. Problems in the input are collected, never thrown one
// at a time, so that a run reports all of them (docs/spec.md §6).
//
// What this file checks: the shape of the input — types (a string where a
// number belongs, a float where an integer belongs), missing required keys,
// unknown keys and keys of another light or object type, misspelt values,
// NaN and infinities, numbers that do not fit the C++ type they go into, and
// colours (whose 0–255 range is part of their format). What it does not
// check: ranges and geometry (room sizes > 0, inside-the-room, overlaps, …);
// validate_scene (validate.hpp) does, from build_scene, on a well-formed scene.
//
// Required tables and keys (a decision docs/spec.md §5 leaves open):
//   [room] with width, height, depth   — required: the room bounds the scene
//                                        (Table 1 of the requirements);
//   [observer] with position           — required: exactly one observer (AB3);
//   [lighting], [output]               — optional, every key has a default
//                                        ([lighting] keys stay "not given",
//                                        R11 lets the caller ask);
//   a light's `type`, a directional or spot light's `direction`, a point or
//   spot light's `position`, an object's `type`, a mesh object's `file`.
// A scene split over several files needs each table in exactly one of them.
//
// Its parts: read_values.cpp (typed values: numbers, vectors, colours,
// choices, and the messages for wrong ones), read_tables.cpp (the tables:
// room, observer, lighting, output, lights, objects, materials), load.cpp
// (files: reading bytes, parsing TOML, merging, validating).
#pragma once

#include <glm/vec3.hpp>
#include "scene/toml.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/scene.hpp"
#include "scene/validate_internal.hpp"

namespace litkit::detail {

// A light or object type and the keys only it has (docs/spec.md §2 and §4 tables).
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

// One scene file, parsed.
struct ParsedFile {
    std::string name;              // as given, for messages
    std::filesystem::path folder;  // resolves relative mesh paths
    toml::table root;
};

// A table being read, and how messages and locations name it.
struct Site {
    const toml::table& table;
    std::string path;        // location key: "lights[0]", "objects[1].material"
    std::string subject;     // message prefix: "lights[0] 'key'"; empty at top level
    std::string key_prefix;  // key names in messages: "" or "material."
};

// What was found where something else belongs: "string", "float 3.5",
// "array of 2 values".
std::string describe(const toml::node& node);

class SceneReader {
  public:
    explicit SceneReader(Scene& scene) : scene_(scene) {}

    void read_file(const ParsedFile& file);
    void check_required_tables(std::span<const ParsedFile> files);
    std::vector<Diagnostic> take_diagnostics() { return std::move(diagnostics_); }
    const BrokenEntities& broken_entities() const { return broken_; }

  private:
    void check_far_beyond_near(const Site& site);

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

}  // namespace litkit::detail
