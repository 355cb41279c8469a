// SPDX-License-Identifier: MIT
// The glass programs (glsl_glass.hpp): docs/spec.md §10.2 in GLSL. Snell's
// law, Fresnel and Beer–Lambert are printed from litkit/refraction.hpp's
// templates, as the lighting is from equations.hpp; the hierarchy walk, the
// watertight triangle test and the ray tree's loop are written here, line
// for line after src/trace/accel.cpp and src/trace/ray_tree.cpp.
#include "codegen/glsl_glass.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "codegen/glsl_expr.hpp"
#include "codegen/glsl_parts.hpp"
#include "litkit/error.hpp"
#include "litkit/refraction.hpp"

namespace litkit::glsl {

namespace {

using equations::Vec3;

int parameter_count() {
    int count = 0;
    for_each_model_parameter([&](const ModelParameter&, const float&) { ++count; }, Material{});
    return count;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
}

Function refract_interface_function() {
    Function function;
    function.doc =
        "docs/spec.md §10.2 items 3-5 at one interface: Snell's law, the mirror\n"
        "direction and exact Fresnel (litkit::equations::refract_interface). direction\n"
        "(d) and normal (n, on the ray's side) are unit; eta = n1/n2. tir: 1 under\n"
        "total internal reflection, where refracted is the mirror direction and F = 1.";
    function.return_type = "Interface";
    function.name = "refract_interface";
    function.parameters = "vec3 direction, vec3 normal, float eta";
    const equations::Interface<Expr> at = equations::refract_interface(
        vec3_variable("direction"), vec3_variable("normal"), Expr::variable("eta"));
    function.outputs.push_back({"result.cos_incident", at.cos_incident});
    function.outputs.push_back({"result.k", at.k});
    function.outputs.push_back({"result.cos_refracted", at.cos_refracted});
    function.outputs.push_back({"result.fresnel", at.fresnel});
    for (const auto& [name, v] :
         {std::pair{"refracted", at.refracted}, {"reflected", at.reflected}}) {
        function.outputs.push_back({std::string("result.") + name + ".x", v.x});
        function.outputs.push_back({std::string("result.") + name + ".y", v.y});
        function.outputs.push_back({std::string("result.") + name + ".z", v.z});
    }
    function.outputs.push_back(
        {"result.tir", select(at.total_internal_reflection, Expr(1.0f), Expr(0.0f))});
    return function;
}

Function absorption_function() {
    Function function;
    function.doc =
        "docs/spec.md §10.2 item 7, Beer-Lambert: A = (a/255)^(length/distance) per\n"
        "channel, 0^x = 0 for x > 0 (litkit::equations::absorption).";
    function.return_type = "vec3";
    function.name = "absorption";
    function.parameters = "vec3 color, float len, float distance";
    const Vec3<Expr> a = equations::absorption(vec3_variable("color"), Expr::variable("len"),
                                               Expr::variable("distance"));
    function.outputs.push_back({"result.x", a.x});
    function.outputs.push_back({"result.y", a.y});
    function.outputs.push_back({"result.z", a.z});
    return function;
}

// reflect_model(model, ...): the reflection terms of the scene's model
// number `model`, and shade_material(p, normal, to_eye, material, model):
// shade() for any material and model (the text of shade() itself).
std::string any_model(std::span<const Reflection> models,
                      std::optional<std::span<const Light>> lights) {
    const PrintOptions options = shader_print_options();
    std::string text;
    for (std::size_t k = 0; k < models.size(); ++k) {
        Function function = reflection_terms_function(models[k]);
        function.name = "reflect_model_" + std::to_string(k);
        text += '\n' + print_function(function, options);
    }
    text +=
        "\n"
        "// The reflection terms of the scene's model number `model`.\n"
        "Reflected reflect_model(int model, vec3 normal, vec3 to_light, vec3 to_eye, Material "
        "material) {\n";
    for (std::size_t k = 0; k + 1 < models.size(); ++k)
        text += "    if (model == " + std::to_string(k) + ") return reflect_model_" +
                std::to_string(k) + "(normal, to_light, to_eye, material);\n";
    text += "    return reflect_model_" + std::to_string(models.size() - 1) +
            "(normal, to_light, to_eye, material);\n}\n";
    std::string shade = shade_text(lights);
    replace_all(shade, "vec3 shade(vec3 p, vec3 normal, vec3 to_eye)",
                "vec3 shade_material(vec3 p, vec3 normal, vec3 to_eye, Material material, int "
                "model)");
    replace_all(shade, "u_material", "material");
    replace_all(shade, "reflect_light(", "reflect_model(model, ");
    return text + "\n// shade() for any material and model of the scene." + shade;
}

// What a glass program reads of the scene's objects (u_objects).
std::string object_fetch() {
    std::string text =
        "\n"
        "uniform samplerBuffer u_objects;  // OBJECT_TEXELS texels an object\n"
        "const int OBJECT_TEXELS = " +
        std::to_string(object_texels()) +
        ";\n"
        "\n"
        "Material object_material(int o) {\n"
        "    int at = OBJECT_TEXELS * o;\n"
        "    vec4 t0 = texelFetch(u_objects, at);\n"
        "    vec4 t1 = texelFetch(u_objects, at + 1);\n"
        "    Material m;\n"
        "    m.color = t0.xyz;\n"
        "    m.ka = t0.w;\n"
        "    m.kd = t1.x;\n"
        "    m.ks = t1.y;\n"
        "    m.shininess = t1.z;\n";
    int i = 0;
    for_each_model_parameter(
        [&](const ModelParameter& parameter, const float&) {
            text += "    m." + std::string(parameter.key) + " = texelFetch(u_objects, at + " +
                    std::to_string(4 + i / 4) + ")." + "xyzw"[i % 4] + ";\n";
            ++i;
        },
        Material{});
    return text +
           "    return m;\n"
           "}\n"
           "float object_transmission(int o) { return texelFetch(u_objects, OBJECT_TEXELS * o + "
           "1).w; }\n"
           "vec4 object_absorption(int o) { return texelFetch(u_objects, OBJECT_TEXELS * o + 2); "
           "}\n"
           "// (n_o, model, smooth, clear)\n"
           "vec4 object_glass(int o) { return texelFetch(u_objects, OBJECT_TEXELS * o + 3); }\n";
}

// The hierarchy walk, the triangle test and the ray tree.
const char* const tracer_text = R"(
// ---- The ray tree of docs/spec.md §10.2, traced against the scene's triangles ----

uniform samplerBuffer u_triangles;  // 7 texels a triangle, in the hierarchy's leaf order
uniform samplerBuffer u_nodes;      // 4 texels a node: its children's boxes
uniform samplerBuffer u_faces;      // N_g of each triangle, in drawing order
uniform int u_node_count;
uniform float u_room_ior;           // n_r
uniform int u_max_depth;
uniform float u_min_distance;       // 1e-6 x the room's diagonal
uniform vec3 u_background_light;    // (background / 255)^gamma

const float NO_HIT = 3.0e38;

struct Hit {
    float t;
    int object;    // -1: none
    int triangle;  // within the object (ties go to the smaller)
    int index;     // in u_triangles
    float b1;
    float b2;
};

// Woop, Benthin and Wald's watertight test (src/trace/accel.cpp): the ray
// sheared so that it runs along +z. Rays in the room (inside < 0) hit front
// faces of any object (det > 0), rays inside object `inside` its back faces.
// GLSL 3.30 has no double for the products' exact zero case.
void intersect(vec3 origin, int kx, int ky, int kz, vec3 shear, int index, int inside,
               float t_min, inout Hit best) {
    vec4 t0 = texelFetch(u_triangles, 7 * index);
    int object = int(t0.w);
    if (inside >= 0 && object != inside) return;
    vec4 t1 = texelFetch(u_triangles, 7 * index + 1);
    vec4 t2 = texelFetch(u_triangles, 7 * index + 2);
    vec3 a = t0.xyz - origin;
    vec3 b = t1.xyz - origin;
    vec3 c = t2.xyz - origin;
    float ax = a[kx] - shear.x * a[kz], ay = a[ky] - shear.y * a[kz];
    float bx = b[kx] - shear.x * b[kz], by = b[ky] - shear.y * b[kz];
    float cx = c[kx] - shear.x * c[kz], cy = c[ky] - shear.y * c[kz];
    float u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return;
    float det = u + v + w;
    if (det == 0.0) return;
    if ((inside < 0) != (det > 0.0)) return;
    float t = (u * (shear.z * a[kz]) + v * (shear.z * b[kz]) + w * (shear.z * c[kz])) / det;
    if (!(t > t_min && t < NO_HIT)) return;
    int triangle = int(t1.w);
    if (t > best.t || (t == best.t && (object > best.object ||
                                       (object == best.object && triangle > best.triangle))))
        return;
    best = Hit(t, object, triangle, index, v / det, w / det);
}

// Where the ray enters the box lo..hi, if before `limit`; else NO_HIT.
float box_entry(vec3 lo, vec3 hi, vec3 origin, vec3 inv, float limit) {
    vec3 s0 = (lo - origin) * inv;
    vec3 s1 = (hi - origin) * inv;
    vec3 near = min(s0, s1);
    vec3 far = max(s0, s1);
    float enter = max(max(near.x, near.y), max(near.z, 0.0));
    float leave = min(min(far.x, far.y), min(far.z, limit));
    return enter <= leave ? enter : NO_HIT;
}

// The nearest hit along origin + t*d (d unit), t > t_min: the two-level
// hierarchy walked from the objects' root (node 0) for a ray in the room,
// from object `inside`'s root (node 1 + inside) for a ray inside it. Each
// node holds its two children's boxes; a leaf's triangles are found from
// its parent, the nearer inner child is taken first, and a subtree is
// skipped once its box lies beyond the nearest hit so far. A SIMD group's
// fragments run in lockstep, so the walk and the tests are two loops: each
// walks until a leaf's triangles wait (or it is done), then all test
// theirs at once (docs/design.md, "Glass through OpenGL").
Hit nearest(vec3 origin, vec3 d, int inside, float t_min) {
    Hit best = Hit(NO_HIT, -1, 0, 0, 0.0, 0.0);
    if (u_node_count == 0) return best;
    vec3 ad = abs(d);
    int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0.0) {
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    vec3 shear = vec3(d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]);
    // 1/d without infinities, so that no slab gives 0 * inf.
    vec3 inv = 1.0 / vec3(ad.x > 1e-30 ? d.x : 1e-30, ad.y > 1e-30 ? d.y : 1e-30,
                          ad.z > 1e-30 ? d.z : 1e-30);
    int stack[64];
    float entries[64];
    int sp = 0;
    int node = inside < 0 ? 0 : 1 + inside;  // -1: none (pop the stack)
    float node_entry = 0.0;
    int first = 0;  // the waiting triangles: first .. first + count - 1
    int count = 0;
    while (true) {
        while (count == 0) {
            if (node_entry > best.t) node = -1;  // beyond the nearest hit so far
            while (node < 0 && sp > 0) {
                --sp;
                if (entries[sp] <= best.t) {
                    node = stack[sp];
                    node_entry = entries[sp];
                }
            }
            if (node < 0) break;
            vec4 a_lo = texelFetch(u_nodes, 4 * node);
            vec4 a_hi = texelFetch(u_nodes, 4 * node + 1);
            vec4 b_lo = texelFetch(u_nodes, 4 * node + 2);
            vec4 b_hi = texelFetch(u_nodes, 4 * node + 3);
            int a = floatBitsToInt(a_lo.w), a_count = floatBitsToInt(a_hi.w);
            int b = floatBitsToInt(b_lo.w), b_count = floatBitsToInt(b_hi.w);
            float a_entry =
                a_count < 0 ? NO_HIT : box_entry(a_lo.xyz, a_hi.xyz, origin, inv, best.t);
            float b_entry =
                b_count < 0 ? NO_HIT : box_entry(b_lo.xyz, b_hi.xyz, origin, inv, best.t);
            // Sibling leaves hold neighbouring triangles: one range holds
            // either or both.
            bool a_leaf = a_count > 0 && a_entry < NO_HIT;
            bool b_leaf = b_count > 0 && b_entry < NO_HIT;
            first = a_leaf ? a : b;
            count = (a_leaf ? a_count : 0) + (b_leaf ? b_count : 0);
            if (a_count > 0) a_entry = NO_HIT;
            if (b_count > 0) b_entry = NO_HIT;
            if (a_entry < NO_HIT && b_entry < NO_HIT) {
                bool a_nearer = a_entry <= b_entry;
                if (sp < 64) {
                    stack[sp] = a_nearer ? b : a;
                    entries[sp] = a_nearer ? b_entry : a_entry;
                    ++sp;
                }
                node = a_nearer ? a : b;
                node_entry = a_nearer ? a_entry : b_entry;
            } else if (a_entry < NO_HIT) {
                node = a;
                node_entry = a_entry;
            } else if (b_entry < NO_HIT) {
                node = b;
                node_entry = b_entry;
            } else {
                node = -1;
            }
        }
        if (count == 0) break;  // nothing waits and nothing is left to walk
        for (int i = 0; i < count; ++i)
            intersect(origin, kx, ky, kz, shear, first + i, inside, t_min, best);
        count = 0;
    }
    return best;
}

bool same_signs(float a, float b) { return (a > 0.0 && b > 0.0) || (a < 0.0 && b < 0.0); }
bool opposite_signs(float a, float b) { return (a > 0.0 && b < 0.0) || (a < 0.0 && b > 0.0); }

// Items 2-6 at one hit: N_s on the ray's side, or N_g where N_s faces away
// from the ray or the guard fails (T must cross the face, R must not).
Interface bend(vec3 d, vec3 shading_normal, vec3 face_normal, bool entering, float eta) {
    float side = entering ? 1.0 : -1.0;
    vec3 geometric = side * face_normal;
    vec3 normal = side * shading_normal;
    if (-dot(d, normal) <= 0.0) return refract_interface(d, geometric, eta);
    Interface at = refract_interface(d, normal, eta);
    float d_n = dot(d, face_normal);
    bool crosses = at.tir > 0.5 || same_signs(dot(at.refracted, face_normal), d_n);
    bool turns_back = opposite_signs(dot(at.reflected, face_normal), d_n);
    if (!crosses || !turns_back) at = refract_interface(d, geometric, eta);
    return at;
}

float largest(vec3 v) { return max(v.x, max(v.y, v.z)); }

// One ray still to trace, with the product of the factors in front of its L.
struct Ray {
    vec3 origin;
    vec3 direction;
    vec3 weight;
    int depth;
    int inside;  // -1: the room's medium
};
const int RAY_STACK = 24;

// t * [F * L(R) + (1 - F) * L(T)] at a pixel's first hit p on glass object
// `object` (d: the pixel's unit ray; the normals unit and outward). Every
// node's light, times its weight, is added to the total as it is found: the
// same sum as the recursion of src/trace/ray_tree.cpp, in another order.
vec3 trace_bracket(int object, vec3 p, vec3 d, vec3 shading_normal, vec3 face_normal) {
    Ray stack[RAY_STACK];
    int sp = 0;
    vec3 total = vec3(0.0);
    // The first hit's interface, then each traced hit's in turn.
    vec3 point = p;
    Interface at = bend(d, shading_normal, face_normal, true, u_room_ior / object_glass(object).x);
    vec3 weight = vec3(1.0);
    float share = object_transmission(object);
    int depth = 1;
    int inside = -1;
    int beyond = object;
    bool split = true;  // `at`'s two rays are still to go (one ray a turn)
    while (true) {
        if (split) {
            // The mirror ray stays on this side, the refracted one crosses.
            if (at.fresnel > 0.0 && sp < RAY_STACK)
                stack[sp++] = Ray(point, normalize(at.reflected), weight * (share * at.fresnel),
                                  depth + 1, inside);
            if (at.tir < 0.5 && sp < RAY_STACK)
                stack[sp++] = Ray(point, normalize(at.refracted),
                                  weight * (share * (1.0 - at.fresnel)), depth + 1, beyond);
            split = false;
        }
        if (sp == 0) break;
        Ray ray = stack[--sp];
        // Item 9: too deep or too faint: L = 0.
        if (ray.depth > u_max_depth || largest(ray.weight) < 1.0 / 1024.0) continue;
        Hit hit = nearest(ray.origin, ray.direction, ray.inside, u_min_distance);
        if (hit.object < 0) {
            if (ray.inside < 0) total += ray.weight * u_background_light;
            continue;  // a ray inside that finds no exit: L = 0
        }
        int at_texel = 7 * hit.index;
        vec3 p0 = texelFetch(u_triangles, at_texel).xyz;
        vec3 p1 = texelFetch(u_triangles, at_texel + 1).xyz;
        vec3 p2 = texelFetch(u_triangles, at_texel + 2).xyz;
        vec3 face = texelFetch(u_triangles, at_texel + 3).xyz;
        float b0 = 1.0 - hit.b1 - hit.b2;
        point = b0 * p0 + hit.b1 * p1 + hit.b2 * p2;
        vec4 glass = object_glass(hit.object);  // (n_o, model, smooth, clear)
        vec3 normal = face;
        if (glass.z > 0.5) {  // gouraud and phong are lit per point here
            vec3 mixed = b0 * texelFetch(u_triangles, at_texel + 4).xyz +
                         hit.b1 * texelFetch(u_triangles, at_texel + 5).xyz +
                         hit.b2 * texelFetch(u_triangles, at_texel + 6).xyz;
            float len = length(mixed);
            if (len > 0.0) normal = mixed / len;
        }
        bool entering = ray.inside < 0;
        float transmission = object_transmission(hit.object);
        int model = int(glass.y);
        if (entering && !(transmission > 0.0)) {
            total += ray.weight * shade_material(point, normal, -ray.direction,
                                                 object_material(hit.object), model);
            continue;
        }
        weight = ray.weight;
        share = 1.0;
        if (entering) {
            Material m = object_material(hit.object);
            vec3 all = shade_material(point, normal, -ray.direction, m, model);
            m.ks = 0.0;
            vec3 ambient_diffuse = shade_material(point, normal, -ray.direction, m, model);
            total += ray.weight * ((1.0 - transmission) * ambient_diffuse +
                                   (all - ambient_diffuse));
            share = transmission;
        } else if (glass.w < 0.5) {
            vec4 a = object_absorption(hit.object);
            weight = weight * absorption(a.xyz, hit.t, a.w);
        }
        float n1 = entering ? u_room_ior : glass.x;
        float n2 = entering ? glass.x : u_room_ior;
        at = bend(ray.direction, normal, face, entering, n1 / n2);
        depth = ray.depth;
        inside = ray.inside;
        beyond = entering ? hit.object : -1;
        split = true;
    }
    return total;
}
)";

// Everything a glass program's fragment stage adds to the lighting.
std::string glass_declarations(std::span<const Reflection> models,
                               std::optional<std::span<const Light>> lights) {
    const PrintOptions options = shader_print_options();
    return any_model(models, lights) + object_fetch() +
           "\n"
           "// What happens to a ray at an interface (docs/spec.md §10.2 items 3-5).\n"
           "struct Interface {\n"
           "    float cos_incident;\n"
           "    float k;\n"
           "    float cos_refracted;\n"
           "    float fresnel;\n"
           "    vec3 refracted;\n"
           "    vec3 reflected;\n"
           "    float tir;\n"
           "};\n\n" +
           print_function(refract_interface_function(), options) + '\n' +
           print_function(absorption_function(), options) + tracer_text;
}

}  // namespace

int object_texels() { return 4 + (parameter_count() + 3) / 4; }

Shaders generate_glass(const GlassProgram& program) {
    const std::size_t count = program.lights.size();
    const int capacity = std::max<int>(1, static_cast<int>(count));
    std::optional<std::span<const Light>> lights;
    if (count <= max_specialised_lights) lights = program.lights;
    const auto own = std::find(program.models.begin(), program.models.end(), program.reflection);
    if (own == program.models.end())
        throw ArgumentError("glsl::generate_glass: the object's model is not among the scene's");
    const std::string own_model =
        "\nconst int OWN_MODEL = " + std::to_string(own - program.models.begin()) + ";\n";
    const Shading shading = program.shading;
    const bool per_vertex = shading == Shading::Flat || shading == Shading::Gouraud;
    const bool smooth = shading == Shading::Phong || shading == Shading::Gouraud;
    const std::string interpolation = shading == Shading::Flat ? "flat " : "";

    Shaders shaders;
    std::string& vertex = shaders.vertex;
    std::string& fragment = shaders.fragment;
    const std::string note =
        "//\n"
        "// A glass program (docs/spec.md §10): the object's surface has t > 0; each\n"
        "// fragment adds t*[F*L(R) + (1-F)*L(T)], traced in the shader against the\n"
        "// scene's triangles. Besides the uniforms above, it reads four RGBA32F texture\n"
        "// buffers:\n"
        "//   u_triangles  7 texels a triangle, in the hierarchy's leaf order: (p0, object),\n"
        "//                (p1, triangle within the object), (p2, 0), (N_g, 0), and the\n"
        "//                corners' vertex normals (n0, 0), (n1, 0), (n2, 0)\n"
        "//   u_nodes      4 texels a node, two for each child: (lower corner, bits of the\n"
        "//                child's node or of its first triangle), (upper corner, bits of\n"
        "//                its triangle count: 0 for a node, -1.0 for an empty slot);\n"
        "//                node 0 is the root over the objects, node 1 + o object o's root\n"
        "//   u_objects    OBJECT_TEXELS a scene object: (C, k_a), (k_d, k_s, shininess, t),\n"
        "//                (absorption colour, D), (n_o, model, smooth, clear), then the\n"
        "//                models' parameters, four a texel\n"
        "//   u_faces      N_g of each triangle in drawing order (u_face_base + gl_PrimitiveID)\n"
        "// and u_node_count, u_room_ior, u_max_depth, u_min_distance (1e-6 x the room's\n"
        "// diagonal), u_background_light ((background/255)^gamma), u_object (the object's\n"
        "// number), u_face_base, u_pass, and in pass 2 four RGBA32F textures of the\n"
        "// picture's size that pass 1 wrote (locations 0-3): u_record_point,\n"
        "// u_record_normal, u_record_face, u_record_own. Pass 0 draws the glass objects'\n"
        "// depth (colour masked), pass 1 the same objects again (depth test LEQUAL) into\n"
        "// the four textures, cleared first to an object of -1, and pass 2 one triangle\n"
        "// over the picture (u_view_projection the identity; no depth test) into the\n"
        "// picture, with any one of the scene's glass programs.\n";
    vertex = header(program.reflection, shading, "vertex", program.output) + note;
    fragment = header(program.reflection, shading, "fragment", program.output) + note;
    const bool pixel = program.output == FragmentOutput::Pixel;

    vertex +=
        "\n"
        "layout(location = 0) in vec3 a_position;\n"
        "layout(location = 1) in vec3 a_normal;\n";
    if (shading == Shading::Flat) vertex += "layout(location = 2) in vec3 a_centroid;\n";
    vertex += "\nuniform mat4 u_view_projection;\n\nout vec3 v_position;\n";
    fragment += "\nin vec3 v_position;\n";
    if (smooth) {
        vertex += "out vec3 v_normal;\n";
        fragment += "in vec3 v_normal;\n";
    }
    if (per_vertex) {
        vertex += interpolation + "out vec3 v_all;  // I\n" + interpolation +
                  "out vec3 v_ambient_diffuse;  // I_ad: I without the specular part\n";
        fragment +=
            interpolation + "in vec3 v_all;\n" + interpolation + "in vec3 v_ambient_diffuse;\n";
        vertex += lighting_declarations(program.reflection, capacity, lights) +
                  any_model(program.models, lights) + own_model;
    }
    const std::string at = shading == Shading::Flat ? "a_centroid" : "a_position";
    vertex += "\nvoid main() {\n    v_position = a_position;\n";
    if (smooth) vertex += "    v_normal = a_normal;\n";
    if (per_vertex)
        vertex += "    vec3 to_eye = unit_vector(u_eye - " + at +
                  ");\n"
                  "    Material m = u_material;\n"
                  "    v_all = shade_material(" +
                  at +
                  ", a_normal, to_eye, m, OWN_MODEL);\n"
                  "    m.ks = 0.0;\n"
                  "    v_ambient_diffuse = shade_material(" +
                  at + ", a_normal, to_eye, m, OWN_MODEL);\n";
    vertex += "    gl_Position = u_view_projection * vec4(a_position, 1.0);\n}\n";

    fragment +=
        "\n"
        "uniform int u_object;      // the object's number in the scene (u_objects)\n"
        "uniform int u_face_base;   // its first triangle in u_faces\n"
        "uniform int u_pass;        // 0: depth only, 1: record, 2: trace (below)\n"
        "// What pass 1 recorded of each pixel's nearest glass fragment, read by pass 2:\n"
        "uniform sampler2D u_record_point;   // (p, object); object -1: no glass there\n"
        "uniform sampler2D u_record_normal;  // (N_s, 0)\n"
        "uniform sampler2D u_record_face;    // (N_g, 0)\n"
        "uniform sampler2D u_record_own;     // (the local part, 0)\n"
        "\n"
        "layout(location = 0) out vec4 frag_color;  // pass 1: (p, object)\n"
        "layout(location = 1) out vec4 record_normal;\n"
        "layout(location = 2) out vec4 record_face;\n"
        "layout(location = 3) out vec4 record_own;\n";
    fragment +=
        lighting_declarations(program.reflection, capacity, lights) +
        glass_declarations(program.models, lights) + own_model +
        (pixel ? to_pixel_function(lights && program.gamma == 1.0f) : sample_light_function());
    fragment +=
        "\n"
        "// The local part (1 - t)*I_ad + I_s by the shading model, plus the traced\n"
        "// bracket at the fragment's point with its N_s, in three passes: the glass\n"
        "// objects' depth (0); what the tree needs of each pixel's nearest glass\n"
        "// fragment, recorded (1); the trees, traced by one triangle over the whole\n"
        "// picture (2), so that the fragments of a SIMD group are whole blocks of\n"
        "// pixels rather than the few a small triangle covers.\n"
        "void main() {\n"
        "    if (u_pass == 0) {\n"
        "        frag_color = vec4(0.0);\n"
        "        return;\n"
        "    }\n"
        "    if (u_pass == 2) {\n"
        "        ivec2 at = ivec2(gl_FragCoord.xy);\n"
        "        vec4 point = texelFetch(u_record_point, at, 0);\n"
        "        if (point.w < 0.0) discard;\n"
        "        vec3 d = unit_vector(point.xyz - u_eye);\n"
        "        vec3 bracket = trace_bracket(int(point.w), point.xyz, d,\n"
        "                                     texelFetch(u_record_normal, at, 0).xyz,\n"
        "                                     texelFetch(u_record_face, at, 0).xyz);\n"
        "        frag_color = vec4(" +
        std::string(pixel ? "to_pixel" : "sample_light") +
        "(texelFetch(u_record_own, at, 0).xyz + bracket), 1.0);\n"
        "        return;\n"
        "    }\n"
        "    vec3 face = texelFetch(u_faces, u_face_base + gl_PrimitiveID).xyz;\n"
        "    vec3 p = v_position;\n"
        "    vec3 normal = face;\n";
    if (smooth)
        fragment +=
            "    float len = length(v_normal);\n"
            "    if (len > 0.0) normal = v_normal / len;\n";
    if (per_vertex) {
        fragment +=
            "    vec3 all = v_all;\n"
            "    vec3 ambient_diffuse = v_ambient_diffuse;\n";
    } else {
        fragment +=
            "    vec3 to_eye = unit_vector(u_eye - p);\n"
            "    Material m = u_material;\n"
            "    vec3 all = shade_material(p, normal, to_eye, m, OWN_MODEL);\n"
            "    m.ks = 0.0;\n"
            "    vec3 ambient_diffuse = shade_material(p, normal, to_eye, m, OWN_MODEL);\n";
    }
    fragment +=
        "    float t = object_transmission(u_object);\n"
        "    vec3 own = (1.0 - t) * ambient_diffuse + (all - ambient_diffuse);\n"
        "    frag_color = vec4(p, float(u_object));\n"
        "    record_normal = vec4(normal, 0.0);\n"
        "    record_face = vec4(face, 0.0);\n"
        "    record_own = vec4(own, 0.0);\n"
        "}\n";
    return shaders;
}

}  // namespace litkit::glsl
