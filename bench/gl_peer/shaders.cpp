// SPDX-License-Identifier: MIT
// The peer's shaders, written by hand: a reflection function per classic
// model, a block per light kind, and the four ways of shading. For a scene,
// the program strings together the blocks of its lights, so the shader has
// no light loop and no branch on a light's kind, as someone writing OpenGL
// for one scene would write it. Light values are uniforms.
#include "peer.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

namespace peer {

namespace {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

glm::vec3 unit(const glm::vec3& v) {
    const float length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return length > 0.0f ? v / length : v;
}

// k_d·D·C + k_s·S for unit N, L, V: what f·I_L multiplies.
std::string reflectance_function(litkit::Reflection reflection) {
    const std::string head =
        "vec3 reflectance(vec3 N, vec3 L, vec3 V) {\n    float nl = dot(N, L);\n";
    switch (reflection) {
        case litkit::Reflection::Lambert:
            return head + "    return (u_kd * max(nl, 0.0)) * u_color;\n}\n";
        case litkit::Reflection::HalfLambert:
            return head +
                   "    float w = 0.5 * nl + 0.5;\n"
                   "    return (u_kd * w * w) * u_color;\n}\n";
        case litkit::Reflection::Phong:
            return head +
                   "    vec3 R = (2.0 * nl) * N - L;\n"
                   "    float rv = dot(R, V);\n"
                   "    float s = (nl > 0.0 && rv > 0.0) ? pow(rv, u_shininess) : 0.0;\n"
                   "    return (u_kd * max(nl, 0.0)) * u_color + u_ks * s;\n}\n";
        case litkit::Reflection::BlinnPhong:
            return head +
                   "    float nh = dot(N, normalize(L + V));\n"
                   "    float s = (nl > 0.0 && nh > 0.0) ? pow(nh, u_shininess) : 0.0;\n"
                   "    return (u_kd * max(nl, 0.0)) * u_color + u_ks * s;\n}\n";
        default:
            throw std::runtime_error(
                "the plain OpenGL peer writes only lambert, half-lambert, "
                "phong and blinn-phong, not " +
                std::string(litkit::to_string(reflection)));
    }
}

// The uniforms and the shade() function for these lights.
std::string lighting(litkit::Reflection reflection, const std::vector<PeerLight>& lights) {
    std::string declarations =
        "uniform vec3 u_eye;\n"
        "uniform vec3 u_color;\n"
        "uniform float u_ka, u_kd, u_ks, u_shininess;\n"
        "uniform vec3 u_ambient;  // the sum of the ambient lights' radiance\n";
    std::string body =
        "vec3 shade(vec3 p, vec3 N, vec3 V) {\n    vec3 I = (u_ka * u_ambient) * u_color;\n";
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::string at = "u_light" + std::to_string(i) + "_";
        switch (lights[i].kind) {
            case PeerLight::Ambient:
                continue;  // in u_ambient
            case PeerLight::Directional:
                declarations += "uniform vec3 " + at + "radiance, " + at + "direction;\n";
                body += "    I += " + at + "radiance * reflectance(N, -" + at + "direction, V);\n";
                break;
            case PeerLight::Point:
            case PeerLight::Spot: {
                declarations +=
                    "uniform vec3 " + at + "radiance, " + at + "position, " + at + "attenuation;\n";
                body +=
                    "    {\n"
                    "        vec3 d = " +
                    at +
                    "position - p;\n"
                    "        float r = length(d);\n"
                    "        vec3 L = d / r;\n"
                    "        float f = 1.0 / (" +
                    at + "attenuation.x + " + at + "attenuation.y * r + " + at +
                    "attenuation.z * r * r);\n";
                if (lights[i].kind == PeerLight::Spot) {
                    declarations += "uniform vec3 " + at + "direction;\n" + "uniform float " + at +
                                    "cos_cutoff, " + at + "cos_inner, " + at + "exponent;\n";
                    body += "        float c = -dot(L, " + at +
                            "direction);\n"
                            "        float width = " +
                            at + "cos_inner - " + at +
                            "cos_cutoff;\n"
                            "        float t = (c - " +
                            at +
                            "cos_cutoff) / (width > 0.0 ? width : 1.0);\n"
                            "        float w = c >= " +
                            at +
                            "cos_inner - 1e-6 ? 1.0 : t * t * (3.0 - 2.0 * t);\n"
                            "        float e = " +
                            at + "exponent == 0.0 ? 1.0 : pow(max(c, 0.0), " + at +
                            "exponent);\n"
                            "        f *= c >= " +
                            at + "cos_cutoff - 1e-6 ? e * w : 0.0;\n";
                }
                body += "        I += f * " + at + "radiance * reflectance(N, L, V);\n    }\n";
                break;
            }
        }
    }
    return declarations + "\n" + reflectance_function(reflection) + "\n" + body +
           "    return I;\n}\n";
}

const char* const version = "#version 330 core\n";

}  // namespace

std::vector<PeerLight> peer_lights(const std::vector<litkit::Light>& lights) {
    std::vector<PeerLight> result;
    for (const litkit::Light& light : lights) {
        PeerLight p;
        p.radiance = light.intensity * light.color;
        std::visit(Overloaded{
                       [&](const litkit::AmbientLight&) { p.kind = PeerLight::Ambient; },
                       [&](const litkit::DirectionalLight& d) {
                           p.kind = PeerLight::Directional;
                           p.direction = unit(d.direction);
                       },
                       [&](const litkit::PointLight& d) {
                           p.kind = PeerLight::Point;
                           p.position = d.position;
                           p.attenuation = d.attenuation;
                       },
                       [&](const litkit::SpotLight& d) {
                           p.kind = PeerLight::Spot;
                           p.position = d.position;
                           p.attenuation = d.attenuation;
                           p.direction = unit(d.direction);
                           const float radians = d.cutoff_degrees * 3.14159265358979f / 180.0f;
                           p.cos_cutoff = std::cos(radians);
                           p.cos_inner = std::cos(radians * (1.0f - d.penumbra));
                           p.exponent = d.exponent;
                       },
                   },
                   light.kind);
        result.push_back(p);
    }
    return result;
}

ShaderSources shaders_for(litkit::Reflection reflection, litkit::Shading shading,
                          const std::vector<PeerLight>& lights, bool gamma) {
    const std::string lit = lighting(reflection, lights);
    // The fragment's colour: GL clamps it to [0, 1] and rounds it into RGBA8.
    const std::string out_color =
        gamma ? "uniform float u_inv_gamma;\nout vec4 frag_color;\n"
                "void put(vec3 c) { frag_color = vec4(pow(clamp(c, 0.0, 1.0), vec3(u_inv_gamma)), "
                "1.0); }\n"
              : "out vec4 frag_color;\nvoid put(vec3 c) { frag_color = vec4(c, 1.0); }\n";
    const std::string inputs =
        "layout(location = 0) in vec3 a_position;\n"
        "layout(location = 1) in vec3 a_normal;\n"
        "uniform mat4 u_view_projection;\n";
    ShaderSources s;
    switch (shading) {
        case litkit::Shading::Flat:
            // Unshared vertices, each with its triangle's normal and centroid:
            // lit once per corner, the same at all three.
            s.vertex = version + inputs + "layout(location = 2) in vec3 a_centroid;\n" + lit +
                       "flat out vec3 v_color;\n"
                       "void main() {\n"
                       "    v_color = shade(a_centroid, a_normal, normalize(u_eye - a_centroid));\n"
                       "    gl_Position = u_view_projection * vec4(a_position, 1.0);\n}\n";
            s.fragment = version + std::string("flat in vec3 v_color;\n") + out_color +
                         "void main() { put(v_color); }\n";
            break;
        case litkit::Shading::Gouraud:
            s.vertex = version + inputs + lit +
                       "out vec3 v_color;\n"
                       "void main() {\n"
                       "    v_color = shade(a_position, a_normal, normalize(u_eye - a_position));\n"
                       "    gl_Position = u_view_projection * vec4(a_position, 1.0);\n}\n";
            s.fragment = version + std::string("in vec3 v_color;\n") + out_color +
                         "void main() { put(v_color); }\n";
            break;
        case litkit::Shading::Phong:
            s.vertex = version + inputs +
                       "out vec3 v_position;\nout vec3 v_normal;\n"
                       "void main() {\n"
                       "    v_position = a_position;\n    v_normal = a_normal;\n"
                       "    gl_Position = u_view_projection * vec4(a_position, 1.0);\n}\n";
            s.fragment = version + std::string("in vec3 v_position;\nin vec3 v_normal;\n") + lit +
                         out_color +
                         "void main() {\n"
                         "    put(shade(v_position, normalize(v_normal), normalize(u_eye - "
                         "v_position)));\n}\n";
            break;
        case litkit::Shading::Faceted:
            s.vertex = version + inputs +
                       "out vec3 v_position;\n"
                       "void main() {\n"
                       "    v_position = a_position;\n"
                       "    gl_Position = u_view_projection * vec4(a_position, 1.0);\n}\n";
            s.fragment = version + std::string("in vec3 v_position;\n") + lit + out_color +
                         "void main() {\n"
                         "    vec3 V = normalize(u_eye - v_position);\n"
                         "    vec3 N = normalize(cross(dFdx(v_position), dFdy(v_position)));\n"
                         "    put(shade(v_position, dot(N, V) < 0.0 ? -N : N, V));\n}\n";
            break;
    }
    return s;
}

}  // namespace peer
