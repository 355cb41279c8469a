// litkit_gl_peer: the same scenes drawn with plain OpenGL, as a user would
// write it, for bench/compare.sh (issue "Faster than OpenGL", R12).
//
// Headless through EGL (Mesa's surfaceless platform when offered, otherwise a
// pbuffer on the default display), OpenGL 3.3 core, functions loaded with
// libepoxy. Each object's vertices are uploaded once; each frame clears an
// FBO (RGBA8 colour + 24-bit depth), draws one glDrawElements/glDrawArrays
// per object with a GLSL program for its reflection × shading model, then
// glFinish + glReadPixels. Nothing here is tuned against litkit: it is the
// straightforward program.
//
// litkit's library is used only for what a user would get from elsewhere
// anyway: the scene file (load_scene / default_scene), the meshes
// (object_mesh), their DD8/DD9 normals (face_normal, vertex_normals), the
// SPEC §2 placement (object_to_world) and PNG writing (write_png).
//
//   litkit_gl_peer [SCENE...] [--frames K] [--width W] [--height H]
//                  [--reflection M] [--shading S] [--png out.png] [--info]
//
// Frame timing (default): one warm-up frame, K timed frames, the last line
// `median_frame_ms=… fps=…` like `litkit bench`, after `peak_rss_mib=…`.
// --png: one frame, whole process, written to a PNG. --info: the GL strings.
#include <CLI/CLI.hpp>
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <sys/resource.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/image.hpp"
#include "litkit/mesh.hpp"
#include "litkit/scene.hpp"

namespace {

constexpr int max_lights = 8;

struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---------------------------------------------------------------- EGL

struct GlContext {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;
    std::string platform;

    GlContext() {
        if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
            display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                               nullptr);
            platform = "surfaceless";
        }
        if (display == EGL_NO_DISPLAY) {
            display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
            platform = "default display, pbuffer";
        }
        EGLint major = 0, minor = 0;
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
            throw Failure("cannot initialise an EGL display");
        if (!eglBindAPI(EGL_OPENGL_API)) throw Failure("EGL has no desktop OpenGL API");

        const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                            EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                            EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!eglChooseConfig(display, config_attributes, &config, 1, &count) || count < 1)
            throw Failure("no EGL config for desktop OpenGL with pbuffers");

        const EGLint context_attributes[] = {
            EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
        if (context == EGL_NO_CONTEXT) throw Failure("cannot create an OpenGL 3.3 core context");

        // Everything is drawn into an FBO: no surface needed where EGL allows
        // it, else a 1×1 pbuffer just to make the context current.
        if (!epoxy_has_egl_extension(display, "EGL_KHR_surfaceless_context")) {
            const EGLint pbuffer_attributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
            surface = eglCreatePbufferSurface(display, config, pbuffer_attributes);
            if (surface == EGL_NO_SURFACE) throw Failure("cannot create a pbuffer");
        }
        if (!eglMakeCurrent(display, surface, surface, context))
            throw Failure("cannot make the OpenGL context current");
    }
    ~GlContext() {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
        if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
        eglTerminate(display);
    }
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;
};

// ---------------------------------------------------------------- shaders

// SPEC §4, once; REFLECTION is defined per program (0 lambert, 1 half-lambert,
// 2 phong, 3 blinn-phong).
const char* const lighting_glsl = R"glsl(
#define MAX_LIGHTS 8
uniform int u_light_count;
uniform int u_light_type[MAX_LIGHTS];          // 0 ambient, 1 directional, 2 point, 3 spot
uniform vec3 u_light_position[MAX_LIGHTS];
uniform vec3 u_light_direction[MAX_LIGHTS];    // unit, the way the light travels
uniform vec3 u_light_attenuation[MAX_LIGHTS];  // k_c, k_l, k_q
uniform vec3 u_light_radiance[MAX_LIGHTS];     // intensity * colour / 255
uniform float u_light_cos_cutoff[MAX_LIGHTS];
uniform float u_light_exponent[MAX_LIGHTS];
uniform vec3 u_eye;
uniform vec3 u_color;                          // material colour / 255
uniform float u_ka;
uniform float u_kd;
uniform float u_ks;
uniform float u_shininess;

vec3 shade(vec3 p, vec3 N) {
    vec3 V = normalize(u_eye - p);
    vec3 I = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
        int type = u_light_type[i];
        if (type == 0) {
            I += u_ka * u_color * u_light_radiance[i];
            continue;
        }
        vec3 L;
        float f = 1.0;
        if (type == 1) {
            L = -u_light_direction[i];
        } else {
            vec3 to_light = u_light_position[i] - p;
            float d = length(to_light);
            L = to_light / d;
            vec3 k = u_light_attenuation[i];
            f = 1.0 / (k.x + k.y * d + k.z * d * d);
            if (type == 3) {
                float c = dot(-L, u_light_direction[i]);
                float e = u_light_exponent[i];
                if (c >= u_light_cos_cutoff[i])
                    f *= (e == 0.0) ? 1.0 : pow(max(c, 0.0), e);
                else
                    f = 0.0;
            }
        }
        float NL = dot(N, L);
        float D;
        float S = 0.0;
#if REFLECTION == 0
        D = max(NL, 0.0);
#elif REFLECTION == 1
        D = (0.5 * NL + 0.5) * (0.5 * NL + 0.5);
#elif REFLECTION == 2
        D = max(NL, 0.0);
        vec3 R = 2.0 * NL * N - L;
        float RV = dot(R, V);
        if (NL > 0.0 && RV > 0.0) S = pow(RV, u_shininess);
#else
        D = max(NL, 0.0);
        vec3 H = normalize(L + V);
        float NH = dot(N, H);
        if (NL > 0.0 && NH > 0.0) S = pow(NH, u_shininess);
#endif
        I += f * u_light_radiance[i] * (u_kd * D * u_color + u_ks * S);
    }
    return I;
}
)glsl";

// SHADING: 0 flat, 1 gouraud, 2 phong.
const char* const vertex_glsl = R"glsl(
uniform mat4 u_view_projection;
layout(location = 0) in vec3 a_position;   // world space
layout(location = 1) in vec3 a_normal;     // flat: the face normal; else the vertex normal
#if SHADING == 0
layout(location = 2) in vec3 a_centroid;
flat out vec3 v_color;
#elif SHADING == 1
out vec3 v_color;
#else
out vec3 v_position;
out vec3 v_normal;
#endif
void main() {
#if SHADING == 0
    v_color = shade(a_centroid, a_normal);
#elif SHADING == 1
    v_color = shade(a_position, a_normal);
#else
    v_position = a_position;
    v_normal = a_normal;
#endif
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)glsl";

const char* const fragment_glsl = R"glsl(
uniform float u_inv_gamma;
#if SHADING == 0
flat in vec3 v_color;
#elif SHADING == 1
in vec3 v_color;
#else
in vec3 v_position;
in vec3 v_normal;
#endif
out vec4 frag_color;
void main() {
#if SHADING == 2
    vec3 I = shade(v_position, normalize(v_normal));
#else
    vec3 I = v_color;
#endif
    frag_color = vec4(pow(clamp(I, 0.0, 1.0), vec3(u_inv_gamma)), 1.0);
}
)glsl";

GLuint compile(GLenum stage, const std::string& source) {
    GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw Failure(std::string("shader does not compile: ") + log);
    }
    return shader;
}

struct Program {
    GLuint id = 0;
    GLint view_projection, eye, color, ka, kd, ks, shininess, inv_gamma, light_count;
    GLint light_type, light_position, light_direction, light_attenuation, light_radiance,
        light_cos_cutoff, light_exponent;
};

Program make_program(litkit::Reflection reflection, litkit::Shading shading) {
    const std::string header = "#version 330 core\n#define REFLECTION " +
                               std::to_string(static_cast<int>(reflection)) + "\n#define SHADING " +
                               std::to_string(static_cast<int>(shading)) + "\n";
    const bool lit_per_vertex = shading != litkit::Shading::Phong;
    const std::string vs = header + (lit_per_vertex ? lighting_glsl : "") + vertex_glsl;
    const std::string fs = header + (lit_per_vertex ? "" : lighting_glsl) + fragment_glsl;
    GLuint v = compile(GL_VERTEX_SHADER, vs);
    GLuint f = compile(GL_FRAGMENT_SHADER, fs);
    Program p;
    p.id = glCreateProgram();
    glAttachShader(p.id, v);
    glAttachShader(p.id, f);
    glLinkProgram(p.id);
    GLint ok = 0;
    glGetProgramiv(p.id, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetProgramInfoLog(p.id, sizeof log, nullptr, log);
        throw Failure(std::string("program does not link: ") + log);
    }
    glDeleteShader(v);
    glDeleteShader(f);
    auto at = [&](const char* name) { return glGetUniformLocation(p.id, name); };
    p.view_projection = at("u_view_projection");
    p.eye = at("u_eye");
    p.color = at("u_color");
    p.ka = at("u_ka");
    p.kd = at("u_kd");
    p.ks = at("u_ks");
    p.shininess = at("u_shininess");
    p.inv_gamma = at("u_inv_gamma");
    p.light_count = at("u_light_count");
    p.light_type = at("u_light_type");
    p.light_position = at("u_light_position");
    p.light_direction = at("u_light_direction");
    p.light_attenuation = at("u_light_attenuation");
    p.light_radiance = at("u_light_radiance");
    p.light_cos_cutoff = at("u_light_cos_cutoff");
    p.light_exponent = at("u_light_exponent");
    return p;
}

// ---------------------------------------------------------------- scene upload

struct LightUniforms {
    int count = 0;
    int type[max_lights]{};
    glm::vec3 position[max_lights]{};
    glm::vec3 direction[max_lights]{};
    glm::vec3 attenuation[max_lights]{};
    glm::vec3 radiance[max_lights]{};
    float cos_cutoff[max_lights]{};
    float exponent[max_lights]{};
};

LightUniforms light_uniforms(const litkit::Scene& scene) {
    if (scene.lights.size() > static_cast<std::size_t>(max_lights))
        throw Failure("the OpenGL peer takes at most " + std::to_string(max_lights) + " lights");
    LightUniforms u;
    for (const litkit::SceneLight& scene_light : scene.lights) {
        const int i = u.count++;
        const litkit::Light& light = scene_light.light;
        u.radiance[i] = light.radiance();
        u.attenuation[i] = glm::vec3(0.0f, 0.0f, 1.0f);
        if (std::holds_alternative<litkit::AmbientLight>(light.kind)) {
            u.type[i] = 0;
        } else if (const auto* d = std::get_if<litkit::DirectionalLight>(&light.kind)) {
            u.type[i] = 1;
            u.direction[i] = glm::normalize(d->direction);
        } else if (const auto* p = std::get_if<litkit::PointLight>(&light.kind)) {
            u.type[i] = 2;
            u.position[i] = p->position;
            u.attenuation[i] = p->attenuation;
        } else if (const auto* s = std::get_if<litkit::SpotLight>(&light.kind)) {
            u.type[i] = 3;
            u.position[i] = s->position;
            u.attenuation[i] = s->attenuation;
            u.direction[i] = glm::normalize(s->direction);
            u.cos_cutoff[i] = std::cos(glm::radians(s->cutoff_degrees));
            u.exponent[i] = s->exponent;
        }
    }
    return u;
}

struct DrawObject {
    GLuint vao = 0;
    GLuint vertex_buffer = 0;
    GLuint index_buffer = 0;  // 0: glDrawArrays (flat shading, unshared vertices)
    GLsizei count = 0;        // indices or vertices
    std::size_t triangles = 0;
    const Program* program = nullptr;
    litkit::Material material;
};

// World-space vertices, uploaded once. Flat shading: three unshared vertices
// per triangle carrying (position, face normal, centroid); otherwise shared
// vertices (position, vertex normal) and an index buffer.
DrawObject upload(const litkit::SceneObject& object, const Program& program, litkit::Shading shading) {
    litkit::Mesh mesh = litkit::object_mesh(object);
    const glm::mat4 model = litkit::object_to_world(object);
    const glm::mat3 rotation = glm::mat3(model);  // rotation × uniform scale
    std::vector<glm::vec3> world(mesh.positions.size());
    for (std::size_t i = 0; i < world.size(); ++i)
        world[i] = glm::vec3(model * glm::vec4(mesh.positions[i], 1.0f));

    DrawObject d;
    d.program = &program;
    d.material = object.material;
    d.triangles = mesh.triangles.size();
    glGenVertexArrays(1, &d.vao);
    glBindVertexArray(d.vao);
    glGenBuffers(1, &d.vertex_buffer);
    glBindBuffer(GL_ARRAY_BUFFER, d.vertex_buffer);
    if (shading == litkit::Shading::Flat) {
        std::vector<float> data;
        data.reserve(mesh.triangles.size() * 27);
        for (const auto& t : mesh.triangles) {
            const glm::vec3 a = world[t[0]], b = world[t[1]], c = world[t[2]];
            const glm::vec3 n = litkit::face_normal(a, b, c);
            const glm::vec3 centroid = (a + b + c) / 3.0f;
            for (const glm::vec3& p : {a, b, c}) {
                data.insert(data.end(), {p.x, p.y, p.z, n.x, n.y, n.z, centroid.x, centroid.y,
                                         centroid.z});
            }
        }
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)),
                     data.data(), GL_STATIC_DRAW);
        const GLsizei stride = 9 * sizeof(float);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(3 * sizeof(float)));
        glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(6 * sizeof(float)));
        glEnableVertexAttribArray(0);
        glEnableVertexAttribArray(1);
        glEnableVertexAttribArray(2);
        d.count = static_cast<GLsizei>(mesh.triangles.size() * 3);
    } else {
        const std::vector<glm::vec3> local_normals = litkit::vertex_normals(mesh);
        std::vector<float> data;
        data.reserve(world.size() * 6);
        for (std::size_t i = 0; i < world.size(); ++i) {
            glm::vec3 n = rotation * local_normals[i];
            const float length = glm::length(n);
            if (length > 0.0f) n /= length;
            data.insert(data.end(), {world[i].x, world[i].y, world[i].z, n.x, n.y, n.z});
        }
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)),
                     data.data(), GL_STATIC_DRAW);
        const GLsizei stride = 6 * sizeof(float);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(3 * sizeof(float)));
        glEnableVertexAttribArray(0);
        glEnableVertexAttribArray(1);
        glGenBuffers(1, &d.index_buffer);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, d.index_buffer);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                     static_cast<GLsizeiptr>(mesh.triangles.size() * sizeof(mesh.triangles[0])),
                     mesh.triangles.data(), GL_STATIC_DRAW);
        d.count = static_cast<GLsizei>(mesh.triangles.size() * 3);
    }
    glBindVertexArray(0);
    return d;
}

// ---------------------------------------------------------------- the renderer

class Peer {
public:
    Peer(const litkit::Scene& scene) : scene_(scene), width_(scene.output.width), height_(scene.output.height) {
        lights_ = light_uniforms(scene);
        const litkit::Observer& o = scene.observer;
        const glm::mat4 view = glm::lookAt(o.position, o.look_at, o.up);
        const glm::mat4 projection =
            glm::perspective(glm::radians(o.fov_degrees),
                             static_cast<float>(width_) / static_cast<float>(height_), o.near, o.far);
        view_projection_ = projection * view;

        const litkit::Reflection scene_reflection = scene.reflection.value_or(litkit::default_reflection);
        const litkit::Shading scene_shading = scene.shading.value_or(litkit::default_shading);
        for (const litkit::SceneObject& object : scene.objects) {
            const litkit::Reflection r = object.reflection.value_or(scene_reflection);
            const litkit::Shading s = object.shading.value_or(scene_shading);
            auto key = std::make_pair(static_cast<int>(r), static_cast<int>(s));
            auto found = programs_.find(key);
            if (found == programs_.end()) found = programs_.emplace(key, make_program(r, s)).first;
            objects_.push_back(upload(object, found->second, s));
            triangles_ += objects_.back().triangles;
        }

        glGenFramebuffers(1, &fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glGenRenderbuffers(2, renderbuffers_);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[1]);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Failure("the framebuffer is not complete");

        glViewport(0, 0, width_, height_);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
        const auto& bg = scene.output.background;
        glClearColor(bg[0] / 255.0f, bg[1] / 255.0f, bg[2] / 255.0f, 1.0f);
        pixels_.resize(static_cast<std::size_t>(width_) * height_ * 4);
    }

    // One frame: clear, one draw per object, glFinish, glReadPixels (RGBA,
    // bottom row first).
    const std::vector<unsigned char>& frame() {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const float inv_gamma = 1.0f / scene_.output.gamma;
        for (const DrawObject& d : objects_) {
            const Program& p = *d.program;
            glUseProgram(p.id);
            glUniformMatrix4fv(p.view_projection, 1, GL_FALSE, glm::value_ptr(view_projection_));
            glUniform3fv(p.eye, 1, glm::value_ptr(scene_.observer.position));
            glUniform3fv(p.color, 1, glm::value_ptr(d.material.color));
            glUniform1f(p.ka, d.material.ka);
            glUniform1f(p.kd, d.material.kd);
            glUniform1f(p.ks, d.material.ks);
            glUniform1f(p.shininess, d.material.shininess);
            glUniform1f(p.inv_gamma, inv_gamma);
            glUniform1i(p.light_count, lights_.count);
            glUniform1iv(p.light_type, max_lights, lights_.type);
            glUniform3fv(p.light_position, max_lights, glm::value_ptr(lights_.position[0]));
            glUniform3fv(p.light_direction, max_lights, glm::value_ptr(lights_.direction[0]));
            glUniform3fv(p.light_attenuation, max_lights, glm::value_ptr(lights_.attenuation[0]));
            glUniform3fv(p.light_radiance, max_lights, glm::value_ptr(lights_.radiance[0]));
            glUniform1fv(p.light_cos_cutoff, max_lights, lights_.cos_cutoff);
            glUniform1fv(p.light_exponent, max_lights, lights_.exponent);
            glBindVertexArray(d.vao);
            if (d.index_buffer)
                glDrawElements(GL_TRIANGLES, d.count, GL_UNSIGNED_INT, nullptr);
            else
                glDrawArrays(GL_TRIANGLES, 0, d.count);
        }
        glFinish();
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels_.data());
        return pixels_;
    }

    litkit::Image image() const {
        litkit::Image out(width_, height_);
        for (int y = 0; y < height_; ++y) {
            const unsigned char* row = &pixels_[static_cast<std::size_t>(height_ - 1 - y) * width_ * 4];
            for (int x = 0; x < width_; ++x) {
                std::uint8_t* px = out.pixel(x, y);
                px[0] = row[x * 4];
                px[1] = row[x * 4 + 1];
                px[2] = row[x * 4 + 2];
            }
        }
        return out;
    }

    std::size_t triangles() const { return triangles_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    const litkit::Scene& scene_;
    int width_, height_;
    LightUniforms lights_;
    glm::mat4 view_projection_{1.0f};
    std::map<std::pair<int, int>, Program> programs_;
    std::vector<DrawObject> objects_;
    std::size_t triangles_ = 0;
    GLuint fbo_ = 0;
    GLuint renderbuffers_[2]{};
    std::vector<unsigned char> pixels_;
};

const char* gl_string(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "?";
}

const char* env_or(const char* name, const char* fallback) {
    const char* value = std::getenv(name);
    return value ? value : fallback;
}

// Once, after the first frame: a GL error there would make every timing moot.
void check_gl(const char* where) {
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", error);
        throw Failure(std::string("OpenGL error ") + code + " " + where);
    }
}

void print_info(const GlContext& gl) {
    std::printf("egl_platform: %s\n", gl.platform.c_str());
    std::printf("gl_vendor: %s\n", gl_string(GL_VENDOR));
    std::printf("gl_renderer: %s\n", gl_string(GL_RENDERER));
    std::printf("gl_version: %s\n", gl_string(GL_VERSION));
    std::printf("glsl_version: %s\n", gl_string(GL_SHADING_LANGUAGE_VERSION));
    std::printf("LP_NUM_THREADS: %s\n", env_or("LP_NUM_THREADS", "(unset: Mesa's default)"));
}

double peak_rss_mib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

struct Arguments {
    std::vector<std::string> scenes;
    int frames = 20;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<std::string> reflection;
    std::optional<std::string> shading;
    std::string png;
    bool info = false;
};

int run(const Arguments& arguments) {
    using clock = std::chrono::steady_clock;
    const auto process_start = clock::now();

    litkit::Scene scene;
    if (arguments.scenes.empty()) {
        scene = litkit::default_scene();
    } else {
        std::vector<std::filesystem::path> paths(arguments.scenes.begin(), arguments.scenes.end());
        scene = litkit::load_scene(paths);
    }
    if (arguments.width) scene.output.width = *arguments.width;
    if (arguments.height) scene.output.height = *arguments.height;
    if (arguments.reflection) scene.reflection = litkit::parse_reflection(*arguments.reflection);
    if (arguments.shading) scene.shading = litkit::parse_shading(*arguments.shading);

    GlContext gl;
    if (arguments.info) {
        print_info(gl);
        return 0;
    }

    const auto setup_start = clock::now();
    Peer peer(scene);
    const double setup_ms = std::chrono::duration<double, std::milli>(clock::now() - setup_start).count();

    if (!arguments.png.empty()) {
        peer.frame();
        check_gl("drawing the frame");
        litkit::write_png(peer.image(), arguments.png);
        const double ms = std::chrono::duration<double, std::milli>(clock::now() - process_start).count();
        std::printf("litkit_gl_peer: wrote %s (%dx%d, %zu triangles, %.0f ms)\n", arguments.png.c_str(),
                    peer.width(), peer.height(), peer.triangles(), ms);
        return 0;
    }

    peer.frame();  // warm-up: llvmpipe compiles the shaders on first use
    check_gl("drawing the first frame");
    std::vector<double> frame_ms;
    for (int frame = 0; frame < arguments.frames; ++frame) {
        const auto start = clock::now();
        peer.frame();
        frame_ms.push_back(std::chrono::duration<double, std::milli>(clock::now() - start).count());
    }
    std::sort(frame_ms.begin(), frame_ms.end());
    const std::size_t n = frame_ms.size();
    const double median = n % 2 ? frame_ms[n / 2] : 0.5 * (frame_ms[n / 2 - 1] + frame_ms[n / 2]);
    std::printf("scene: %s\n", arguments.scenes.empty() ? "(default)" : arguments.scenes.front().c_str());
    std::printf("renderer: %s, %s, LP_NUM_THREADS=%s\n", gl_string(GL_RENDERER), gl_string(GL_VERSION),
                env_or("LP_NUM_THREADS", "(unset)"));
    std::printf("image: %dx%d, %zu triangles\n", peer.width(), peer.height(), peer.triangles());
    std::printf("setup: %.3f ms (meshes, normals, upload, shader compile)\n", setup_ms);
    std::printf("frames: %d, median %.3f ms, min %.3f ms\n", arguments.frames, median, frame_ms.front());
    std::printf("peak_rss_mib=%.1f\n", peak_rss_mib());
    std::printf("median_frame_ms=%.3f fps=%.1f\n", median, 1000.0 / median);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"litkit_gl_peer: a scene drawn with plain OpenGL (EGL headless), for comparison"};
    Arguments arguments;
    app.add_option("SCENE", arguments.scenes, "Scene files (TOML), merged in order; none: the default scene");
    app.add_option("--frames", arguments.frames, "Frames to time (after one warm-up)")
        ->check(CLI::Range(1, 100000));
    app.add_option("--width", arguments.width, "Image width in pixels")->check(CLI::Range(1, 16384));
    app.add_option("--height", arguments.height, "Image height in pixels")->check(CLI::Range(1, 16384));
    app.add_option("--reflection", arguments.reflection, "Reflection model")
        ->check(CLI::IsMember({"lambert", "half-lambert", "phong", "blinn-phong"}));
    app.add_option("--shading", arguments.shading, "Shading model")
        ->check(CLI::IsMember({"flat", "gouraud", "phong"}));
    app.add_option("--png", arguments.png, "Render one frame (whole process) to this PNG");
    app.add_flag("--info", arguments.info, "Print the EGL platform and the GL strings, then exit");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? 0 : 2;
    }
    try {
        return run(arguments);
    } catch (const litkit::SceneError& error) {
        for (const litkit::Diagnostic& d : error.diagnostics()) std::cerr << d.to_string() << "\n";
        return 2;
    } catch (const litkit::IoError& error) {
        std::cerr << error.what() << "\n";
        return 1;
    } catch (const std::exception& error) {
        std::cerr << "litkit_gl_peer: error: " << error.what() << "\n";
        return 1;
    }
}
