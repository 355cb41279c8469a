// SPDX-License-Identifier: MIT
// docs/spec.md §6: ranges, then geometry (inside the room, overlaps, lights inside
// objects, the observer), then warnings. Each rule reports every offender,
// located at the offending value.
#include "litkit/validate.hpp"

#include "litkit/limits.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>

#include "core/scale_free.hpp"
#include "geometry/convex.hpp"
#include "litkit/shapes.hpp"
#include "scene/float_range.hpp"
#include "scene/transparency.hpp"
#include "scene/validate_internal.hpp"
#include "scene/world_mesh.hpp"

namespace litkit {

namespace {

std::string number_text(float value) {
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

std::string vector_text(const glm::vec3& v) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + s.
    std::string text("[");
    text += number_text(v.x);
    text += ", ";
    text += number_text(v.y);
    text += ", ";
    text += number_text(v.z);
    text += ']';
    return text;
}

// "lights[0] 'key'" when named, "lights[0]" otherwise (the loader's style).
std::string subject(std::string_view kind, std::size_t index, const std::string& name) {
    std::string text = std::string(kind) + "[" + std::to_string(index) + "]";
    if (!name.empty()) text += " '" + name + "'";
    return text;
}

std::string object_label(const SceneObject& object, std::size_t index) {
    return object.name.empty() ? "objects[" + std::to_string(index) + "]"
                               : "object '" + object.name + "'";
}

std::string light_label(const SceneLight& light, std::size_t index) {
    return light.name.empty() ? "lights[" + std::to_string(index) + "]"
                              : "light '" + light.name + "'";
}

// A position as a hash key: equal positions (== on each coordinate, so 0 and
// -0 are one) give equal keys.
std::string position_key(const glm::vec3& p) {
    std::string key(sizeof(float) * 3, '\0');
    const float coordinates[3] = {p.x + 0.0f, p.y + 0.0f, p.z + 0.0f};  // -0 + 0 is +0
    std::memcpy(key.data(), coordinates, sizeof coordinates);
    return key;
}

// An axis-aligned bounding box: the broad phase of the overlap and
// containment tests (two hulls can only meet where their boxes do).
struct Box {
    glm::vec3 low{0.0f};
    glm::vec3 high{0.0f};
    bool empty = true;
    bool overlaps(const Box& other) const {
        return !empty && !other.empty && low.x <= other.high.x && other.low.x <= high.x &&
               low.y <= other.high.y && other.low.y <= high.y && low.z <= other.high.z &&
               other.low.z <= high.z;
    }
    bool contains(const glm::vec3& p) const {
        return !empty && p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y &&
               p.z >= low.z && p.z <= high.z;
    }
};

Box box_of(const std::vector<glm::vec3>& points) {
    Box box;
    if (points.empty()) return box;
    box.empty = false;
    box.low = box.high = points.front();
    for (const glm::vec3& p : points) {
        box.low = glm::min(box.low, p);
        box.high = glm::max(box.high, p);
    }
    return box;
}

// For each object, the earlier objects whose boxes meet its box, in
// increasing order: sort and sweep along x, then test y and z.
std::vector<std::vector<std::size_t>> overlapping_boxes(const std::vector<Box>& boxes) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (!boxes[i].empty) order.push_back(i);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return boxes[a].low.x < boxes[b].low.x; });
    std::vector<std::vector<std::size_t>> candidates(boxes.size());
    std::vector<std::size_t> active;  // boxes whose x interval may still meet the next one
    for (const std::size_t i : order) {
        std::erase_if(active, [&](std::size_t j) { return boxes[j].high.x < boxes[i].low.x; });
        for (const std::size_t j : active) {
            if (!boxes[i].overlaps(boxes[j])) continue;
            candidates[std::max(i, j)].push_back(std::min(i, j));
        }
        active.push_back(i);
    }
    for (std::vector<std::size_t>& list : candidates) std::sort(list.begin(), list.end());
    return candidates;
}

// The sine of the angle between two non-zero vectors, in double and free of
// scale: a view of length 4e19 (whose square overflows a float) or an up of
// length 1e-30 (whose square underflows) gives the same answer as at 1.
double sine_between(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 unit_a = a / std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z)});
    const glm::dvec3 unit_b = b / std::max({std::abs(b.x), std::abs(b.y), std::abs(b.z)});
    return glm::length(glm::cross(unit_a, unit_b)) / (glm::length(unit_a) * glm::length(unit_b));
}

// 268435456 → "268,435,456".
std::string grouped(std::uint64_t value) {
    const std::string digits = std::to_string(value);
    std::string text;
    for (std::size_t at = 0; at < digits.size(); ++at) {
        if (at > 0 && (digits.size() - at) % 3 == 0) text += ',';
        text += digits[at];
    }
    return text;
}

const glm::vec3* light_position(const Light& light) {
    if (const auto* point = std::get_if<PointLight>(&light.kind)) return &point->position;
    if (const auto* spot = std::get_if<SpotLight>(&light.kind)) return &spot->position;
    return nullptr;
}

class Validator {
  public:
    Validator(const Scene& scene, const BrokenEntities& broken, std::uint64_t triangle_budget)
        : scene_(scene), broken_(broken), triangle_budget_(triangle_budget) {}

    // check_renderable: each value and entity on its own, no relations
    // between entities, no meshes built, no warnings.
    std::vector<Diagnostic> run_values_only() {
        relations_ = false;
        check_values();
        return std::move(diagnostics_);
    }

    std::vector<Diagnostic> run() {
        check_values();
        check_names();
        // Over the budget, no mesh is built: the geometric checks would
        // allocate what the budget exists to refuse.
        if (within_triangle_budget()) check_geometry();
        check_warnings();
        return std::move(diagnostics_);
    }

  private:
    void check_values() {
        check_room();
        check_output();
        check_lighting();
        check_observer();
        for (std::size_t i = 0; i < scene_.lights.size(); ++i) check_light(i);
        for (std::size_t i = 0; i < scene_.objects.size(); ++i) check_object_values(i);
    }

    // Reporting: `path` names the value ("lights[0].position"); when the file
    // did not give it (a default), point at the nearest enclosing table.
    FileLoc where(std::string path) const {
        while (!path.empty()) {
            FileLoc location = scene_.location_of(path);
            if (location.line > 0) return location;
            // "objects[1].material.kd" → "objects[1].material" → "objects[1]" → "".
            const std::size_t cut = path.back() == ']' ? path.rfind('[') : path.rfind('.');
            path.resize(cut == std::string::npos ? 0 : cut);
        }
        return {};
    }
    void report(Severity severity, const std::string& path, const std::string& who,
                const std::string& message) {
        diagnostics_.push_back(
            Diagnostic{where(path), severity, who.empty() ? message : who + ": " + message});
    }
    void error(const std::string& path, const std::string& who, const std::string& message) {
        report(Severity::Error, path, who, message);
    }

    // Range helpers: "kd must be in [0, 1], found 1.5".
    void at_least(float value, float low, bool inclusive, const std::string& path,
                  const std::string& who, const std::string& key) {
        const bool ok = inclusive ? value >= low : value > low;
        if (!ok)
            error(path, who,
                  key + " must be " + (inclusive ? "≥ " : "> ") + number_text(low) + ", found " +
                      number_text(value));
    }
    void in_range(float value, float low, float high, const std::string& path,
                  const std::string& who, const std::string& key) {
        if (!(value >= low && value <= high))
            error(path, who,
                  key + " must be in [" + number_text(low) + ", " + number_text(high) +
                      "], found " + number_text(value));
    }
    void integer_in(int value, int low, int high, const std::string& path, const std::string& who,
                    const std::string& key) {
        if (value < low || value > high)
            error(path, who,
                  key + " must be " + std::to_string(low) + "–" + std::to_string(high) +
                      ", found " + std::to_string(value));
    }
    // A scene read from a file holds finite numbers only (the reader refuses
    // nan and inf); these catch the ones a scene built in code may hold.
    bool finite(float value, const std::string& path, const std::string& who,
                const std::string& key) {
        if (std::isfinite(value)) return true;
        error(path, who, key + " must be a finite number, found " + number_text(value));
        return false;
    }
    bool finite(const glm::vec3& v, const std::string& path, const std::string& who,
                const std::string& key) {
        if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) return true;
        error(path, who, key + " must be finite, found " + vector_text(v));
        return false;
    }
    void non_zero(const glm::vec3& v, const std::string& path, const std::string& who,
                  const std::string& key) {
        if (v.x == 0.0f && v.y == 0.0f && v.z == 0.0f)
            error(path, who, key + " must not be the zero vector");
    }

    bool inside_room(const glm::vec3& p) const {
        const Room& room = scene_.room;
        const float slack = 1e-5f * std::max({room.width, room.height, room.depth});
        return std::abs(p.x) <= room.width / 2 + slack &&
               std::abs(p.y) <= room.height / 2 + slack && std::abs(p.z) <= room.depth / 2 + slack;
    }
    std::string room_text() const {
        const Room& room = scene_.room;
        return "the room (x in ±" + number_text(room.width / 2) + ", y in ±" +
               number_text(room.height / 2) + ", z in ±" + number_text(room.depth / 2) + ")";
    }

    void check_room() {
        const Room& room = scene_.room;
        const std::size_t before = diagnostics_.size();
        at_least(room.width, 0.0f, false, "room.width", "room", "width");
        at_least(room.height, 0.0f, false, "room.height", "room", "height");
        at_least(room.depth, 0.0f, false, "room.depth", "room", "depth");
        finite(room.width, "room.width", "room", "width");
        finite(room.height, "room.height", "room", "height");
        finite(room.depth, "room.depth", "room", "depth");
        room_ok_ = usable("room") && diagnostics_.size() == before;
        // docs/spec.md §10.1; not a size, so a bad one leaves the room usable.
        in_range(room.ior, 1.0f, 3.0f, "room.ior", "room", "ior");
    }

    // False for an entity that failed the loader's shape checks (it holds
    // defaults in place of bad values), and for everything when the file as a
    // whole had a problem such as a missing table.
    bool usable(const std::string& entity) const {
        return !broken_.contains("") && !broken_.contains(entity);
    }

    void check_output() {
        const OutputSettings& output = scene_.output;
        integer_in(output.width, 1, max_image_side, "output.width", "output", "width");
        integer_in(output.height, 1, max_image_side, "output.height", "output", "height");
        at_least(output.gamma, 0.0f, false, "output.gamma", "output", "gamma");
        finite(output.gamma, "output.gamma", "output", "gamma");
        if (!valid_sample_count(output.samples))
            error("output.samples", "output",
                  "samples must be 1, 4, 8 or 16, found " + std::to_string(output.samples));
        // Colours are 0–1 (lighting.hpp); a file's 0–255 always is.
        const glm::vec3& b = output.background;
        if (!(b.x >= 0.0f && b.x <= 1.0f && b.y >= 0.0f && b.y <= 1.0f && b.z >= 0.0f &&
              b.z <= 1.0f))
            error("output.background", "output",
                  "background must be 0–1 per channel (litkit::from_rgb8 converts 0–255), found " +
                      vector_text(b));
    }

    // docs/spec.md §9.2: crease_angle in (0, 180].
    void crease_angle(const std::optional<float>& degrees, const std::string& path,
                      const std::string& who) {
        if (degrees && !(*degrees > 0.0f && *degrees <= 180.0f))
            error(path, who,
                  "crease_angle must be in (0, 180] degrees, found " + number_text(*degrees));
    }

    void check_lighting() {
        crease_angle(scene_.crease_angle_degrees, "lighting.crease_angle", "lighting");
        integer_in(scene_.max_depth, min_max_depth, max_max_depth, "lighting.max_depth", "lighting",
                   "max_depth");
    }

    void check_observer() {
        const Observer& o = scene_.observer;
        const std::size_t before = diagnostics_.size();
        // The lower bound is docs/reliability.md's: below about 1e-7 degrees
        // a float's positions are coarser than the pixels and the picture
        // gets holes; 0.01 keeps a margin of 1000 at the largest image.
        if (!(o.fov_degrees >= smallest_fov_degrees && o.fov_degrees < 180.0f))
            error("observer.fov", "observer",
                  "fov must be in [0.01, 180) degrees, found " + number_text(o.fov_degrees));
        at_least(o.near, 0.0f, false, "observer.near", "observer", "near");
        finite(o.position, "observer.position", "observer", "position");
        finite(o.look_at, "observer.look_at", "observer", "look_at");
        finite(o.up, "observer.up", "observer", "up");
        finite(o.far, "observer.far", "observer", "far");
        // A scene read from a file had far and near compared as written (the
        // reader, check_far_beyond_near); this check is for scenes built in code.
        const bool far_near_from_file =
            scene_.locations.contains("observer.far") || scene_.locations.contains("observer.near");
        if (!far_near_from_file && !(o.far > o.near))
            error("observer.far", "observer",
                  "far (" + number_text(o.far) + ") must be greater than near (" +
                      number_text(o.near) + ")");
        observer_position_ok_ = usable("observer");
        if (!observer_position_ok_) {
            observer_ok_ = false;
            return;
        }
        const glm::vec3 view = o.look_at - o.position;
        if (view == glm::vec3(0.0f)) {
            error("observer.look_at", "observer",
                  "look_at " + vector_text(o.look_at) + " is the observer's own position");
        } else if (o.up == glm::vec3(0.0f)) {
            error("observer.up", "observer", "up must not be the zero vector");
        } else if (sine_between(glm::dvec3(o.look_at) - glm::dvec3(o.position), glm::dvec3(o.up)) <
                   1e-6) {
            error("observer.up", "observer",
                  "up " + vector_text(o.up) + " is parallel to the view direction " +
                      vector_text(view));
        }
        observer_ok_ = diagnostics_.size() == before;
        if (relations_ && room_ok_ && !inside_room(o.position))
            error("observer.position", "observer",
                  "position " + vector_text(o.position) + " is outside " + room_text());
    }

    void check_light(std::size_t index) {
        const SceneLight& scene_light = scene_.lights[index];
        const Light& light = scene_light.light;
        const std::string base = "lights[" + std::to_string(index) + "]";
        const std::string who = subject("lights", index, scene_light.name);
        at_least(light.intensity, 0.0f, true, base + ".intensity", who, "intensity");
        finite(light.intensity, base + ".intensity", who, "intensity");
        finite(light.color, base + ".color", who, "color");
        auto check_attenuation = [&](const glm::vec3& k) {
            const std::string path = base + ".attenuation";
            if (k.x < 0.0f || k.y < 0.0f || k.z < 0.0f)
                error(path, who, "attenuation coefficients must be ≥ 0, found " + vector_text(k));
            else if (k == glm::vec3(0.0f))
                error(path, who, "attenuation coefficients must not all be 0");
        };
        if (const auto* directional = std::get_if<DirectionalLight>(&light.kind)) {
            if (finite(directional->direction, base + ".direction", who, "direction"))
                non_zero(directional->direction, base + ".direction", who, "direction");
        } else if (const auto* point = std::get_if<PointLight>(&light.kind)) {
            if (finite(point->position, base + ".position", who, "position") &&
                finite(point->attenuation, base + ".attenuation", who, "attenuation"))
                check_attenuation(point->attenuation);
        } else if (const auto* spot = std::get_if<SpotLight>(&light.kind)) {
            if (finite(spot->position, base + ".position", who, "position") &&
                finite(spot->attenuation, base + ".attenuation", who, "attenuation"))
                check_attenuation(spot->attenuation);
            if (finite(spot->direction, base + ".direction", who, "direction"))
                non_zero(spot->direction, base + ".direction", who, "direction");
            if (!(spot->cutoff_degrees > 0.0f && spot->cutoff_degrees <= 90.0f))
                error(base + ".cutoff", who,
                      "cutoff must be in (0, 90] degrees, found " +
                          number_text(spot->cutoff_degrees));
            at_least(spot->exponent, 0.0f, true, base + ".exponent", who, "exponent");
            in_range(spot->penumbra, 0.0f, 1.0f, base + ".penumbra", who, "penumbra");
        }
        if (const glm::vec3* position = light_position(light);
            relations_ && position && usable(base)) {
            if (room_ok_ && !inside_room(*position))
                error(base + ".position", who,
                      "position " + vector_text(*position) + " is outside " + room_text());
            if (observer_position_ok_ && *position == scene_.observer.position)
                error(base + ".position", who,
                      "position " + vector_text(*position) + " is the observer's position");
            // Earlier lights at the same place, found by hashing (a loop over
            // every earlier light made 100,000 lights take minutes).
            std::vector<std::size_t>& same_place = light_positions_[position_key(*position)];
            for (const std::size_t other : same_place)
                error(base + ".position", who,
                      "position " + vector_text(*position) + " is also the position of " +
                          light_label(scene_.lights[other], other));
            same_place.push_back(index);
        }
    }

    void check_object_values(std::size_t index) {
        const SceneObject& object = scene_.objects[index];
        const std::string base = "objects[" + std::to_string(index) + "]";
        const std::string who = subject("objects", index, object.name);
        // Only the scale and the shape's parameters decide whether the mesh
        // can be built for the geometry checks; a bad material does not.
        std::size_t before = diagnostics_.size();
        at_least(object.scale, 0.0f, false, base + ".scale", who, "scale");
        finite(object.scale, base + ".scale", who, "scale");
        finite(object.position, base + ".position", who, "position");
        finite(object.rotation_degrees, base + ".rotation", who, "rotation");
        bool geometry_ok = diagnostics_.size() == before;
        const Material& m = object.material;
        finite(m.color, base + ".material.color", who, "material.color");
        in_range(m.ka, 0.0f, 1.0f, base + ".material.ka", who, "material.ka");
        in_range(m.kd, 0.0f, 1.0f, base + ".material.kd", who, "material.kd");
        in_range(m.ks, 0.0f, 1.0f, base + ".material.ks", who, "material.ks");
        at_least(m.shininess, 0.0f, true, base + ".material.shininess", who, "material.shininess");
        finite(m.shininess, base + ".material.shininess", who, "material.shininess");
        // docs/spec.md §9.1: checked whatever the object's model.
        for_each_model_parameter(
            [&](const ModelParameter& parameter, const float& value) {
                const std::string key = "material." + std::string(parameter.key);
                if (!parameter.whole) {
                    in_range(value, parameter.low, parameter.high, base + "." + key, who, key);
                } else if (!(value >= parameter.low && value <= parameter.high &&
                             value == std::floor(value))) {
                    error(base + "." + key, who,
                          key + " must be a whole number " + number_text(parameter.low) + "–" +
                              number_text(parameter.high) + ", found " + number_text(value));
                }
            },
            m);
        check_refraction_values(object, base, who);
        crease_angle(object.crease_angle_degrees, base + ".crease_angle", who);
        if (object.normals == Normals::File && !std::holds_alternative<MeshFileShape>(object.shape))
            error(base + ".normals", who,
                  "normals = \"file\" needs a mesh object (type = \"mesh\"); a " +
                      std::string(shape_type_name(object.shape)) +
                      " has no file normals (use mean, area, angle or max)");

        struct ShapeCheck {
            Validator& v;
            const std::string& base;
            const std::string& who;
            void positive(float value, const char* key) {
                v.at_least(value, 0.0f, false, base + "." + key, who, key);
            }
            void operator()(const CubeShape& cube) { positive(cube.size, "size"); }
            void operator()(const SphereShape& sphere) {
                positive(sphere.radius, "radius");
                v.integer_in(sphere.segments, 3, 4096, base + ".segments", who, "segments");
                v.integer_in(sphere.rings, 2, 2048, base + ".rings", who, "rings");
            }
            void operator()(const TorusShape& torus) {
                positive(torus.major_radius, "major_radius");
                positive(torus.minor_radius, "minor_radius");
                if (torus.minor_radius > 0.0f && torus.major_radius > 0.0f &&
                    !(torus.minor_radius < torus.major_radius))
                    v.error(base + ".minor_radius", who,
                            "minor_radius " + number_text(torus.minor_radius) +
                                " must be below major_radius " + number_text(torus.major_radius));
                v.integer_in(torus.segments, 3, 4096, base + ".segments", who, "segments");
                v.integer_in(torus.sides, 3, 4096, base + ".sides", who, "sides");
            }
            void operator()(const TeapotShape& teapot) {
                positive(teapot.size, "size");
                v.integer_in(teapot.subdivisions, 1, 64, base + ".subdivisions", who,
                             "subdivisions");
            }
            void operator()(const MeshFileShape&) {}
            // Checked as load_obj checks a file (the file's are checked when
            // it is read, in build_hulls).
            void operator()(const MeshDataShape& data) {
                const std::string problem =
                    data.mesh ? check_mesh_data(*data.mesh) : "the MeshDataShape holds no mesh";
                if (!problem.empty()) v.error(base + ".mesh", who, "in-memory mesh: " + problem);
            }
        };
        before = diagnostics_.size();
        std::visit(ShapeCheck{*this, base, who}, object.shape);
        shape_ok_.push_back(usable(base) && geometry_ok && diagnostics_.size() == before);
    }

    // docs/spec.md §10.1: the material's refraction keys, checked whatever
    // the transmission (as the §9.1 parameters are whatever the model); and
    // the closed-mesh rule for the teapot, which no parameter closes (a mesh
    // is checked when it is built, in build_hulls).
    void check_refraction_values(const SceneObject& object, const std::string& base,
                                 const std::string& who) {
        const Material& m = object.material;
        in_range(m.transmission, 0.0f, 1.0f, base + ".material.transmission", who,
                 "material.transmission");
        in_range(m.ior, 1.0f, 3.0f, base + ".material.ior", who, "material.ior");
        const glm::vec3& a = m.absorption_color;
        if (!(a.x >= 0.0f && a.x <= 1.0f && a.y >= 0.0f && a.y <= 1.0f && a.z >= 0.0f &&
              a.z <= 1.0f))
            error(base + ".material.absorption_color", who,
                  "material.absorption_color must be 0–1 per channel (litkit::from_rgb8 "
                  "converts 0–255), found " +
                      vector_text(a));
        if (finite(m.absorption_distance, base + ".material.absorption_distance", who,
                   "material.absorption_distance"))
            at_least(m.absorption_distance, 0.0f, false, base + ".material.absorption_distance",
                     who, "material.absorption_distance");
        if (m.transmission > 0.0f && std::holds_alternative<TeapotShape>(object.shape))
            error(base, who,
                  "transmission " + number_text(m.transmission) +
                      " needs a closed mesh (docs/spec.md §10.1), and the teapot is not closed; "
                      "use a cube, sphere, torus or closed mesh, or transmission 0");
    }

    void check_names() {
        std::map<std::string, std::string> first_use;  // name → who used it first
        auto claim = [&](const std::string& name, const std::string& path, const std::string& who) {
            if (name.empty()) return;
            auto [it, inserted] = first_use.emplace(name, who);
            if (!inserted)
                error(path + ".name", who, "name '" + name + "' is already used by " + it->second);
        };
        for (std::size_t i = 0; i < scene_.lights.size(); ++i)
            claim(scene_.lights[i].name, "lights[" + std::to_string(i) + "]",
                  subject("lights", i, ""));
        for (std::size_t i = 0; i < scene_.objects.size(); ++i)
            claim(scene_.objects[i].name, "objects[" + std::to_string(i) + "]",
                  subject("objects", i, ""));
    }

    // World-space vertices of every object whose values passed (others are
    // skipped: their meshes may be unbuildable or huge).
    void build_hulls() {
        hulls_.resize(scene_.objects.size());
        for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
            if (!shape_ok_[i]) continue;
            const SceneObject& object = scene_.objects[i];
            Mesh mesh;
            try {
                mesh = object_mesh(object, scene_.built_meshes.get());
            } catch (const IoError& failure) {
                // Point at the scene's `file` key, and keep the line inside
                // the mesh file where reading stopped.
                const FileLoc scene_place = where("objects[" + std::to_string(i) + "].file");
                if (failure.location().line > 0) {
                    // "mesh.obj:6:3: error: …": the place in the mesh file
                    // first, where an editor jumps; the scene's key after.
                    throw IoError(failure.path(),
                                  failure.reason() + " (objects[" + std::to_string(i) +
                                      "].file at " + scene_place.to_string() + ")",
                                  failure.location());
                }
                throw IoError(failure.path(), failure.reason(), scene_place);
            }
            check_orientation(i, mesh);
            // docs/spec.md §10.1: a mesh that refracts must be closed (the
            // built-in cube, sphere and torus are by construction).
            if (object.material.transmission > 0.0f &&
                (std::holds_alternative<MeshFileShape>(object.shape) ||
                 std::holds_alternative<MeshDataShape>(object.shape))) {
                const std::string problem = detail::closed_mesh_problem(object, mesh);
                if (!problem.empty())
                    error("objects[" + std::to_string(i) + "]", subject("objects", i, object.name),
                          problem);
            }
            // docs/spec.md §9.2: "file" normals need one at every face corner.
            const auto* file = std::get_if<MeshFileShape>(&object.shape);
            if (file && normal_options(scene_, object).normals == Normals::File) {
                if (auto missing = check_file_normals(*file, mesh))
                    diagnostics_.push_back(std::move(*missing));
            }
            const glm::mat4 model = object_to_world(object);
            std::vector<glm::vec3>& hull = hulls_[i].emplace();
            hull.reserve(mesh.positions.size());
            for (const glm::vec3& p : mesh.positions)
                hull.push_back(glm::vec3(model * glm::vec4(p, 1.0f)));
            // For the renderer of this scene, which would build it again.
            if (scene_.built_meshes) scene_.built_meshes->keep(object.shape, std::move(mesh));
        }
    }

    // A closed mesh (file or in memory) with a negative signed volume is
    // inside out: its faces wind clockwise seen from outside, so back-face
    // culling hides its outside and shows the far inside. Built-in shapes
    // wind correctly by construction.
    void check_orientation(std::size_t index, const Mesh& mesh) {
        const SceneObject& object = scene_.objects[index];
        const auto* file = std::get_if<MeshFileShape>(&object.shape);
        if (!file && !std::holds_alternative<MeshDataShape>(object.shape)) return;
        if (!is_closed(mesh) || !(signed_volume(mesh) < 0.0)) return;
        const std::string what = file ? "mesh file '" + file->file.filename().string() + "'"
                                      : std::string("in-memory mesh");
        report(Severity::Warning,
               "objects[" + std::to_string(index) + "]" + (file ? ".file" : ".mesh"),
               subject("objects", index, object.name),
               what +
                   " is inside out: it is closed but its faces wind clockwise seen from "
                   "outside (negative signed volume), so its outside is culled as back faces "
                   "and its inside shows; reverse the order of every face's vertices (e.g. "
                   "\"f 1 2 3\" → \"f 1 3 2\"; Blender: Mesh › Normals › Flip)");
    }

    // docs/reliability.md: the objects' triangles together, from their
    // parameters, against the budget; the error names the largest objects.
    bool within_triangle_budget() {
        std::uint64_t total = 0;
        std::vector<std::pair<std::uint64_t, std::size_t>> sizes;  // triangles, object
        for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
            if (!shape_ok_[i]) continue;
            const std::uint64_t triangles = triangles_of(scene_.objects[i].shape);
            total += triangles;
            sizes.emplace_back(triangles, i);
        }
        if (total <= triangle_budget_) return true;
        std::stable_sort(sizes.begin(), sizes.end(),
                         [](const auto& a, const auto& b) { return a.first > b.first; });
        std::string largest;
        const std::size_t named = std::min<std::size_t>(sizes.size(), 5);
        for (std::size_t k = 0; k < named; ++k) {
            if (k) largest += ", ";
            largest += object_label(scene_.objects[sizes[k].second], sizes[k].second) + " " +
                       grouped(sizes[k].first);
        }
        if (sizes.size() > named)
            largest += " and " + std::to_string(sizes.size() - named) + " more";
        const std::size_t biggest = sizes.front().second;
        error("objects[" + std::to_string(biggest) + "]",
              subject("objects", biggest, scene_.objects[biggest].name),
              "the objects need " + grouped(total) +
                  " triangles together, more than the budget of " + grouped(triangle_budget_) +
                  " (" + largest +
                  "); lower their tessellation, or raise the budget with --max-triangles "
                  "(docs/reliability.md)");
        return false;
    }

    void check_geometry() {
        build_hulls();
        boxes_.assign(hulls_.size(), Box{});
        for (std::size_t i = 0; i < hulls_.size(); ++i)
            if (hulls_[i]) boxes_[i] = box_of(*hulls_[i]);
        const std::vector<std::vector<std::size_t>> candidates = overlapping_boxes(boxes_);
        for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
            if (!hulls_[i]) continue;
            const std::string base = "objects[" + std::to_string(i) + "]";
            const std::string who = subject("objects", i, scene_.objects[i].name);
            if (room_ok_) {
                for (const glm::vec3& p : *hulls_[i]) {
                    if (!inside_room(p)) {
                        error(base + ".position", who,
                              "object reaches outside " + room_text() + ", e.g. at " +
                                  vector_text(p));
                        break;
                    }
                }
            }
            for (const std::size_t j : candidates[i]) {
                if (hulls_intersect(*hulls_[i], *hulls_[j]))
                    error(base + ".position", who,
                          "overlaps " + object_label(scene_.objects[j], j));
            }
            // The position is usable even when fov, near, far, look_at or up
            // are not (observer_ok_ only guards the view below).
            if (observer_position_ok_ && hull_contains(*hulls_[i], scene_.observer.position))
                error("observer.position", "observer",
                      "position " + vector_text(scene_.observer.position) + " is inside " +
                          object_label(scene_.objects[i], i));
        }
        for (std::size_t l = 0; l < scene_.lights.size(); ++l) {
            const glm::vec3* position = light_position(scene_.lights[l].light);
            if (!position || !usable("lights[" + std::to_string(l) + "]")) continue;
            for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
                if (hulls_[i] && boxes_[i].contains(*position) &&
                    hull_contains(*hulls_[i], *position))
                    error("lights[" + std::to_string(l) + "].position",
                          subject("lights", l, scene_.lights[l].name),
                          "position " + vector_text(*position) + " is inside " +
                              object_label(scene_.objects[i], i));
            }
        }
    }

    // The file a scene-wide message belongs to: the scene's file when it has
    // one (as the loader does for a missing table), none when it spans several.
    FileLoc scene_file() const {
        FileLoc location;
        for (const auto& [path, value] : scene_.locations) {
            if (location.file.empty()) location.file = value.file;
            if (value.file != location.file) return {};
        }
        return location;
    }

    void check_warnings() {
        if (scene_.lights.empty())
            diagnostics_.push_back(
                Diagnostic{scene_file(), Severity::Warning,
                           "the scene has no lights: every object will be black"});
        if (scene_.objects.empty())
            diagnostics_.push_back(Diagnostic{scene_file(), Severity::Warning,
                                              "the scene has no objects: the image will be empty"});
        if (!observer_ok_ || !usable("output")) return;
        // An object is surely out of view when all its vertices lie beyond
        // one plane of the view frustum.
        // In the scene's lengths brought to a float's range (a power of two,
        // exact), so that near · far of a room of 1e19 cannot overflow.
        const float k = float_safe_length_scale(scene_);
        const Observer o = scale_lengths(scene_.observer, k);
        const float aspect = static_cast<float>(scene_.output.width) /
                             static_cast<float>(std::max(1, scene_.output.height));
        if (!(aspect > 0.0f)) return;
        const glm::mat4 view_projection =
            glm::perspective(glm::radians(o.fov_degrees), aspect, o.near, o.far) *
            scale_free::look_at(o.position, o.look_at, o.up);
        for (std::size_t i = 0; i < hulls_.size(); ++i) {
            if (!hulls_[i] || hulls_[i]->empty()) continue;
            bool outside[6] = {true, true, true, true, true, true};
            for (const glm::vec3& p : *hulls_[i]) {
                const glm::vec4 c = view_projection * glm::vec4(k * p, 1.0f);
                const float distances[6] = {c.w + c.x, c.w - c.x, c.w + c.y,
                                            c.w - c.y, c.w + c.z, c.w - c.z};
                for (int k = 0; k < 6; ++k) outside[k] = outside[k] && distances[k] < 0.0f;
            }
            if (std::find(std::begin(outside), std::end(outside), true) != std::end(outside))
                report(Severity::Warning, "objects[" + std::to_string(i) + "]",
                       subject("objects", i, scene_.objects[i].name),
                       "object is entirely outside the view");
        }
    }

    const Scene& scene_;
    const BrokenEntities& broken_;
    std::uint64_t triangle_budget_;
    std::vector<Diagnostic> diagnostics_;
    bool room_ok_ = true;
    bool observer_ok_ = true;           // the whole view is usable
    bool observer_position_ok_ = true;  // the position alone is usable
    std::vector<bool> shape_ok_;
    std::vector<std::optional<std::vector<glm::vec3>>> hulls_;  // build_hulls(), per object
    std::vector<Box> boxes_;  // each hull's bounding box (empty: no hull)
    bool relations_ = true;   // false: check_renderable (no relations between entities)
    std::unordered_map<std::string, std::vector<std::size_t>> light_positions_;
};

}  // namespace

std::vector<Diagnostic> validate_scene(const Scene& scene, const BrokenEntities& broken,
                                       std::uint64_t triangle_budget) {
    return Validator(scene, broken, triangle_budget).run();
}

std::vector<Diagnostic> validate_scene(const Scene& scene) {
    return validate_scene(scene, BrokenEntities{}, default_triangle_budget);
}

std::vector<Diagnostic> validate_scene(const Scene& scene, std::uint64_t triangle_budget) {
    return validate_scene(scene, {}, triangle_budget);
}

void check_renderable(const Scene& scene) {
    std::vector<Diagnostic> errors =
        Validator(scene, {}, default_triangle_budget).run_values_only();
    if (!errors.empty()) throw SceneError(std::move(errors));
}

std::uint64_t triangles_of(const Shape& shape) {
    struct Count {
        std::uint64_t operator()(const CubeShape&) const { return 12; }
        std::uint64_t operator()(const SphereShape& s) const {  // make_sphere's reserve
            return 2 * static_cast<std::uint64_t>(std::max(s.segments, 0)) *
                   static_cast<std::uint64_t>(std::max(s.rings - 1, 0));
        }
        std::uint64_t operator()(const TorusShape& t) const {
            return 2 * static_cast<std::uint64_t>(std::max(t.segments, 0)) *
                   static_cast<std::uint64_t>(std::max(t.sides, 0));
        }
        std::uint64_t operator()(const TeapotShape& t) const {  // 32 patches, s² quads each
            const auto s = static_cast<std::uint64_t>(std::max(t.subdivisions, 0));
            return 32 * 2 * s * s;
        }
        std::uint64_t operator()(const MeshFileShape&) const { return 0; }
        std::uint64_t operator()(const MeshDataShape& data) const {
            return data.mesh ? data.mesh->triangles.size() : 0;
        }
    };
    return std::visit(Count{}, shape);
}

}  // namespace litkit
