// SPDX-License-Identifier: MIT
// litkit_gl_peer: the scenes of bench/ drawn by a plain OpenGL program, the
// way a competent programmer (or a tutorial) writes one for a given scene.
// bench/compare.sh measures both litkit backends against it.
//
// It is deliberately separate from litkit's OpenGL backend and shader
// generator (src/gl, src/codegen): nothing of those is linked or included.
// It takes from litkit only what makes it draw the same picture: the scene
// file (litkit::load_scene / default_scene), each object's world-space mesh
// with its vertex normals (litkit::world_mesh, so the geometry is the very
// same), and PNG writing (litkit::write_png, so the file written costs the
// same to encode on both sides). `--check` also renders litkit's picture,
// to compare. Everything that draws is its own:
//
//   - a headless EGL context (Mesa's surfaceless platform, else the default
//     display with a 1×1 pbuffer), OpenGL 3.3 core, through libepoxy;
//   - shaders written for the scene (shaders.cpp): one program per
//     reflection × shading model used, with a block of code per light of the
//     scene (no light loop, no branch on kinds), light values as uniforms;
//   - per object an indexed mesh (positions and vertex normals interleaved,
//     32-bit indices); flat shading, which needs each triangle's normal and
//     centroid at all three corners, gets unshared vertices instead;
//   - per frame: clear an FBO (RGBA8 colour, 24-bit depth), one draw per
//     object (depth test, back faces culled), glFinish and glReadPixels of
//     RGBA bytes into memory (OpenGL's bottom-up rows, as they come).
//
//   litkit_gl_peer [SCENE] [--width W] [--height H] [--reflection M]
//                  [--shading S] [--frames K] [-o out.png] [--check]
//
// Default: steady frames, one warm-up then K (default 20), printing the
// lines `litkit bench` prints (`setup: … ms`, `median_frame_ms=…`).
// -o: the whole process, one frame written as a PNG (rows flipped, RGB), as
// `litkit render -o` does. --check: the peer's frame against litkit's CPU
// picture of the same scene, by the measure of tests/picture_agreement.hpp
// (≥ 99.5% of interior pixels within 2/255); exit status 1 when it fails.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <sys/resource.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "heap.hpp"
#include "litkit/error.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "peer.hpp"
#include "picture_agreement.hpp"

namespace {

using clock_type = std::chrono::steady_clock;
double ms_since(clock_type::time_point start) {
    return std::chrono::duration<double, std::milli>(clock_type::now() - start).count();
}

// ---- EGL ---------------------------------------------------------------------

struct Context {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;

    Context() {
        if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
            display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                               nullptr);
        if (display == EGL_NO_DISPLAY) display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
        EGLint major = 0, minor = 0;
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
            throw std::runtime_error("cannot initialise an EGL display");
        if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL offers no desktop OpenGL");
        const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                            EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!eglChooseConfig(display, config_attributes, &config, 1, &count) || count < 1)
            throw std::runtime_error("no EGL configuration for desktop OpenGL");
        const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                             3,
                                             EGL_CONTEXT_MINOR_VERSION,
                                             3,
                                             EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                             EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                             EGL_NONE};
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
        if (context == EGL_NO_CONTEXT)
            throw std::runtime_error("cannot create an OpenGL 3.3 core context");
        if (!epoxy_has_egl_extension(display, "EGL_KHR_surfaceless_context")) {
            const EGLint pbuffer_attributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
            surface = eglCreatePbufferSurface(display, config, pbuffer_attributes);
            if (surface == EGL_NO_SURFACE) throw std::runtime_error("cannot create a pbuffer");
        }
        if (!eglMakeCurrent(display, surface, surface, context))
            throw std::runtime_error("cannot make the OpenGL context current");
    }
    ~Context() {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
        eglDestroyContext(display, context);
        eglTerminate(display);
    }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
};

// ---- Shaders -----------------------------------------------------------------

GLuint compile(GLenum stage, const std::string& source) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("shader does not compile: ") + log + "\n" + source);
    }
    return shader;
}

GLuint program_from(const peer::ShaderSources& sources) {
    const GLuint program = glCreateProgram();
    const GLuint vertex = compile(GL_VERTEX_SHADER, sources.vertex);
    const GLuint fragment = compile(GL_FRAGMENT_SHADER, sources.fragment);
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("program does not link: ") + log);
    }
    return program;
}

// ---- The scene on the GPU ----------------------------------------------------

struct Object {
    GLuint program = 0, vertex_array = 0, buffers[2] = {0, 0};
    GLsizei count = 0;
    bool indexed = true;
    litkit::Material material;
};

Object upload(const litkit::SceneObject& object, const litkit::Scene& scene,
              litkit::Shading shading) {
    const litkit::WorldMesh mesh =
        litkit::world_mesh(object, litkit::normal_options(scene, object));
    std::vector<float> vertices;
    std::vector<std::uint32_t> indices;
    const auto put = [&](const glm::vec3& v) { vertices.insert(vertices.end(), {v.x, v.y, v.z}); };
    Object gpu;
    gpu.material = object.material;
    gpu.indexed = shading != litkit::Shading::Flat;
    if (gpu.indexed) {
        vertices.reserve(mesh.positions.size() * 6);
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            put(mesh.positions[i]);
            put(mesh.normals[i]);
        }
        for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
        gpu.count = static_cast<GLsizei>(indices.size());
    } else {
        vertices.reserve(mesh.triangles.size() * 27);
        for (const auto& t : mesh.triangles) {
            const glm::vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]],
                            &c = mesh.positions[t[2]];
            const glm::vec3 cross = glm::cross(b - a, c - a);
            const float length = glm::length(cross);
            const glm::vec3 normal = length > 0.0f ? cross / length : glm::vec3(0.0f);
            const glm::vec3 centroid = (a + b + c) / 3.0f;
            for (const glm::vec3* corner : {&a, &b, &c}) {
                put(*corner);
                put(normal);
                put(centroid);
            }
        }
        gpu.count = static_cast<GLsizei>(mesh.triangles.size() * 3);
    }
    const int floats = gpu.indexed ? 6 : 9;
    glGenVertexArrays(1, &gpu.vertex_array);
    glBindVertexArray(gpu.vertex_array);
    glGenBuffers(2, gpu.buffers);
    glBindBuffer(GL_ARRAY_BUFFER, gpu.buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)),
                 vertices.data(), GL_STATIC_DRAW);
    for (int attribute = 0; attribute < floats / 3; ++attribute) {
        glVertexAttribPointer(attribute, 3, GL_FLOAT, GL_FALSE, floats * sizeof(float),
                              reinterpret_cast<const void*>(attribute * 3 * sizeof(float)));
        glEnableVertexAttribArray(attribute);
    }
    if (gpu.indexed) {
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.buffers[1]);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                     static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                     indices.data(), GL_STATIC_DRAW);
    }
    glBindVertexArray(0);
    return gpu;
}

struct Peer {
    int width, height;
    std::vector<Object> objects;
    GLuint framebuffer = 0, renderbuffers[2] = {0, 0};
    glm::vec3 background;

    explicit Peer(const litkit::Scene& scene)
        : width(scene.output.width),
          height(scene.output.height),
          background(scene.output.background) {  // 0-1 per channel, as every colour
        std::vector<litkit::Light> scene_lights;
        for (const litkit::SceneLight& light : scene.lights) scene_lights.push_back(light.light);
        const std::vector<peer::PeerLight> lights = peer::peer_lights(scene_lights);
        const bool gamma = scene.output.gamma != 1.0f;
        const litkit::Observer& o = scene.observer;
        const glm::mat4 view_projection =
            glm::perspective(glm::radians(o.fov_degrees), float(width) / float(height), o.near,
                             o.far) *
            glm::lookAt(o.position, o.look_at, o.up);
        glm::vec3 ambient(0.0f);
        for (const peer::PeerLight& light : lights)
            if (light.kind == peer::PeerLight::Ambient) ambient += light.radiance;

        std::map<std::pair<litkit::Reflection, litkit::Shading>, GLuint> programs;
        for (const litkit::SceneObject& object : scene.objects) {
            const litkit::Reflection reflection = object.reflection.value_or(*scene.reflection);
            const litkit::Shading shading = object.shading.value_or(*scene.shading);
            GLuint& program = programs[{reflection, shading}];
            if (!program) {
                program = program_from(peer::shaders_for(reflection, shading, lights, gamma));
                // What stays the same for every frame, set once.
                glUseProgram(program);
                const auto at = [&](const std::string& name) {
                    return glGetUniformLocation(program, name.c_str());
                };
                glUniformMatrix4fv(at("u_view_projection"), 1, GL_FALSE,
                                   glm::value_ptr(view_projection));
                glUniform3fv(at("u_eye"), 1, glm::value_ptr(o.position));
                glUniform3fv(at("u_ambient"), 1, glm::value_ptr(ambient));
                if (gamma) glUniform1f(at("u_inv_gamma"), 1.0f / scene.output.gamma);
                for (std::size_t i = 0; i < lights.size(); ++i) {
                    const std::string l = "u_light" + std::to_string(i) + "_";
                    glUniform3fv(at(l + "radiance"), 1, glm::value_ptr(lights[i].radiance));
                    glUniform3fv(at(l + "position"), 1, glm::value_ptr(lights[i].position));
                    glUniform3fv(at(l + "direction"), 1, glm::value_ptr(lights[i].direction));
                    glUniform3fv(at(l + "attenuation"), 1, glm::value_ptr(lights[i].attenuation));
                    glUniform1f(at(l + "cos_cutoff"), lights[i].cos_cutoff);
                    glUniform1f(at(l + "cos_inner"), lights[i].cos_inner);
                    glUniform1f(at(l + "exponent"), lights[i].exponent);
                }
            }
            objects.push_back(upload(object, scene, shading));
            objects.back().program = program;
        }

        glGenFramebuffers(1, &framebuffer);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glGenRenderbuffers(2, renderbuffers);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  renderbuffers[0]);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  renderbuffers[1]);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("the framebuffer is incomplete");
        glViewport(0, 0, width, height);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_CULL_FACE);  // counter-clockwise fronts, back faces culled
        glClearColor(background.r, background.g, background.b, 1.0f);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
    }

    // One frame, read back into `rgba` (bottom row first).
    void frame(std::vector<std::uint8_t>& rgba) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        for (const Object& object : objects) {
            glUseProgram(object.program);
            const auto at = [&](const char* name) {
                return glGetUniformLocation(object.program, name);
            };
            glUniform3fv(at("u_color"), 1, glm::value_ptr(object.material.color));
            glUniform1f(at("u_ka"), object.material.ka);
            glUniform1f(at("u_kd"), object.material.kd);
            glUniform1f(at("u_ks"), object.material.ks);
            glUniform1f(at("u_shininess"), object.material.shininess);
            glBindVertexArray(object.vertex_array);
            if (object.indexed)
                glDrawElements(GL_TRIANGLES, object.count, GL_UNSIGNED_INT, nullptr);
            else
                glDrawArrays(GL_TRIANGLES, 0, object.count);
        }
        glFinish();
        rgba.resize(static_cast<std::size_t>(width) * height * 4);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        if (const GLenum error = glGetError(); error != GL_NO_ERROR)
            throw std::runtime_error("OpenGL error " + std::to_string(error));
    }

    litkit::Image picture(const std::vector<std::uint8_t>& rgba) const {
        litkit::Image image(width, height);
        for (int y = 0; y < height; ++y) {
            const std::uint8_t* from =
                rgba.data() + static_cast<std::size_t>(height - 1 - y) * width * 4;
            std::uint8_t* to = image.rgb.data() + static_cast<std::size_t>(y) * width * 3;
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < 3; ++c) to[3 * x + c] = from[4 * x + c];
        }
        return image;
    }
};

// ---- Command line -----------------------------------------------------------

struct Arguments {
    std::string scene, output, reflection, shading;
    int width = 0, height = 0, frames = 20;
    bool check = false;
};

Arguments parse(int argc, char** argv) {
    Arguments a;
    for (int i = 1; i < argc; ++i) {
        const std::string word = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(word + " needs a value");
            return argv[++i];
        };
        if (word == "--width")
            a.width = std::stoi(value());
        else if (word == "--height")
            a.height = std::stoi(value());
        else if (word == "--frames")
            a.frames = std::stoi(value());
        else if (word == "--reflection")
            a.reflection = value();
        else if (word == "--shading")
            a.shading = value();
        else if (word == "-o")
            a.output = value();
        else if (word == "--check")
            a.check = true;
        else if (!word.empty() && word[0] == '-')
            throw std::runtime_error("unknown option " + word);
        else if (a.scene.empty())
            a.scene = word;
        else
            throw std::runtime_error("one scene file only");
    }
    if (a.frames < 1) throw std::runtime_error("--frames must be at least 1");
    return a;
}

litkit::Scene load(const Arguments& a) {
    litkit::Scene scene;
    if (a.scene.empty()) {
        scene = litkit::default_scene();
    } else {
        const std::filesystem::path file = a.scene;
        scene = litkit::load_scene(std::span(&file, 1));
    }
    if (a.width) scene.output.width = a.width;
    if (a.height) scene.output.height = a.height;
    if (!a.reflection.empty()) scene.reflection = litkit::parse_reflection(a.reflection);
    if (!a.shading.empty()) scene.shading = litkit::parse_shading(a.shading);
    if (!scene.reflection) scene.reflection = litkit::default_reflection;
    if (!scene.shading) scene.shading = litkit::default_shading;
    return scene;
}

int run(const Arguments& a) {
    const litkit::Scene scene = load(a);
    const auto setup_start = clock_type::now();
    Context context;
    Peer peer(scene);
    const double setup_ms = ms_since(setup_start);
    std::vector<std::uint8_t> rgba;

    if (!a.output.empty()) {  // the whole process: one frame to a PNG
        peer.frame(rgba);
        litkit::write_png(peer.picture(rgba), a.output);
        return 0;
    }
    if (a.check) {
        peer.frame(rgba);
        const litkit::Image own = peer.picture(rgba);
        const litkit::Image theirs = litkit::render(scene);
        const litkit_test::Agreement agreement =
            litkit_test::agreement(own, theirs, litkit_test::labels(scene));
        const bool ok = agreement.fraction() >= litkit_test::required_fraction &&
                        agreement.background_differing == 0;
        std::printf(
            "%s: %.3f%% of %zu interior pixels within 2/255 of litkit's (largest %d/255), "
            "%.3f%% of all pixels, %zu background pixels differ\n",
            ok ? "agree" : "DISAGREE", 100.0 * agreement.fraction(), agreement.counted,
            agreement.worst, 100.0 * agreement.fraction_of_all(), agreement.background_differing);
        return ok ? 0 : 1;
    }

    peer.frame(rgba);  // warm-up
    std::vector<double> frame_ms;
    for (int i = 0; i < a.frames; ++i) {
        const auto start = clock_type::now();
        peer.frame(rgba);
        frame_ms.push_back(ms_since(start));
    }
    std::sort(frame_ms.begin(), frame_ms.end());
    const std::size_t n = frame_ms.size();
    const double median = n % 2 ? frame_ms[n / 2] : 0.5 * (frame_ms[n / 2 - 1] + frame_ms[n / 2]);
    std::size_t triangles = 0;
    for (const Object& object : peer.objects)
        triangles += static_cast<std::size_t>(object.count) / 3;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("scene: %s\n", a.scene.empty() ? "(default)" : a.scene.c_str());
    std::printf("renderer: plain OpenGL peer: %s, OpenGL %s\n",
                reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                reinterpret_cast<const char*>(glGetString(GL_VERSION)));
    std::printf("image: %dx%d, %zu triangles\n", peer.width, peer.height, triangles);
    std::printf("setup: %.3f ms (meshes, normals, world space, context, shaders, upload)\n",
                setup_ms);
    std::printf("peak_rss_mib=%.1f\n", usage.ru_maxrss / 1024.0);
    std::printf("frames: %d, median %.3f ms, min %.3f ms\n", a.frames, median, frame_ms.front());
    std::printf("median_frame_ms=%.3f fps=%.1f\n", median, 1000.0 / median);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    // The heap litkit's command sets up (apps/litkit/heap.cpp: 2 MiB pages,
    // no separate mappings for large blocks). Without it this program's
    // frames depend on an accident of glibc: llvmpipe allocates large
    // blocks every frame, which glibc maps and unmaps afresh (every page a
    // fault, about 14 µs each on this VM) unless a large block freed earlier
    // had raised its mmap threshold. On the 261k sphere: 83-102 ms a frame
    // without, 31-36 ms with (docs/performance.md). The peer at its best.
    litkit_cli::use_large_pages_for_the_heap();
    try {
        return run(parse(argc, argv));
    } catch (const litkit::Error& error) {
        std::fprintf(stderr, "litkit_gl_peer: %s\n", error.what());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "litkit_gl_peer: %s\n", error.what());
    }
    return 2;
}
