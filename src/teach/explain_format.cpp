// SPDX-License-Identifier: MIT
// litkit explain's two forms: text for reading, JSON for programs.
#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <string>
#include <variant>

#include "litkit/explain.hpp"

#include "core/json.hpp"
#include "core/portable_math.hpp"
#include "core/scale_free.hpp"
#include "teach/explain_text.hpp"

namespace litkit {

namespace {

using detail::json_vec;
using detail::num;
using detail::object_label;
using detail::vec;

std::string light_type(const Light& light) { return std::string(light_kind_name(light.kind)); }

std::string light_label(const Scene& scene, std::size_t index) {
    const SceneLight& light = scene.lights[index];
    return "lights[" + std::to_string(index) + "]" +
           (light.name.empty() ? "" : " '" + light.name + "'") + " (" + light_type(light.light) +
           ")";
}

// The lines of one evaluation of docs/spec.md §4 at a point.
std::string evaluation_lines(const PointEvaluation& point, const Scene& scene,
                             const Material& material, const std::string& indent) {
    std::string text;
    text += indent + "p = " + vec(point.position) + "\n";
    text += indent + "N = " + vec(point.normal) + "\n";
    text += indent + "V = normalize(eye - p) = " + vec(point.to_eye) + "   (eye " +
            vec(scene.observer.position) + ")\n";
    text += indent + "C = " + vec(material.color) + ", k_a = " + num(material.ka) +
            ", k_d = " + num(material.kd) + ", k_s = " + num(material.ks) +
            ", alpha = " + num(material.shininess) + "\n";
    for (std::size_t i = 0; i < point.terms.lights.size() && i < scene.lights.size(); ++i) {
        const LightTerms& terms = point.terms.lights[i];
        const Light& light = scene.lights[i].light;
        text += indent + light_label(scene, i) + ": I_L = " + vec(light.radiance()) + "\n";
        if (terms.ambient) {
            text += indent + "  ambient: k_a * C * I_L = " + vec(terms.contribution) + "\n";
            continue;
        }
        text += indent + "  L = " + vec(terms.to_light) + ", f = " + num(terms.factor);
        if (const auto* point_light = std::get_if<PointLight>(&light.kind)) {
            text += "   (d = " + num(glm::length(point_light->position - point.position)) + ")";
        } else if (const auto* spot = std::get_if<SpotLight>(&light.kind)) {
            const float c = -glm::dot(terms.to_light, scale_free::unit(spot->direction));
            text +=
                "   (d = " + num(glm::length(spot->position - point.position)) + ", c = " + num(c) +
                ", cos(cutoff) = " + num(static_cast<float>(cos_degrees(spot->cutoff_degrees))) +
                ")";
        }
        text += "\n";
        text += indent + "  N.L = " + num(glm::dot(point.normal, terms.to_light)) +
                ", D = " + num(terms.diffuse) + ", S = " + num(terms.specular) + "\n";
        if (!terms.intermediates.empty()) {
            text += indent + " ";
            for (const auto& [name, value] : terms.intermediates)
                text += " " + name + " = " + num(value);
            text += "\n";
        }
        text += indent + "  f * I_L * (" + num(terms.weight) + " * " + vec(terms.color) +
                " + k_s * S) = " + vec(terms.contribution) + "\n";
    }
    text += indent + "sum I = " + vec(point.terms.total) + "\n";
    return text;
}

std::string json_lights(const PointEvaluation& point, const Scene& scene) {
    std::string out = "[";
    for (std::size_t i = 0; i < point.terms.lights.size() && i < scene.lights.size(); ++i) {
        const LightTerms& terms = point.terms.lights[i];
        out += std::string(i ? ", " : "") + "{\"name\": " + json::string(scene.lights[i].name) +
               ", \"type\": " + json::string(light_type(scene.lights[i].light)) +
               ", \"to_light\": " + json_vec(terms.to_light) +
               ", \"factor\": " + json::number(terms.factor) +
               ", \"diffuse\": " + json::number(terms.diffuse) +
               ", \"specular\": " + json::number(terms.specular) + ", \"intermediates\": {";
        for (std::size_t k = 0; k < terms.intermediates.size(); ++k)
            out += std::string(k ? ", " : "") + json::string(terms.intermediates[k].first) + ": " +
                   json::number(terms.intermediates[k].second);
        out += "}, \"contribution\": " + json_vec(terms.contribution) + "}";
    }
    return out + "]";
}

glm::vec3 clamped(const glm::vec3& sum) {
    auto one = [](float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; };
    return {one(sum.x), one(sum.y), one(sum.z)};
}

std::string rgb_text(const Rgb8& rgb) {
    return "(" + std::to_string(rgb[0]) + ", " + std::to_string(rgb[1]) + ", " +
           std::to_string(rgb[2]) + ")";
}

// docs/spec.md §11: each sample's L_k and their mean, which gamma turns
// into the pixel.
std::string samples_text(const PixelExplanation& e, const Scene& scene) {
    std::string text = "\nanti-aliasing (docs/spec.md §11): " + std::to_string(e.samples.size()) +
                       " samples, each lit as a pixel centre would be, its light L clamped to\n"
                       "[0, 1] (the background's: its colour ^ gamma); the pixel is their mean:\n";
    glm::vec3 sum{0.0f};
    for (std::size_t k = 0; k < e.samples.size(); ++k) {
        const SampleProbe& sample = e.samples[k];
        text += "  sample " + std::to_string(k) + " at (" + num(sample.position.x) + ", " +
                num(sample.position.y) + "): " +
                (sample.hit ? object_label(scene, sample.object) : std::string("background")) +
                ", L = " + vec(sample.light) + "\n";
        sum += sample.light;
    }
    text += "mean = " + vec(sum / static_cast<float>(e.samples.size())) + "\n";
    if (e.gamma != 1.0f)
        text += "gamma " + num(e.gamma) + ": each channel ^ (1/" + num(e.gamma) + ")\n";
    text += "rgb = round(255 * that) = " + rgb_text(e.rgb) + "\n";
    return text;
}

std::string samples_json(const PixelExplanation& e) {
    std::string out = ", \"samples\": [";
    glm::vec3 sum{0.0f};
    for (std::size_t k = 0; k < e.samples.size(); ++k) {
        const SampleProbe& sample = e.samples[k];
        out += std::string(k ? ", " : "") + "{\"position\": [" + json::number(sample.position.x) +
               ", " + json::number(sample.position.y) +
               "], \"hit\": " + (sample.hit ? "true" : "false");
        if (sample.hit) out += ", \"object_index\": " + std::to_string(sample.object);
        out += ", \"light\": " + json_vec(sample.light) + "}";
        sum += sample.light;
    }
    return out + "], \"mean\": " + json_vec(sum / static_cast<float>(e.samples.size()));
}

}  // namespace

std::string explanation_text(const PixelExplanation& e, const Scene& scene) {
    std::string text = "pixel (" + std::to_string(e.x) + ", " + std::to_string(e.y) + ") of the " +
                       std::to_string(scene.output.width) + "x" +
                       std::to_string(scene.output.height) + " image\n";
    if (!e.hit && !e.samples.empty())
        return text + "no object covers its centre\n" + samples_text(e, scene);
    if (!e.hit) {
        return text + "no object covers it: the background colour, as given (no gamma)\nrgb = " +
               rgb_text(e.rgb) + "\n";
    }
    if (!e.samples.empty()) text += "at its centre (one sample; all of them below):\n";
    const Material& material = scene.objects[e.object].material;
    text += "visible: " + object_label(scene, e.object) + ", triangle " +
            std::to_string(e.triangle) +
            (e.clipped ? " (a piece of it: it crosses the near plane)" : "") + "\n";
    text += "models: reflection " + std::string(to_string(e.reflection)) + ", shading " +
            std::string(to_string(e.shading)) + "\n";
    text += "corners (world space, docs/spec.md §2):\n";
    for (int k = 0; k < 3; ++k) {
        const auto i = static_cast<std::size_t>(k);
        text += "  v" + std::to_string(k) + " = " + vec(e.corners[i]) + ", vertex normal (DD9) " +
                vec(e.corner_normals[i]) + "\n";
    }
    text += "face normal (DD8, in the mesh's winding) = " + vec(e.face_normal) + "\n";
    text += "perspective-correct weights of the corners at the pixel centre: (" +
            num(e.weights[0]) + ", " + num(e.weights[1]) + ", " + num(e.weights[2]) + ")\n\n";
    switch (e.shading) {
        case Shading::Flat:
            text +=
                "flat shading (docs/spec.md §3): lit once, at the centroid, with the face normal\n";
            text += evaluation_lines(e.evaluations.at(0), scene, material, "  ");
            break;
        case Shading::Gouraud:
            text +=
                "gouraud shading (docs/spec.md §3): lit at each corner with its vertex normal,\n"
                "the unclamped colours mixed with the weights\n";
            for (std::size_t k = 0; k < e.evaluations.size(); ++k) {
                text += "  corner v" + std::to_string(k) + ":\n";
                text += evaluation_lines(e.evaluations[k], scene, material, "    ");
            }
            text += "  I = w0 * I0 + w1 * I1 + w2 * I2\n";
            break;
        case Shading::Faceted:
            text +=
                "faceted shading (docs/spec.md §9.2): lit at the pixel, p interpolated from the\n"
                "corners with the weights, N the face normal\n";
            text += evaluation_lines(e.evaluations.at(0), scene, material, "  ");
            break;
        default:
            text += std::string(to_string(e.shading)) +
                    " shading (docs/spec.md §3): lit at the pixel, p and N interpolated from the\n"
                    "corners with the weights, N renormalised (DD10)\n";
            text += evaluation_lines(e.evaluations.at(0), scene, material, "  ");
            break;
    }
    const glm::vec3 c = clamped(e.sum);
    if (!e.ray_tree.empty()) {
        text +=
            "  glass (t > 0): of I above, the specular part I_s stays and t of the rest I_ad\n"
            "  gives way to what the rays below bring, t [F L(R) + (1 - F) L(T)]\n\n";
        text += detail::ray_tree_text(e, scene);
        text += "L = " + vec(e.sum) + " (as the renderer computed it)\n";
    } else {
        text += "\nI = " + vec(e.sum) + " (as the renderer computed it)\n";
    }
    text += "clamp to [0, 1]: " + vec(c) + "\n";
    if (!e.samples.empty()) return text + samples_text(e, scene);
    if (e.gamma != 1.0f)
        text += "gamma " + num(e.gamma) + ": each channel ^ (1/" + num(e.gamma) + ")\n";
    text += "rgb = round(255 * that) = " + rgb_text(e.rgb) + "\n";
    return text;
}

std::string explanation_json(const PixelExplanation& e, const Scene& scene) {
    std::string out = "{\"pixel\": [" + std::to_string(e.x) + ", " + std::to_string(e.y) +
                      "], \"hit\": " + (e.hit ? "true" : "false");
    if (e.hit) {
        const std::string weights = "[" + json::number(e.weights[0]) + ", " +
                                    json::number(e.weights[1]) + ", " + json::number(e.weights[2]) +
                                    "]";
        out += ", \"object\": " +
               json::string(e.object_name.empty() ? "objects[" + std::to_string(e.object) + "]"
                                                  : e.object_name) +
               ", \"object_index\": " + std::to_string(e.object) +
               ", \"triangle\": " + std::to_string(e.triangle) +
               ", \"reflection\": " + json::string(std::string(to_string(e.reflection))) +
               ", \"shading\": " + json::string(std::string(to_string(e.shading))) +
               ", \"clipped\": " + (e.clipped ? "true" : "false") + ", \"weights\": " + weights;
        if (e.shading == Shading::Gouraud) {
            out += ", \"vertices\": [";
            for (std::size_t k = 0; k < e.evaluations.size(); ++k) {
                const PointEvaluation& v = e.evaluations[k];
                out += std::string(k ? ", " : "") + "{\"position\": " + json_vec(v.position) +
                       ", \"normal\": " + json_vec(v.normal) +
                       ", \"lights\": " + json_lights(v, scene) +
                       ", \"sum\": " + json_vec(v.terms.total) + "}";
            }
            out += "]";
            // The point of the pixel: the corners mixed with the weights.
            glm::vec3 p{0.0f};
            for (int k = 0; k < 3; ++k)
                p +=
                    e.weights[static_cast<std::size_t>(k)] * e.corners[static_cast<std::size_t>(k)];
            out += ", \"position\": " + json_vec(p) + ", \"normal\": " + json_vec(e.face_normal) +
                   ", \"lights\": []";
        } else {
            const PointEvaluation& v = e.evaluations.at(0);
            out += ", \"position\": " + json_vec(v.position) +
                   ", \"normal\": " + json_vec(v.normal) + ", \"lights\": " + json_lights(v, scene);
        }
        out += ", \"sum\": " + json_vec(e.sum) + ", \"gamma\": " + json::number(e.gamma);
        if (!e.ray_tree.empty()) out += ", \"ray_tree\": " + detail::ray_tree_json(e, scene);
    }
    if (!e.samples.empty()) out += samples_json(e);
    out += ", \"rgb\": [" + std::to_string(e.rgb[0]) + ", " + std::to_string(e.rgb[1]) + ", " +
           std::to_string(e.rgb[2]) + "]}";
    return out;
}

std::string evaluation_text(const PointEvaluation& point, const Scene& scene, Reflection reflection,
                            const Material& material) {
    std::string text = "the equations of docs/spec.md §4 with reflection " +
                       std::string(to_string(reflection)) + "\n";
    text += evaluation_lines(point, scene, material, "  ");
    const glm::vec3 c = clamped(point.terms.total);
    Rgb8 rgb{to_pixel(point.terms.total.x, scene.output.gamma),
             to_pixel(point.terms.total.y, scene.output.gamma),
             to_pixel(point.terms.total.z, scene.output.gamma)};
    text += "clamp to [0, 1]: " + vec(c) + "\n";
    if (scene.output.gamma != 1.0f) text += "gamma " + num(scene.output.gamma) + "\n";
    return text + "rgb = " + rgb_text(rgb) + "\n";
}

std::string evaluation_json(const PointEvaluation& point, const Scene& scene,
                            Reflection reflection) {
    const float g = scene.output.gamma;
    return "{\"reflection\": " + json::string(std::string(to_string(reflection))) +
           ", \"position\": " + json_vec(point.position) +
           ", \"normal\": " + json_vec(point.normal) +
           ", \"lights\": " + json_lights(point, scene) +
           ", \"sum\": " + json_vec(point.terms.total) + ", \"rgb\": [" +
           std::to_string(to_pixel(point.terms.total.x, g)) + ", " +
           std::to_string(to_pixel(point.terms.total.y, g)) + ", " +
           std::to_string(to_pixel(point.terms.total.z, g)) + "]}";
}

}  // namespace litkit
