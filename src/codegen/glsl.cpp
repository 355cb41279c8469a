#include "litkit/glsl.hpp"
#include "litkit/error.hpp"

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

// ---- The generated functions ----

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
                   " reflection model: the diffuse weight and colour\n(k_d*D and C for most models) and the specular S. " +
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

// ---- Program assembly ----

namespace {

static_assert(static_cast<int>(equations::PreparedLight::Kind::Ambient) == 0 &&
                  static_cast<int>(equations::PreparedLight::Kind::Directional) == 1 &&
                  static_cast<int>(equations::PreparedLight::Kind::Point) == 2 &&
                  static_cast<int>(equations::PreparedLight::Kind::Spot) == 3,
              "the GLSL LIGHT_* constants are the PreparedLight::Kind values");

std::string header(Reflection reflection, Shading shading, std::string_view stage) {
    return "#version 330 core\n"
           "// Generated by litkit " LITKIT_VERSION ": the " +
           std::string(stage) + " shader for reflection \"" + std::string(to_string(reflection)) +
           "\", shading \"" + std::string(to_string(shading)) +
           "\".\n"
           "// Regenerate it with `litkit export` rather than edit it.\n"
           "//\n"
           "// The lighting functions are litkit's equations (docs/user-guide.md, \"The\n"
           "// lighting models\"), generated from the same C++ templates as the CPU\n"
           "// renderer: the same operations in the same order (a compiler may still fuse\n"
           "// a * b + c into one rounding; GLSL 3.30 cannot forbid it).\n"
           "//\n"
           "// The program's interface (both stages):\n"
           "//   vertex inputs, world space:\n"
           "//     location 0  vec3 a_position\n"
           "//     location 1  vec3 a_normal     flat: the face normal (DD8), else the vertex "
           "normal (DD9;\n"
           "//                                   faceted does not use it)\n"
           "//     location 2  vec3 a_centroid   flat only: the triangle's centroid, the same at "
           "its 3 vertices\n"
           "//   uniforms:\n"
           "//     mat4 u_view_projection        world -> clip\n"
           "//     vec3 u_eye                    the observer's position\n"
           "//     Material u_material           colour C (colour / 255), k_a, k_d, k_s, "
           "shininess\n"
           "//     int u_light_count             the lights used, at most MAX_LIGHTS (a program\n"
           "//                                   specialised to a scene's lights ignores it)\n"
           "//     Light u_lights[MAX_LIGHTS]    the fields of litkit::equations::PreparedLight:\n"
           "//                                   kind (LIGHT_*), radiance I_L, position, "
           "direction\n"
           "//                                   (unit; directional: travel, spot: axis),\n"
           "//                                   attenuation (k_c, k_l, k_q), cos_cutoff and\n"
           "//                                   cos_inner (cosines of the cone's outer and inner\n"
           "//                                   half-angles), exponent\n"
           "//     float u_inv_gamma             1 / gamma\n"
           "//   fragment output: vec4 frag_color, the pixel value litkit defines, a multiple of\n"
           "//   1/255 (exact in RGBA8), alpha 1\n";
}

// The Material struct's fields for the parameters of docs/spec.md §9.1.
std::string material_parameter_fields() {
    std::string fields;
    for_each_model_parameter(
        [&](const ModelParameter& parameter, const float&) {
            fields += "    float " + std::string(parameter.key) + ";\n";
        },
        Material{});
    return fields;
}

// A light's kind as the shaders number it (LIGHT_AMBIENT ... LIGHT_SPOT):
// the index of its alternative in litkit::LightKind.
static_assert(std::is_same_v<std::variant_alternative_t<0, LightKind>, AmbientLight> &&
                  std::is_same_v<std::variant_alternative_t<1, LightKind>, DirectionalLight> &&
                  std::is_same_v<std::variant_alternative_t<2, LightKind>, PointLight> &&
                  std::is_same_v<std::variant_alternative_t<3, LightKind>, SpotLight>,
              "LightKind's alternatives are in the order of the LIGHT_* constants");

// shade() for lights whose kinds are known: one block per light, in the
// scene's order (so the sum is taken in the order equations::shade_point
// takes it), no loop and no branch on a kind; the values are still read
// from u_lights[i].
std::string unrolled_shade(std::span<const Light> lights) {
    std::string text =
        "\n"
        "// I = sum over ambient lights of k_a*C*I_L + sum over the others of\n"
        "// f*I_L*(k_d*D*C + k_s*S) at point p with unit normal N and unit V,\n"
        "// unclamped. Specialised to the scene's lights: one block per light, of its\n"
        "// kind, in the scene's order (the kinds are fixed when the program is\n"
        "// generated, the values are the uniforms u_lights[i]); the same sum, term for\n"
        "// term, as equations::shade_point.\n"
        "vec3 shade(vec3 p, vec3 normal, vec3 to_eye) {\n"
        "    vec3 total = vec3(0.0);\n";
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::string at = "u_lights[" + std::to_string(i) + "].";
        const LightKind& kind = lights[i].kind;
        const std::string kind_name(light_kind_name(kind));
        if (std::holds_alternative<AmbientLight>(kind)) {
            text += "    total = total + ambient_term(" + at + "radiance, u_material);  // light " +
                    std::to_string(i) + ": " + kind_name + "\n";
            continue;
        }
        text += "    {  // light " + std::to_string(i) + ": " + kind_name + "\n";
        if (std::holds_alternative<DirectionalLight>(kind)) {
            text += "        Incidence incidence = directional_incidence(" + at + "direction);\n";
        } else {
            text += "        Incidence incidence = point_incidence(" + at + "position, " + at +
                    "attenuation, p);\n";
            if (std::holds_alternative<SpotLight>(kind))
                text += "        incidence.factor = incidence.factor * spot_factor(incidence.to_light, " +
                        at + "direction,\n                                           " + at +
                        "cos_cutoff, " + at + "cos_inner, " + at + "exponent);\n";
        }
        text += "        Reflected reflected = reflect_light(normal, incidence.to_light, to_eye, u_material);\n"
                "        total = total + direct_term(" + at + "radiance, incidence.factor, reflected, u_material);\n"
                "    }\n";
    }
    return text + "    return total;\n}\n";
}

// `lights`: the scene's lights, for a program specialised to them; none: the
// general program, a loop over u_light_count lights of any kind.
std::string lighting_declarations(Reflection reflection, int light_capacity,
                                  std::optional<std::span<const Light>> lights) {
    std::string text =
        "\n"
        "// Light kinds: the order of litkit::equations::PreparedLight::Kind.\n"
        "const int LIGHT_AMBIENT = 0;\n"
        "const int LIGHT_DIRECTIONAL = 1;\n"
        "const int LIGHT_POINT = 2;\n"
        "const int LIGHT_SPOT = 3;\n"
        "\n"
        "struct Material {\n"
        "    vec3 color;\n"
        "    float ka;\n"
        "    float kd;\n"
        "    float ks;\n"
        "    float shininess;\n" +
        material_parameter_fields() +
        "};\n"
        "\n"
        "struct Light {\n"
        "    int kind;\n"
        "    vec3 radiance;\n"
        "    vec3 position;\n"
        "    vec3 direction;\n"
        "    vec3 attenuation;\n"
        "    float cos_cutoff;\n"
        "    float cos_inner;\n"
        "    float exponent;\n"
        "};\n"
        "\n"
        "// Where a light comes from: L (unit, towards the light) and the factor f.\n"
        "struct Incidence {\n"
        "    vec3 to_light;\n"
        "    float factor;\n"
        "};\n"
        "\n"
        "// What a light's f * I_L multiplies: the diffuse weight and colour (k_d * D\n"
        "// and C for most models) and the specular S.\n"
        "struct Reflected {\n"
        "    float diffuse;\n"
        "    vec3 color;\n"
        "    float specular;\n"
        "};\n"
        "\n"
        "const int MAX_LIGHTS = " +
        std::to_string(light_capacity) +
        ";\n"
        "\n"
        "uniform vec3 u_eye;\n"
        "uniform Material u_material;\n"
        "uniform int u_light_count;\n"
        "uniform Light u_lights[MAX_LIGHTS];\n"
        "\n"
        "// pow as C and the CPU path define it, x^0 = 1 for every x (litkit: 0^0 = 1);\n"
        "// GLSL leaves pow(0, 0) undefined.\n"
        "float power(float x, float y) {\n"
        "    return y == 0.0 ? 1.0 : pow(x, y);\n"
        "}\n";
    const PrintOptions options = shader_print_options();
    for (const Function& function :
         {unit_vector_function(), directional_incidence_function(), point_incidence_function(),
          spot_factor_function(), reflection_terms_function(reflection), ambient_term_function(),
          direct_term_function()}) {
        text += '\n';
        text += print_function(function, options);
    }
    if (lights) return text + unrolled_shade(*lights);
    text +=
        "\n"
        "// I = sum over ambient lights of k_a*C*I_L + sum over the others of\n"
        "// f*I_L*(k_d*D*C + k_s*S) at point p with unit normal N and unit V,\n"
        "// unclamped. Hand-written (the lights are uniforms here) and kept line for line\n"
        "// parallel to equations::shade_point: change one, change the other.\n"
        "vec3 shade(vec3 p, vec3 normal, vec3 to_eye) {\n"
        "    vec3 total = vec3(0.0);\n"
        "    for (int i = 0; i < u_light_count; ++i) {\n"
        "        vec3 radiance = u_lights[i].radiance;\n"
        "        Incidence incidence;\n"
        "        if (u_lights[i].kind == LIGHT_AMBIENT) {\n"
        "            total = total + ambient_term(radiance, u_material);\n"
        "            continue;\n"
        "        } else if (u_lights[i].kind == LIGHT_DIRECTIONAL) {\n"
        "            incidence = directional_incidence(u_lights[i].direction);\n"
        "        } else if (u_lights[i].kind == LIGHT_POINT) {\n"
        "            incidence = point_incidence(u_lights[i].position, u_lights[i].attenuation, "
        "p);\n"
        "        } else if (u_lights[i].kind == LIGHT_SPOT) {\n"
        "            incidence = point_incidence(u_lights[i].position, u_lights[i].attenuation, "
        "p);\n"
        "            incidence.factor =\n"
        "                incidence.factor * spot_factor(incidence.to_light, "
        "u_lights[i].direction,\n"
        "                                               u_lights[i].cos_cutoff, "
        "u_lights[i].cos_inner,\n"
        "                                               u_lights[i].exponent);\n"
        "        } else {\n"
        "            continue;  // no other kinds\n"
        "        }\n"
        "        Reflected reflected = reflect_light(normal, incidence.to_light, to_eye, "
        "u_material);\n"
        "        total = total + direct_term(radiance, incidence.factor, reflected, u_material);\n"
        "    }\n"
        "    return total;\n"
        "}\n";
    return text;
}

// litkit::to_pixel on the GPU.
// `gamma_one`: for a program specialised to a picture of gamma 1, which
// leaves the power out (a uniform branch still costs llvmpipe the power).
std::string to_pixel_function(bool gamma_one) {
    return std::string(
    "\n"
    "uniform float u_inv_gamma;\n"
    "\n"
    "// The pixel value litkit defines, round(255 * clamp(I, 0, 1)^(1/gamma)) with halves up,\n"
    "// as litkit::to_pixel computes it (NaN -> 0), divided by 255 so that the conversion\n"
    "// to RGBA8 is exact.") + (gamma_one ? " This program is for gamma 1: no power.\n" : "\n") +
    "vec3 to_pixel(vec3 intensity) {\n"
    "    vec3 c = mix(vec3(0.0), min(intensity, vec3(1.0)), greaterThan(intensity, vec3(0.0)));\n" +
    (gamma_one ? "" : "    if (u_inv_gamma != 1.0) c = pow(c, vec3(u_inv_gamma));\n") +
    "    vec3 scaled = 255.0 * c;\n"
    "    vec3 level = floor(scaled);\n"
    "    level += step(0.5, scaled - level);  // halves up (scaled - level is exact)\n"
    "    return level / 255.0;\n"
    "}\n";
}

}  // namespace

namespace {

Shaders generate_program(Reflection reflection, Shading shading, int light_capacity,
                         std::optional<std::span<const Light>> lights, bool gamma_one) {
    Shaders shaders;
    std::string& vertex = shaders.vertex;
    std::string& fragment = shaders.fragment;
    vertex = header(reflection, shading, "vertex");
    fragment = header(reflection, shading, "fragment");

    vertex +=
        "\n"
        "layout(location = 0) in vec3 a_position;\n"
        "layout(location = 1) in vec3 a_normal;\n";
    if (shading == Shading::Flat) vertex += "layout(location = 2) in vec3 a_centroid;\n";
    vertex += "\nuniform mat4 u_view_projection;\n";

    switch (shading) {
        case Shading::Flat:
            vertex += lighting_declarations(reflection, light_capacity, lights);
            vertex +=
                "\n"
                "// Flat shading: lit once per triangle, at its centroid, with the face\n"
                "// normal. All three vertices of a triangle carry the same centroid and\n"
                "// normal, so v_color is the same at each and does not depend on the\n"
                "// provoking vertex.\n"
                "flat out vec3 v_color;\n"
                "\n"
                "void main() {\n"
                "    v_color = shade(a_centroid, a_normal, unit_vector(u_eye - a_centroid));\n"
                "    gl_Position = u_view_projection * vec4(a_position, 1.0);\n"
                "}\n";
            fragment +=
                "\n"
                "// The triangle's colour, unclamped.\n"
                "flat in vec3 v_color;\n"
                "\n"
                "out vec4 frag_color;\n";
            fragment += to_pixel_function(gamma_one);
            fragment +=
                "\n"
                "void main() {\n"
                "    frag_color = vec4(to_pixel(v_color), 1.0);\n"
                "}\n";
            break;
        case Shading::Gouraud:
            vertex += lighting_declarations(reflection, light_capacity, lights);
            vertex +=
                "\n"
                "// Gouraud shading: lit at each vertex with its vertex normal; the colour,\n"
                "// unclamped, is interpolated perspective-correctly (smooth).\n"
                "out vec3 v_color;\n"
                "\n"
                "void main() {\n"
                "    v_color = shade(a_position, a_normal, unit_vector(u_eye - a_position));\n"
                "    gl_Position = u_view_projection * vec4(a_position, 1.0);\n"
                "}\n";
            fragment +=
                "\n"
                "// The interpolated vertex colours, unclamped.\n"
                "in vec3 v_color;\n"
                "\n"
                "out vec4 frag_color;\n";
            fragment += to_pixel_function(gamma_one);
            fragment +=
                "\n"
                "void main() {\n"
                "    frag_color = vec4(to_pixel(v_color), 1.0);\n"
                "}\n";
            break;
        case Shading::Phong:
            vertex +=
                "\n"
                "// Phong shading: world position and vertex normal, interpolated\n"
                "// perspective-correctly (smooth); lit per fragment.\n"
                "out vec3 v_position;\n"
                "out vec3 v_normal;\n"
                "\n"
                "void main() {\n"
                "    v_position = a_position;\n"
                "    v_normal = a_normal;\n"
                "    gl_Position = u_view_projection * vec4(a_position, 1.0);\n"
                "}\n";
            fragment +=
                "\n"
                "// World position and vertex normal, interpolated perspective-correctly.\n"
                "in vec3 v_position;\n"
                "in vec3 v_normal;\n"
                "\n"
                "out vec4 frag_color;\n";
            fragment += lighting_declarations(reflection, light_capacity, lights);
            fragment += to_pixel_function(gamma_one);
            fragment +=
                "\n"
                "// Phong shading: lit at the interpolated position with the interpolated\n"
                "// normal, renormalised (DD10).\n"
                "void main() {\n"
                "    vec3 normal = unit_vector(v_normal);\n"
                "    vec3 to_eye = unit_vector(u_eye - v_position);\n"
                "    frag_color = vec4(to_pixel(shade(v_position, normal, to_eye)), 1.0);\n"
                "}\n";
            break;
        case Shading::Faceted:
            vertex +=
                "\n"
                "// Faceted shading: the world position, interpolated perspective-correctly\n"
                "// (smooth); lit per fragment.\n"
                "out vec3 v_position;\n"
                "\n"
                "void main() {\n"
                "    v_position = a_position;\n"
                "    gl_Position = u_view_projection * vec4(a_position, 1.0);\n"
                "}\n";
            fragment +=
                "\n"
                "// World position, interpolated perspective-correctly.\n"
                "in vec3 v_position;\n"
                "\n"
                "out vec4 frag_color;\n";
            fragment += lighting_declarations(reflection, light_capacity, lights);
            fragment += to_pixel_function(gamma_one);
            fragment +=
                "\n"
                "// Faceted shading (docs/spec.md §9.2): lit at the interpolated position with\n"
                "// the face normal, from the position's screen-space derivatives. Across a\n"
                "// triangle the position moves in its plane, so dFdx(p) x dFdy(p) is\n"
                "// perpendicular to it; turned towards the eye, it is the front face's DD8\n"
                "// normal (back faces are culled), whichever way the window's y axis runs.\n"
                "void main() {\n"
                "    vec3 to_eye = unit_vector(u_eye - v_position);\n"
                "    vec3 normal = unit_vector(cross(dFdx(v_position), dFdy(v_position)));\n"
                "    if (dot(normal, to_eye) < 0.0) normal = -normal;\n"
                "    frag_color = vec4(to_pixel(shade(v_position, normal, to_eye)), 1.0);\n"
                "}\n";
            break;
    }
    return shaders;
}

}  // namespace

Shaders generate(Reflection reflection, Shading shading, int light_capacity) {
    if (light_capacity < 1) {
        throw ArgumentError("glsl::generate: the light capacity must be at least 1, not " +
                                    std::to_string(light_capacity));
    }
    return generate_program(reflection, shading, light_capacity, std::nullopt, false);
}

Shaders generate(Reflection reflection, Shading shading, std::span<const Light> lights,
                 float gamma) {
    return generate_program(reflection, shading, std::max<int>(1, static_cast<int>(lights.size())),
                            lights, gamma == 1.0f);
}

Shaders generate_for_scene(Reflection reflection, Shading shading, std::span<const Light> lights,
                           float gamma) {
    if (lights.size() <= max_specialised_lights) return generate(reflection, shading, lights, gamma);
    return generate(reflection, shading, static_cast<int>(lights.size()));
}

}  // namespace litkit::glsl
