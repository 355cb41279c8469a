// SPDX-License-Identifier: MIT
// The per-point evaluator: Material, Light, shade() and shade_terms(), for
// checking one point's arithmetic by hand (docs/spec.md §4).
#include <pybind11/stl.h>

#include <type_traits>
#include <variant>
#include <vector>

#include "convert.hpp"

namespace litkit_python {

namespace {

std::string type_of(const litkit::Light& light) {
    return std::string(litkit::light_kind_name(light.kind));
}

// A light from the keys a scene file's [[lights]] entry has (colour 0-1 here,
// as litkit::Light holds it). Keys that the type does not have must be left out.
litkit::Light make_light(const std::string& type, std::optional<glm::vec3> position,
                         std::optional<glm::vec3> direction, glm::vec3 color, float intensity,
                         std::optional<glm::vec3> attenuation, std::optional<float> cutoff,
                         std::optional<float> exponent, std::optional<float> penumbra) {
    auto refuse = [&](const char* key, bool given) {
        if (given) throw litkit::ArgumentError("Light: a " + type + " light has no " + key);
    };
    auto need = [&](const char* key, bool given) {
        if (!given) throw litkit::ArgumentError("Light: a " + type + " light needs a " + key);
    };
    const std::optional<litkit::LightKind> kind = litkit::parse_light_kind(type);
    if (!kind) unknown("light type", type, litkit::light_kind_names);
    litkit::Light light;
    light.color = color;
    light.intensity = intensity;
    light.kind = *kind;
    if (!std::holds_alternative<litkit::SpotLight>(light.kind)) {
        refuse("cutoff", cutoff.has_value());
        refuse("exponent", exponent.has_value());
        refuse("penumbra", penumbra.has_value());
    }
    if (std::holds_alternative<litkit::AmbientLight>(light.kind)) {
        refuse("position", position.has_value());
        refuse("direction", direction.has_value());
        refuse("attenuation", attenuation.has_value());
    } else if (auto* directional = std::get_if<litkit::DirectionalLight>(&light.kind)) {
        refuse("position", position.has_value());
        refuse("attenuation", attenuation.has_value());
        need("direction", direction.has_value());
        directional->direction = *direction;
    } else if (auto* point = std::get_if<litkit::PointLight>(&light.kind)) {
        refuse("direction", direction.has_value());
        need("position", position.has_value());
        point->position = *position;
        if (attenuation) point->attenuation = *attenuation;
    } else if (auto* cone = std::get_if<litkit::SpotLight>(&light.kind)) {
        need("position", position.has_value());
        need("direction", direction.has_value());
        cone->position = *position;
        cone->direction = *direction;
        if (attenuation) cone->attenuation = *attenuation;
        if (cutoff) cone->cutoff_degrees = *cutoff;
        if (exponent) cone->exponent = *exponent;
        if (penumbra) cone->penumbra = *penumbra;
    }
    return light;
}

py::dict terms_dict(const litkit::LightTerms& terms) {
    py::dict intermediates;
    for (const auto& [name, value] : terms.intermediates) intermediates[py::str(name)] = value;
    py::dict d;
    d["ambient"] = terms.ambient;
    d["to_light"] = terms.to_light;
    d["factor"] = terms.factor;
    d["diffuse"] = terms.diffuse;
    d["specular"] = terms.specular;
    d["weight"] = terms.weight;
    d["color"] = terms.color;
    d["intermediates"] = intermediates;
    d["contribution"] = terms.contribution;
    return d;
}

void bind_material(py::module_& module) {
    const litkit::Material defaults;
    py::class_<litkit::Material>(module, "Material",
                                 "Surface coefficients; color per channel in 0-1.")
        .def(py::init([](glm::vec3 color, float ka, float kd, float ks, float shininess,
                         float sigma, float roughness, float f0, float bands, float minnaert_k,
                         float transmission, float ior, glm::vec3 absorption_color,
                         float absorption_distance) {
                 return litkit::Material{.color = color,
                                         .ka = ka,
                                         .kd = kd,
                                         .ks = ks,
                                         .shininess = shininess,
                                         .sigma = sigma,
                                         .roughness = roughness,
                                         .f0 = f0,
                                         .bands = bands,
                                         .minnaert_k = minnaert_k,
                                         .transmission = transmission,
                                         .ior = ior,
                                         .absorption_color = absorption_color,
                                         .absorption_distance = absorption_distance};
             }),
             py::kw_only(), py::arg("color") = defaults.color, py::arg("ka") = defaults.ka,
             py::arg("kd") = defaults.kd, py::arg("ks") = defaults.ks,
             py::arg("shininess") = defaults.shininess, py::arg("sigma") = defaults.sigma,
             py::arg("roughness") = defaults.roughness, py::arg("f0") = defaults.f0,
             py::arg("bands") = defaults.bands, py::arg("minnaert_k") = defaults.minnaert_k,
             py::arg("transmission") = defaults.transmission, py::arg("ior") = defaults.ior,
             py::arg("absorption_color") = defaults.absorption_color,
             py::arg("absorption_distance") = defaults.absorption_distance)
        .def_readwrite("color", &litkit::Material::color)
        .def_readwrite("ka", &litkit::Material::ka)
        .def_readwrite("kd", &litkit::Material::kd)
        .def_readwrite("ks", &litkit::Material::ks)
        .def_readwrite("shininess", &litkit::Material::shininess)
        .def_readwrite("sigma", &litkit::Material::sigma)
        .def_readwrite("roughness", &litkit::Material::roughness)
        .def_readwrite("f0", &litkit::Material::f0)
        .def_readwrite("bands", &litkit::Material::bands)
        .def_readwrite("minnaert_k", &litkit::Material::minnaert_k)
        // docs/spec.md §10.1: refraction, without effect while transmission is 0.
        .def_readwrite("transmission", &litkit::Material::transmission,
                       "Share of ambient and diffuse light replaced by refraction, 0-1")
        .def_readwrite("ior", &litkit::Material::ior, "Refractive index of the inside, 1-3")
        .def_readwrite("absorption_color", &litkit::Material::absorption_color,
                       "Colour white light turns into after absorption_distance inside, 0-1")
        .def_readwrite("absorption_distance", &litkit::Material::absorption_distance,
                       "Distance inside after which white light is absorption_color (> 0)");
}

void bind_light(py::module_& module) {
    py::class_<litkit::Light>(module, "Light",
                              "A light: type ambient, directional, point or spot; color 0-1.")
        .def(py::init(&make_light), py::arg("type"), py::kw_only(),
             py::arg("position") = py::none(), py::arg("direction") = py::none(),
             py::arg("color") = glm::vec3(1.0f), py::arg("intensity") = 1.0f,
             py::arg("attenuation") = py::none(), py::arg("cutoff") = py::none(),
             py::arg("exponent") = py::none(), py::arg("penumbra") = py::none())
        .def_property_readonly("type", &type_of)
        .def_readwrite("color", &litkit::Light::color)
        .def_readwrite("intensity", &litkit::Light::intensity)
        .def("__repr__", [](const litkit::Light& light) {
            return std::string("<litkit.Light ") + type_of(light) + ">";
        });
}

}  // namespace

void bind_lighting(py::module_& module) {
    bind_material(module);
    bind_light(module);
    module.def(
        "shade",
        [](const std::string& reflection, const litkit::Material& material,
           const std::vector<litkit::Light>& lights, const glm::vec3& position,
           const glm::vec3& normal, const glm::vec3& eye) {
            return litkit::shade(reflection_from(reflection), material, lights, position, normal,
                                 eye);
        },
        py::arg("reflection"), py::arg("material"), py::arg("lights"), py::arg("position"),
        py::arg("normal"), py::arg("eye"),
        "The colour I at one surface point before clamping and gamma (docs/spec.md §4). "
        "normal must be unit length (within 1e-3), else litkit.ArgumentError.");
    module.def(
        "shade_terms",
        [](const std::string& reflection, const litkit::Material& material,
           const std::vector<litkit::Light>& lights, const glm::vec3& position,
           const glm::vec3& normal, const glm::vec3& eye) {
            const litkit::ShadeTerms terms = litkit::shade_terms(
                reflection_from(reflection), material, lights, position, normal, eye);
            py::list per_light;
            for (const litkit::LightTerms& light : terms.lights)
                per_light.append(terms_dict(light));
            py::dict d;
            d["lights"] = per_light;
            d["total"] = terms.total;
            return d;
        },
        py::arg("reflection"), py::arg("material"), py::arg("lights"), py::arg("position"),
        py::arg("normal"), py::arg("eye"),
        "shade() with its working: each light's L, f, D, S and the model's intermediate values.");
    module.def("reflection_models", [] {
        std::vector<std::string> names;
        for (const litkit::ReflectionModel& model : litkit::reflection_models())
            names.emplace_back(model.name);
        return names;
    });
    module.def("shading_models", [] {
        return std::vector<std::string>(litkit::shading_names.begin(), litkit::shading_names.end());
    });
    module.def("normals_weightings", [] {
        return std::vector<std::string>(litkit::normals_names.begin(), litkit::normals_names.end());
    });
    module.def("light_types", [] {
        return std::vector<std::string>(litkit::light_kind_names.begin(),
                                        litkit::light_kind_names.end());
    });
}

}  // namespace litkit_python
