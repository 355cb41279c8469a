// SPDX-License-Identifier: MIT
// The glass programs' GLSL helpers (src/codegen/glsl_glass.cpp) run on the
// GPU against the C++ they follow, on the same inputs: Snell's law and
// Fresnel (refract_interface, against equations::refract_interface<float>),
// Beer–Lambert (absorption), the guard that gives N_g the place of N_s
// (bend), and the hierarchy walk with the watertight test (nearest, against
// the CPU tracer's trace::Accel over the same triangles). Each runs as the
// main() of a glass program's fragment shader, one pixel per case of a
// float target, read back. Runs on Mesa's llvmpipe in CI.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "codegen/gl_glass.hpp"
#include "codegen/gl_scene.hpp"
#include "codegen/glsl_glass.hpp"
#include "glass_scenes.hpp"
#include "litkit/gl_renderer.hpp"
#include "litkit/refraction.hpp"
#include "trace/accel.hpp"

namespace {

using glass_scenes::Scene;
using litkit::equations::Vec3;

GLuint compile(GLenum stage, const std::string& text) {
    const GLuint shader = glCreateShader(stage);
    const char* source = text.c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::string log(4096, '\0');
        glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
        ADD_FAILURE() << log.c_str();
    }
    return shader;
}

// Evaluates `main_text` (the body of a main() that writes frag_color from
// case k = int(gl_FragCoord.x), its inputs in the texture buffer u_inputs
// and `u_part` saying which of its outputs) after a glass program's
// declarations, for `cases` cases and `parts` parts: parts × cases × 4 floats.
class Evaluator {
  public:
    Evaluator(const std::string& main_text, int cases, const std::vector<float>& inputs)
        : cases_(cases) {
        const std::vector<litkit::Reflection> models{litkit::Reflection::Phong};
        litkit::Light ambient;
        ambient.kind = litkit::AmbientLight{};
        const std::vector<litkit::Light> lights{ambient};
        std::string fragment =
            litkit::glsl::generate_glass(
                {litkit::Reflection::Phong, litkit::Shading::Phong, models, lights, 1.0f})
                .fragment;
        fragment = fragment.substr(0, fragment.rfind("void main() {"));
        fragment += "uniform samplerBuffer u_inputs;\nuniform int u_part;\nvoid main() {\n" +
                    main_text + "}\n";
        const std::string vertex =
            "#version 330 core\n"
            "void main() {\n"
            "    vec2 corner = vec2(float((gl_VertexID & 1) * 4 - 1), "
            "float((gl_VertexID & 2) * 2 - 1));\n"
            "    gl_Position = vec4(corner, 0.0, 1.0);\n"
            "}\n";
        program_ = glCreateProgram();
        const GLuint v = compile(GL_VERTEX_SHADER, vertex);
        const GLuint f = compile(GL_FRAGMENT_SHADER, fragment);
        glAttachShader(program_, v);
        glAttachShader(program_, f);
        glLinkProgram(program_);
        glDeleteShader(v);
        glDeleteShader(f);
        GLint ok = GL_FALSE;
        glGetProgramiv(program_, GL_LINK_STATUS, &ok);
        EXPECT_TRUE(ok);
        glGenVertexArrays(1, &vertex_array_);
        glGenFramebuffers(1, &framebuffer_);
        glGenRenderbuffers(1, &colour_);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glBindRenderbuffer(GL_RENDERBUFFER, colour_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, cases, 1);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
        EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        input_ = buffer(inputs, 4);
        glUseProgram(program_);
        glUniform1i(glGetUniformLocation(program_, "u_inputs"), 4);
    }
    ~Evaluator() {
        for (auto [buffer, texture] : buffers_) {
            glDeleteTextures(1, &texture);
            glDeleteBuffers(1, &buffer);
        }
        glDeleteRenderbuffers(1, &colour_);
        glDeleteFramebuffers(1, &framebuffer_);
        glDeleteVertexArrays(1, &vertex_array_);
        glDeleteProgram(program_);
    }

    // `floats` as an RGBA32F texture buffer on texture unit `unit`.
    GLuint buffer(const std::vector<float>& floats, int unit) {
        GLuint buffer = 0, texture = 0;
        glGenBuffers(1, &buffer);
        glBindBuffer(GL_TEXTURE_BUFFER, buffer);
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(floats.size() * sizeof(float)), floats.data(),
                     GL_STATIC_DRAW);
        glGenTextures(1, &texture);
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_BUFFER, texture);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, buffer);
        glActiveTexture(GL_TEXTURE0);
        buffers_.push_back({buffer, texture});
        return texture;
    }
    GLuint program() const { return program_; }

    std::vector<float> run(int parts) const {
        std::vector<float> out;
        glUseProgram(program_);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glViewport(0, 0, cases_, 1);
        glBindVertexArray(vertex_array_);
        for (int part = 0; part < parts; ++part) {
            glUniform1i(glGetUniformLocation(program_, "u_part"), part);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            std::vector<float> read(std::size_t(cases_) * 4);
            glReadPixels(0, 0, cases_, 1, GL_RGBA, GL_FLOAT, read.data());
            out.insert(out.end(), read.begin(), read.end());
        }
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        return out;
    }

  private:
    int cases_;
    GLuint program_ = 0, vertex_array_ = 0, framebuffer_ = 0, colour_ = 0, input_ = 0;
    std::vector<std::pair<GLuint, GLuint>> buffers_;
};

// A current OpenGL context for the evaluators: a renderer's.
litkit::GlRenderer& context() {
    static litkit::GlRenderer renderer(glass_scenes::axis_scene(5.0f));
    return renderer;
}

glm::vec3 random_unit(std::mt19937& random) {
    std::normal_distribution<float> normal;
    for (;;) {
        const glm::vec3 v(normal(random), normal(random), normal(random));
        if (glm::length(v) > 1e-3f) return glm::normalize(v);
    }
}

Vec3<float> v3(const glm::vec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

// Snell's law, exact Fresnel and total internal reflection, from the same
// template as the CPU's: every field within float rounding.
TEST(GlGlassShaders, RefractInterfaceIsTheCpusOnTheGpu) {
    context();
    std::mt19937 random(7);
    std::uniform_real_distribution<float> eta_of(1.0f / 3.0f, 3.0f);
    const int cases = 1024;
    std::vector<float> inputs;
    std::vector<litkit::equations::Interface<float>> expected;
    for (int k = 0; k < cases; ++k) {
        const glm::vec3 n = random_unit(random);
        glm::vec3 d = random_unit(random);
        if (glm::dot(d, n) > 0.0f) d = -d;  // c1 >= 0
        const float eta = k % 8 == 0 ? 1.0f : eta_of(random);
        inputs.insert(inputs.end(), {d.x, d.y, d.z, eta, n.x, n.y, n.z, 0.0f});
        expected.push_back(litkit::equations::refract_interface(v3(d), v3(n), eta));
    }
    Evaluator evaluator(
        "    int k = int(gl_FragCoord.x);\n"
        "    vec4 a = texelFetch(u_inputs, 2 * k);\n"
        "    vec4 b = texelFetch(u_inputs, 2 * k + 1);\n"
        "    Interface at = refract_interface(a.xyz, b.xyz, a.w);\n"
        "    if (u_part == 0) frag_color = vec4(at.cos_incident, at.k, at.cos_refracted, "
        "at.fresnel);\n"
        "    else if (u_part == 1) frag_color = vec4(at.refracted, at.tir);\n"
        "    else frag_color = vec4(at.reflected, 0.0);\n",
        cases, inputs);
    const std::vector<float> got = evaluator.run(3);
    int total_internal = 0;
    for (int k = 0; k < cases; ++k) {
        const auto& e = expected[std::size_t(k)];
        const float* p0 = &got[std::size_t(k) * 4];
        const float* p1 = &got[std::size_t(cases + k) * 4];
        const float* p2 = &got[std::size_t(2 * cases + k) * 4];
        const float tolerance = 2e-5f;
        EXPECT_NEAR(p0[0], e.cos_incident, tolerance) << k;
        EXPECT_NEAR(p0[1], e.k, 1e-4f) << k;
        EXPECT_NEAR(p0[2], e.cos_refracted, 1e-3f) << k;  // √k near k = 0
        EXPECT_NEAR(p0[3], e.fresnel, 1e-4f) << k;
        EXPECT_EQ(p1[3] > 0.5f, bool(e.total_internal_reflection)) << k;
        total_internal += e.total_internal_reflection;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(p1[c], (&e.refracted.x)[c], 1e-3f) << k;
            EXPECT_NEAR(p2[c], (&e.reflected.x)[c], tolerance) << k;
        }
    }
    EXPECT_GT(total_internal, cases / 20) << "the cases include total internal reflection";
}

// Beer–Lambert, with a colour channel of 0 and a length of 0.
TEST(GlGlassShaders, AbsorptionIsTheCpusOnTheGpu) {
    context();
    std::mt19937 random(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const int cases = 512;
    std::vector<float> inputs;
    std::vector<Vec3<float>> expected;
    for (int k = 0; k < cases; ++k) {
        const glm::vec3 color(k % 7 == 0 ? 0.0f : unit(random), unit(random), 1.0f);
        const float length = k % 5 == 0 ? 0.0f : 3.0f * unit(random);
        const float distance = 0.1f + 2.0f * unit(random);
        inputs.insert(inputs.end(), {color.x, color.y, color.z, length, distance, 0, 0, 0});
        expected.push_back(litkit::equations::absorption(v3(color), length, distance));
    }
    Evaluator evaluator(
        "    int k = int(gl_FragCoord.x);\n"
        "    vec4 a = texelFetch(u_inputs, 2 * k);\n"
        "    vec4 b = texelFetch(u_inputs, 2 * k + 1);\n"
        "    frag_color = vec4(absorption(a.xyz, a.w, b.x), 0.0);\n",
        cases, inputs);
    const std::vector<float> got = evaluator.run(1);
    for (int k = 0; k < cases; ++k)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[std::size_t(k) * 4 + std::size_t(c)], (&expected[std::size_t(k)].x)[c],
                        2e-5f)
                << k;
}

// The guard (docs/spec.md §10.2 items 2 and 6): with N_s facing away from
// the ray, or bending T back across the face, N_g takes its place; else
// N_s is used. Entering and leaving.
TEST(GlGlassShaders, BendFallsBackToTheFaceNormal) {
    context();
    struct Case {
        glm::vec3 d, shading, face;
        bool entering;
        float eta;
        glm::vec3 expected_normal;  // on the ray's side
    };
    const glm::vec3 up(0.0f, 0.0f, 1.0f);
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f));
    const glm::vec3 away = glm::normalize(glm::vec3(1.0f, 0.0f, -0.2f));
    const glm::vec3 grazing = glm::normalize(glm::vec3(1.0f, 0.0f, -0.05f));
    const glm::vec3 steep = glm::normalize(glm::vec3(0.2f, 0.1f, -1.0f));
    const std::vector<Case> cases{
        {steep, tilted, up, true, 1.0f / 1.5f, tilted},  // N_s used
        {steep, -tilted, up, false, 1.5f, tilted},       // leaving: −N_s on the ray's side
        {grazing, away, up, true, 1.0f / 1.5f, up},      // N_s faces away from the ray: N_g
        // N_s leans with the ray so that R = d + 2c₁·N_s would still go down
        // through the face (c₁ = 0.01 > 0): the guard gives N_g.
        {grazing, glm::normalize(glm::vec3(0.04f, 0.0f, 1.0f)), up, true, 1.0f / 1.5f, up},
        // Leaning the other way, R turns back and T crosses: N_s stays.
        {grazing, glm::normalize(glm::vec3(-1.0f, 0.0f, 0.3f)), up, true, 1.0f / 1.5f,
         glm::normalize(glm::vec3(-1.0f, 0.0f, 0.3f))},
    };
    std::vector<float> inputs;
    for (const Case& c : cases) {
        inputs.insert(inputs.end(),
                      {c.d.x, c.d.y, c.d.z, c.eta, c.shading.x, c.shading.y, c.shading.z,
                       c.entering ? 1.0f : 0.0f, c.face.x, c.face.y, c.face.z, 0.0f});
    }
    Evaluator evaluator(
        "    int k = int(gl_FragCoord.x);\n"
        "    vec4 a = texelFetch(u_inputs, 3 * k);\n"
        "    vec4 b = texelFetch(u_inputs, 3 * k + 1);\n"
        "    vec4 c = texelFetch(u_inputs, 3 * k + 2);\n"
        "    Interface at = bend(a.xyz, b.xyz, c.xyz, b.w > 0.5, a.w);\n"
        "    if (u_part == 0) frag_color = vec4(at.refracted, at.fresnel);\n"
        "    else frag_color = vec4(at.reflected, at.tir);\n",
        int(cases.size()), inputs);
    const std::vector<float> got = evaluator.run(2);
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const Case& c = cases[k];
        const auto e = litkit::equations::refract_interface(v3(c.d), v3(c.expected_normal), c.eta);
        const float* p0 = &got[k * 4];
        const float* p1 = &got[(cases.size() + k) * 4];
        EXPECT_NEAR(p0[3], e.fresnel, 1e-4f) << k;
        EXPECT_EQ(p1[3] > 0.5f, bool(e.total_internal_reflection)) << k;
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(p0[i], (&e.refracted.x)[i], 1e-4f) << k;
            EXPECT_NEAR(p1[i], (&e.reflected.x)[i], 1e-4f) << k;
        }
    }
}

// The walk of the hierarchy in the texture buffers and the watertight test
// find what the CPU tracer's hierarchy finds: front faces from the room,
// an object's back faces from inside it, the same triangle and distance.
namespace {

void expect_nearest_as_on_the_cpu(const Scene& scene) {
    context();
    std::vector<litkit::detail::GlObject> objects;
    for (const litkit::SceneObject& object : scene.objects)
        objects.push_back(litkit::detail::gl_object(object, litkit::Reflection::Phong,
                                                    litkit::Shading::Phong,
                                                    litkit::normal_options(scene, object)));
    const litkit::detail::GlassData data = litkit::detail::glass_data(scene, objects);
    // The same triangles for the CPU's hierarchy.
    std::vector<std::vector<glm::vec3>> positions(objects.size());
    std::vector<std::vector<std::array<std::uint32_t, 3>>> triangles(objects.size());
    std::vector<litkit::trace::MeshView> views;
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const auto& v = objects[o].vertices;
        for (std::size_t i = 0; i < v.size(); i += 6)
            positions[o].push_back({v[i], v[i + 1], v[i + 2]});
        const auto& idx = objects[o].indices;
        for (std::size_t i = 0; i < idx.size(); i += 3)
            triangles[o].push_back({idx[i], idx[i + 1], idx[i + 2]});
        views.push_back({positions[o], triangles[o]});
    }
    const litkit::trace::Accel accel(views);

    std::mt19937 random(3);
    std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f);
    const int cases = 2048;
    const int glass_count = int(objects.size());
    std::vector<float> inputs;
    std::vector<litkit::trace::Hit> expected;
    for (int k = 0; k < cases; ++k) {
        const glm::vec3 origin(coordinate(random), coordinate(random), coordinate(random) + 2.0f);
        // Aim at a random triangle's inside now and then, so most rays hit.
        glm::vec3 d = random_unit(random);
        if (k % 2 == 0) {
            const auto& o = positions[std::size_t(k / 2) % positions.size()];
            d = glm::normalize(o[std::size_t(k) % o.size()] * 0.98f - origin);
        }
        const int inside = k % 3 == 0 ? (k / 3) % glass_count : -1;
        const float t_min = data.min_distance;
        inputs.insert(inputs.end(),
                      {origin.x, origin.y, origin.z, float(inside), d.x, d.y, d.z, t_min});
        const litkit::trace::Ray ray{origin, d, t_min, std::numeric_limits<float>::infinity()};
        expected.push_back(inside < 0 ? accel.nearest_front(ray)
                                      : accel.nearest_back(ray, std::uint32_t(inside)));
    }
    Evaluator evaluator(
        "    int k = int(gl_FragCoord.x);\n"
        "    vec4 a = texelFetch(u_inputs, 2 * k);\n"
        "    vec4 b = texelFetch(u_inputs, 2 * k + 1);\n"
        "    Hit hit = nearest(a.xyz, b.xyz, int(a.w), b.w);\n"
        "    if (u_part == 0) frag_color = vec4(hit.t, float(hit.object), float(hit.triangle), "
        "0.0);\n"
        "    else frag_color = vec4(hit.b1, hit.b2, 0.0, 0.0);\n",
        cases, inputs);
    const GLuint program = evaluator.program();
    const char* names[4] = {"u_triangles", "u_nodes", "u_objects", "u_faces"};
    const std::vector<float>* buffers[4] = {&data.triangles, &data.nodes, &data.objects,
                                            &data.faces};
    glUseProgram(program);
    for (int i = 0; i < 4; ++i) {
        evaluator.buffer(*buffers[i], i);
        glUniform1i(glGetUniformLocation(program, names[i]), i);
    }
    glUniform1i(glGetUniformLocation(program, "u_node_count"), data.node_count);
    const std::vector<float> got = evaluator.run(2);
    int hits = 0, same = 0;
    for (int k = 0; k < cases; ++k) {
        const litkit::trace::Hit& e = expected[std::size_t(k)];
        const float* p0 = &got[std::size_t(k) * 4];
        const float* p1 = &got[std::size_t(cases + k) * 4];
        const int object = int(p0[1]);
        hits += e.found();
        const bool agrees = e.found() ? object == int(e.object) && int(p0[2]) == int(e.triangle) &&
                                            std::fabs(p0[0] - e.t) <= 1e-4f * e.t &&
                                            std::fabs(p1[0] - e.b1) <= 1e-3f &&
                                            std::fabs(p1[1] - e.b2) <= 1e-3f
                                      : object == -1;
        same += agrees;
    }
    EXPECT_GT(hits, cases / 3) << "the rays hit something";
    EXPECT_GT(cases - hits, cases / 20) << "and some miss";
    // Rays exactly through an edge may pick the neighbour (no double in GLSL).
    EXPECT_GE(same, cases - 2) << same << " of " << cases << " agree";
}

}  // namespace

TEST(GlGlassShaders, NearestHitIsTheCpuTracersOnTheGpu) {
    expect_nearest_as_on_the_cpu(glass_scenes::two_glasses_scene());
}

// One object of four triangles: the objects' root and the object's root
// each hold a single child (a node's other slot empty), and the object's
// tree is a single leaf.
TEST(GlGlassShaders, NearestHitWithOneObjectOfOneLeaf) {
    Scene scene = glass_scenes::base_scene();
    const std::vector<glm::vec3> corners{{-1, -1, -1}, {1, -1, -1}, {0, 1, -1}, {0, 0, 1}};
    scene.objects.push_back(
        glass_scenes::glass(litkit::MeshDataShape(glass_scenes::convex_mesh(
                                corners, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}})),
                            {0.1f, 0.0f, 0.5f}));
    ASSERT_EQ(scene.objects.size(), 1u);
    expect_nearest_as_on_the_cpu(scene);
}
