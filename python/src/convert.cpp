// SPDX-License-Identifier: MIT
// Conversions and argument checks shared by the binding (convert.hpp).
#include "convert.hpp"

#include <utility>
#include <vector>

namespace litkit_python {

namespace {

int checked_size(const char* what, int pixels) {
    // The command line's --width/--height range (docs/reliability.md).
    if (pixels < 1 || pixels > litkit::max_image_side) {
        throw litkit::ArgumentError(std::string(what) + " must be 1-" +
                                    std::to_string(litkit::max_image_side) + " pixels, found " +
                                    std::to_string(pixels));
    }
    return pixels;
}

}  // namespace

void unknown(const std::string& what, const std::string& name,
             std::span<const std::string_view> known) {
    std::string list;
    for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    throw litkit::ArgumentError("unknown " + what + " '" + name + "'; expected one of: " + list);
}

litkit::Reflection reflection_from(const std::string& name) {
    if (const auto reflection = litkit::parse_reflection(name)) return *reflection;
    std::vector<std::string_view> known;
    for (const litkit::ReflectionModel& model : litkit::reflection_models())
        known.push_back(model.name);
    unknown("reflection model", name, known);
}

litkit::Shading shading_from(const std::string& name) {
    if (const auto shading = litkit::parse_shading(name)) return *shading;
    unknown("shading model", name, litkit::shading_names);
}

litkit::Normals normals_from(const std::string& name) {
    if (const auto normals = litkit::parse_normals(name)) return *normals;
    unknown("normals weighting", name, litkit::normals_names);
}

void Overrides::apply_to(litkit::Scene& scene) const {
    if (reflection) scene.reflection = reflection_from(*reflection);
    if (shading) scene.shading = shading_from(*shading);
    if (width) scene.output.width = checked_size("width", *width);
    if (height) scene.output.height = checked_size("height", *height);
    if (max_depth) {
        // The command line's --max-depth range (docs/spec.md §10.1).
        if (*max_depth < litkit::min_max_depth || *max_depth > litkit::max_max_depth)
            throw litkit::ArgumentError(
                "max_depth must be " + std::to_string(litkit::min_max_depth) + "-" +
                std::to_string(litkit::max_max_depth) + ", found " + std::to_string(*max_depth));
        scene.max_depth = *max_depth;
    }
    if (samples) {
        if (!litkit::valid_sample_count(*samples))
            throw litkit::ArgumentError("samples must be 1, 4, 8 or 16, found " +
                                        std::to_string(*samples));
        scene.output.samples = *samples;
    }
}

int checked_threads(int threads) {
    if (threads < 0 || threads > litkit::max_render_threads) {
        throw litkit::ArgumentError(
            "threads must be 0-" + std::to_string(litkit::max_render_threads) +
            " (0: one per hardware thread), found " + std::to_string(threads));
    }
    return threads;
}

py::array image_array(litkit::Image&& image) {
    const auto height = static_cast<py::ssize_t>(image.height);
    const auto width = static_cast<py::ssize_t>(image.width);
    auto* pixels = new std::vector<std::uint8_t>(std::move(image.rgb));
    // The capsule owns the pixels from here on, also if making the array fails.
    py::capsule owner(pixels, [](void* p) { delete static_cast<std::vector<std::uint8_t>*>(p); });
    return py::array_t<std::uint8_t>({height, width, py::ssize_t{3}}, pixels->data(), owner);
}

std::vector<litkit::Diagnostic> validate_or_throw(const litkit::Scene& scene) {
    std::vector<litkit::Diagnostic> errors;
    std::vector<litkit::Diagnostic> warnings;
    for (litkit::Diagnostic& diagnostic : litkit::validate_scene(scene)) {
        (diagnostic.severity == litkit::Severity::Error ? errors : warnings)
            .push_back(std::move(diagnostic));
    }
    if (!errors.empty()) throw litkit::SceneError(std::move(errors), std::move(warnings));
    return warnings;
}

}  // namespace litkit_python
