// SPDX-License-Identifier: MIT
// The GLSL functions printed from the model family's one definition
// (include/litkit/equations.hpp evaluated on glsl_expr's expressions):
// incidence per light kind, the spot factor, each reflection model's terms,
// the ambient and direct terms, and how a function is printed. glsl.cpp
// assembles them into the shaders.
#include "litkit/error.hpp"
#include "litkit/glsl.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "codegen/glsl_expr.hpp"
#include "litkit/equations.hpp"

namespace litkit::glsl {

namespace {

using equations::Vec3;

void add_vec3_output(Function& function, const std::string& target, const Vec3<Expr>& value) {
    function.outputs.push_back({target + ".x", value.x});
    function.outputs.push_back({target + ".y", value.y});
    function.outputs.push_back({target + ".z", value.z});
}

void add_vec3_hint(Function& function, const std::string& name, const Vec3<Expr>& pattern) {
    function.hints.push_back({name + "_x", pattern.x});
    function.hints.push_back({name + "_y", pattern.y});
    function.hints.push_back({name + "_z", pattern.z});
}

void add_incidence_outputs(Function& function, const equations::Incidence<Expr>& incidence) {
    add_vec3_output(function, "result.to_light", incidence.to_light);
    function.outputs.push_back({"result.factor", incidence.factor});
}

}  // namespace

Function directional_incidence_function() {
    Function function;
    function.doc =
        "Directional light: L = -normalize(direction), f = 1.\n"
        "travel_unit: the normalised direction the light travels.";
    function.return_type = "Incidence";
    function.name = "directional_incidence";
    function.parameters = "vec3 travel_unit";
    add_incidence_outputs(function, equations::directional_incidence(vec3_variable("travel_unit")));
    return function;
}

Function point_incidence_function() {
    Function function;
    function.doc =
        "Point light: L = normalize(position - p),\n"
        "f = 1 / (k_c + k_l*d + k_q*d^2) with d = |position - p| and attenuation = (k_c, k_l, "
        "k_q).";
    function.return_type = "Incidence";
    function.name = "point_incidence";
    function.parameters = "vec3 light_position, vec3 attenuation, vec3 p";
    const Vec3<Expr> light_position = vec3_variable("light_position");
    const Vec3<Expr> attenuation = vec3_variable("attenuation");
    const Vec3<Expr> p = vec3_variable("p");
    add_incidence_outputs(function, equations::point_incidence(light_position, attenuation, p));

    const Vec3<Expr> to_light = light_position - p;
    const Expr distance = equations::length(to_light);
    add_vec3_hint(function, "to_light", to_light);
    function.hints.push_back({"light_distance", distance});
    function.hints.push_back({"inv_distance", Expr(1.0f) / distance});
    return function;
}

Function spot_factor_function() {
    Function function;
    function.doc =
        "Spot cone: c = -L.axis; s = c^exponent * w where c >= cos(cutoff) (0^0 = 1),\n"
        "else 0; w = 1 where c >= cos_inner, else t^2(3 - 2t) with\n"
        "t = (c - cos_cutoff)/(cos_inner - cos_cutoff) (the penumbra; no smoothstep,\n"
        "which is undefined for equal edges). axis_unit: the normalised spot\n"
        "direction; cos_cutoff and cos_inner the cosines of the outer and inner\n"
        "half-angles; the comparisons allow 1e-6 so that the cone's boundary is inside.";
    function.return_type = "float";
    function.name = "spot_factor";
    function.parameters =
        "vec3 to_light, vec3 axis_unit, float cos_cutoff, float cos_inner, float exponent";
    const Vec3<Expr> to_light = vec3_variable("to_light");
    const Vec3<Expr> axis_unit = vec3_variable("axis_unit");
    function.outputs.push_back(
        {"", equations::spot_factor(to_light, axis_unit, Expr::variable("cos_cutoff"),
                                    Expr::variable("cos_inner"), Expr::variable("exponent"))});
    function.hints.push_back({"c", -equations::dot(to_light, axis_unit)});
    return function;
}

Function reflection_terms_function(Reflection reflection) {
    Function function;
    function.return_type = "Reflected";
    function.name = "reflect_light";
    function.parameters = "vec3 normal, vec3 to_light, vec3 to_eye, Material material";
    const Vec3<Expr> normal = vec3_variable("normal");
    const Vec3<Expr> to_light = vec3_variable("to_light");
    const Vec3<Expr> to_eye = vec3_variable("to_eye");
    const equations::MaterialT<Expr> material = material_variable("material");
    const equations::Reflected<Expr> reflected =
        equations::with_reflection(reflection, [&](auto model) {
            return equations::reflect<decltype(model)::value>(normal, to_light, to_eye, material);
        });
    function.outputs.push_back({"result.diffuse", reflected.diffuse});
    add_vec3_output(function, "result.color", reflected.color);
    function.outputs.push_back({"result.specular", reflected.specular});

    std::string summary;
    for (const ReflectionModel& model : reflection_models())
        if (model.id == reflection) summary = model.summary;
    function.doc = "The " + std::string(to_string(reflection)) +
                   " reflection model: the diffuse weight and colour\n(k_d*D and C for most "
                   "models) and the specular S. " +
                   summary + "\nnormal, to_light (L) and to_eye (V) are unit vectors.";

    // Names for what the equations name, where the model computes them.
    const Expr n_dot_l = equations::dot(normal, to_light);
    function.hints.push_back({"n_dot_l", n_dot_l});
    const Expr two_n_dot_l = Expr(2.0f) * n_dot_l;
    const Vec3<Expr> reflected_direction = two_n_dot_l * normal - to_light;
    function.hints.push_back({"two_n_dot_l", two_n_dot_l});
    add_vec3_hint(function, "reflected", reflected_direction);
    function.hints.push_back({"r_dot_v", equations::dot(reflected_direction, to_eye)});
    function.hints.push_back({"wrapped", Expr(0.5f) * n_dot_l + Expr(0.5f)});
    const Vec3<Expr> l_plus_v = to_light + to_eye;
    const Expr l_plus_v_length = equations::length(l_plus_v);
    add_vec3_hint(function, "l_plus_v", l_plus_v);
    function.hints.push_back({"l_plus_v_length", l_plus_v_length});
    function.hints.push_back({"inv_l_plus_v_length", Expr(1.0f) / l_plus_v_length});
    const Vec3<Expr> halfway = equations::normalize(l_plus_v);
    add_vec3_hint(function, "halfway", halfway);
    function.hints.push_back({"n_dot_h", equations::dot(normal, halfway)});
    function.hints.push_back({"n_dot_v", max(equations::dot(normal, to_eye), Expr(0.0f))});
    return function;
}

Function ambient_term_function() {
    Function function;
    function.doc = "Ambient light: k_a * C * I_L, per channel.";
    function.return_type = "vec3";
    function.name = "ambient_term";
    function.parameters = "vec3 radiance, Material material";
    add_vec3_output(
        function, "result",
        equations::ambient_term(vec3_variable("radiance"), material_variable("material")));
    return function;
}

Function direct_term_function() {
    Function function;
    function.doc =
        "Any other light: f * I_L * (k_d * D * C + k_s * S), per channel;\n"
        "the specular part takes the light's colour.";
    function.return_type = "vec3";
    function.name = "direct_term";
    function.parameters = "vec3 radiance, float factor, Reflected reflected, Material material";
    const equations::MaterialT<Expr> material = material_variable("material");
    const equations::Reflected<Expr> reflected{Expr::variable("reflected.diffuse"),
                                               vec3_variable("reflected.color"),
                                               Expr::variable("reflected.specular")};
    add_vec3_output(function, "result",
                    equations::direct_term(vec3_variable("radiance"), Expr::variable("factor"),
                                           reflected, material));
    function.hints.push_back({"diffuse", reflected.diffuse});
    function.hints.push_back({"specular", material.ks * reflected.specular});
    return function;
}

Function unit_vector_function() {
    Function function;
    function.doc =
        "v / |v| as equations::normalize computes it, (1 / sqrt(v.v)) * v: the very\n"
        "operations of the CPU path (GLSL's normalize may use inversesqrt).";
    function.return_type = "vec3";
    function.name = "unit_vector";
    function.parameters = "vec3 v";
    const Vec3<Expr> v = vec3_variable("v");
    add_vec3_output(function, "result", equations::normalize(v));
    function.hints.push_back({"inv_length", Expr(1.0f) / equations::length(v)});
    return function;
}

std::string print_function(const Function& function, const PrintOptions& options) {
    std::string text;
    std::size_t start = 0;
    while (start <= function.doc.size()) {
        std::size_t end = function.doc.find('\n', start);
        if (end == std::string::npos) end = function.doc.size();
        text += "// " + function.doc.substr(start, end - start) + "\n";
        start = end + 1;
    }
    text += function.return_type + " " + function.name + "(" + function.parameters + ") {\n";
    const Statements body = statements(function.outputs, function.hints, options, "    ");
    text += body.temporaries;
    if (function.return_type == "float") {
        text += body.assignments;  // return ...;
    } else {
        text += "    " + function.return_type + " result;\n" + body.assignments +
                "    return result;\n";
    }
    return text + "}\n";
}

PrintOptions shader_print_options() {
    PrintOptions options;
    options.pow_function = "power";
    return options;
}

}  // namespace litkit::glsl
