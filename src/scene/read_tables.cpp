// SPDX-License-Identifier: MIT
// The scene reader's tables (scene/reader.hpp): which keys each table has,
// and how each becomes part of the Scene.
#include <algorithm>
#include <array>
#include <charconv>
#include <utility>
#include <variant>

#include "scene/reader.hpp"
#include "scene/words.hpp"

namespace litkit::detail {

namespace {

namespace fs = std::filesystem;

// A number as the file wrote it: the shortest text that reads back as the
// same double ("5.0000001", "1e-50").
std::string written_text(double value) {
    char buffer[64];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

// The names of the closed sets in scene files.
constexpr std::array<std::string_view, 6> top_level_keys{"room",   "observer", "lighting",
                                                         "output", "lights",   "objects"};
constexpr std::array<std::string_view, 4> room_keys{"width", "height", "depth", "ior"};
constexpr std::array<std::string_view, 6> observer_keys{"position", "look_at", "up",
                                                        "fov",      "near",    "far"};
constexpr std::array<std::string_view, 5> lighting_keys{"reflection", "shading", "normals",
                                                        "crease_angle", "max_depth"};
constexpr std::array<std::string_view, 5> output_keys{"width", "height", "background", "gamma",
                                                      "samples"};
// The material keys of docs/spec.md §5 and the parameters of §9.1: every
// object takes them all, whatever its reflection model, so that models can be
// switched freely.
std::span<const std::string_view> material_keys() {
    static const std::vector<std::string_view> keys = [] {
        std::vector<std::string_view> all{"color", "ka", "kd", "ks", "shininess"};
        for_each_model_parameter(
            [&](const ModelParameter& parameter, const float&) { all.push_back(parameter.key); },
            Material{});
        // docs/spec.md §10.1, refraction's: accepted on every object too.
        all.insert(all.end(), {"transmission", "ior", "absorption_color", "absorption_distance"});
        return all;
    }();
    return keys;
}

// The reflection models' names, from the family's one list (lighting.hpp).
std::span<const std::string_view> reflection_names() {
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> all;
        for (const ReflectionModel& model : reflection_models()) all.push_back(model.name);
        return all;
    }();
    return names;
}
// The keys of each light kind beyond those every light has.
struct LightKeys {
    std::vector<std::string_view> operator()(const AmbientLight&) const { return {}; }
    std::vector<std::string_view> operator()(const DirectionalLight&) const {
        return {"direction"};
    }
    std::vector<std::string_view> operator()(const PointLight&) const {
        return {"position", "attenuation"};
    }
    std::vector<std::string_view> operator()(const SpotLight&) const {
        return {"position", "attenuation", "direction", "cutoff", "exponent", "penumbra"};
    }
};

// The light types are the library's one list (lighting.hpp's light_kind_names).
const Family& light_family() {
    static const Family family = [] {
        Family light{"light", {"name", "type", "color", "intensity"}, {}};
        for (std::string_view name : light_kind_names)
            light.types.push_back({name, std::visit(LightKeys{}, *parse_light_kind(name))});
        return light;
    }();
    return family;
}

const Family& object_family() {
    static const Family family{"object",
                               {"name", "type", "position", "rotation", "scale", "material",
                                "reflection", "shading", "normals", "crease_angle"},
                               {
                                   {"cube", {"size"}},
                                   {"sphere", {"radius", "segments", "rings"}},
                                   {"torus", {"major_radius", "minor_radius", "segments", "sides"}},
                                   {"teapot", {"size", "subdivisions"}},
                                   {"mesh", {"file", "format"}},
                               }};
    return family;
}

glm::vec3 unit_color(const Rgb8& color) { return from_rgb8(color); }

}  // namespace

// A top-level table other than `lights` and `objects` may appear in one file
// only (docs/spec.md §5). Returns false when another file already has it.
bool SceneReader::claim_table(const Site& root, std::string_view key, const toml::node& node) {
    FileLoc here = location(node.source());
    auto [existing, inserted] = defined_tables_.try_emplace(std::string(key), here);
    if (inserted) return true;
    error(
        node.source(), root,
        "[" + std::string(key) + "] is defined twice: here and at " + existing->second.to_string());
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
    for (std::string_view key : {"width", "height", "depth"}) require(site, key);
    if (auto width = read_number(site, "width")) scene_.room.width = *width;
    if (auto height = read_number(site, "height")) scene_.room.height = *height;
    if (auto depth = read_number(site, "depth")) scene_.room.depth = *depth;
    if (auto ior = read_number(site, "ior")) scene_.room.ior = *ior;
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
    check_far_beyond_near(site);
}

// far > near (docs/spec.md §5), compared as written, in double: 5.0000001 and
// 5 are one 32-bit float, and a check of the floats would report "far (5)
// must be greater than near (5)", which the file never said.
void SceneReader::check_far_beyond_near(const Site& site) {
    const toml::node* near_node = site.table.get("near");
    const toml::node* far_node = site.table.get("far");
    if (!near_node && !far_node) return;
    const Observer& observer = scene_.observer;
    const std::optional<double> near_written =
        near_node ? near_node->value<double>() : std::optional<double>(observer.near);
    const std::optional<double> far_written =
        far_node ? far_node->value<double>() : std::optional<double>(observer.far);
    if (!near_written || !far_written) return;  // not numbers: already reported
    const toml::node& place = far_node ? *far_node : *near_node;
    if (!(*far_written > *near_written)) {
        error(place.source(), site,
              "far (" + written_text(*far_written) + ") must be greater than near (" +
                  written_text(*near_written) + ")");
    } else if (!(static_cast<float>(*far_written) > static_cast<float>(*near_written))) {
        error(place.source(), site,
              "far (" + written_text(*far_written) + ") and near (" + written_text(*near_written) +
                  ") are the same 32-bit float (" +
                  written_text(static_cast<double>(static_cast<float>(*far_written))) +
                  "); make far greater than near by more than that precision");
    }
}

void SceneReader::read_lighting(const Site& site) {
    check_keys(site, lighting_keys);
    scene_.reflection = read_enum<Reflection>(site, "reflection", reflection_names(),
                                              "reflection model", parse_reflection);
    scene_.shading =
        read_enum<Shading>(site, "shading", shading_names, "shading model", parse_shading);
    scene_.normals = read_enum<Normals>(site, "normals", normals_names, "way of computing normals",
                                        parse_normals);
    scene_.crease_angle_degrees = read_number(site, "crease_angle");
    if (auto max_depth = read_integer(site, "max_depth")) scene_.max_depth = *max_depth;
}

void SceneReader::read_output(const Site& site) {
    check_keys(site, output_keys);
    OutputSettings& output = scene_.output;
    if (auto width = read_integer(site, "width")) output.width = *width;
    if (auto height = read_integer(site, "height")) output.height = *height;
    if (auto background = read_color(site, "background"))
        output.background = unit_color(*background);
    if (auto gamma = read_number(site, "gamma")) output.gamma = *gamma;
    if (auto samples = read_integer(site, "samples")) output.samples = *samples;
}

void SceneReader::read_lights(const Site& root, const toml::node& node) {
    const toml::array* array = node.as_array();
    if (!array) {
        error(node.source(), root,
              "lights must be an array of tables ([[lights]]), found " + describe(node));
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
        error(node.source(), root,
              "objects must be an array of tables ([[objects]]), found " + describe(node));
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

    LightKind kind = *parse_light_kind(type->type);  // a type of light_family(): a kind
    if (auto* directional = std::get_if<DirectionalLight>(&kind)) {
        require(site, "direction");
        if (auto direction = read_vec3(site, "direction")) directional->direction = *direction;
    } else if (auto* point = std::get_if<PointLight>(&kind)) {
        require(site, "position");
        if (auto position = read_vec3(site, "position")) point->position = *position;
        if (auto attenuation = read_vec3(site, "attenuation")) point->attenuation = *attenuation;
    } else if (auto* spot = std::get_if<SpotLight>(&kind)) {
        require(site, "position");
        require(site, "direction");
        if (auto position = read_vec3(site, "position")) spot->position = *position;
        if (auto attenuation = read_vec3(site, "attenuation")) spot->attenuation = *attenuation;
        if (auto direction = read_vec3(site, "direction")) spot->direction = *direction;
        if (auto cutoff = read_number(site, "cutoff")) spot->cutoff_degrees = *cutoff;
        if (auto exponent = read_number(site, "exponent")) spot->exponent = *exponent;
        if (auto penumbra = read_number(site, "penumbra")) spot->penumbra = *penumbra;
    }
    light.light.kind = kind;
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
    object.reflection = read_enum<Reflection>(site, "reflection", reflection_names(),
                                              "reflection model", parse_reflection);
    object.shading =
        read_enum<Shading>(site, "shading", shading_names, "shading model", parse_shading);
    object.normals = read_enum<Normals>(site, "normals", normals_names, "way of computing normals",
                                        parse_normals);
    object.crease_angle_degrees = read_number(site, "crease_angle");
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
                // docs/spec.md §5: relative to the file that names it.
                fs::path path(*file);
                mesh.file = path.is_absolute() ? path : file_->folder / path;
            }
        }
        mesh.format = read_enum<MeshFileFormat>(site, "format", mesh_file_format_names,
                                                "mesh file format", parse_mesh_file_format);
        object.shape = mesh;
    }
}

void SceneReader::read_material(const Site& object_site, Material& material) {
    const toml::node* node = lookup(object_site, "material");
    if (!node) return;
    const toml::table* table = as_table(*node, object_site, "material");
    if (!table) return;
    const Site site{*table, object_site.path + ".material", object_site.subject, "material."};
    check_keys(site, material_keys());
    if (auto color = read_color(site, "color")) material.color = unit_color(*color);
    if (auto ka = read_number(site, "ka")) material.ka = *ka;
    if (auto kd = read_number(site, "kd")) material.kd = *kd;
    if (auto ks = read_number(site, "ks")) material.ks = *ks;
    if (auto shininess = read_number(site, "shininess")) material.shininess = *shininess;
    if (auto transmission = read_number(site, "transmission"))
        material.transmission = *transmission;
    if (auto ior = read_number(site, "ior")) material.ior = *ior;
    if (auto absorption = read_color(site, "absorption_color"))
        material.absorption_color = unit_color(*absorption);
    if (auto distance = read_number(site, "absorption_distance"))
        material.absorption_distance = *distance;
    for_each_model_parameter(
        [&](const ModelParameter& parameter, float& value) {
            if (parameter.whole) {
                if (auto whole = read_integer(site, parameter.key))
                    value = static_cast<float>(*whole);
            } else if (auto number = read_number(site, parameter.key)) {
                value = *number;
            }
        },
        material);
}

}  // namespace litkit::detail
