// SPDX-License-Identifier: MIT
#include "litkit/gl_renderer.hpp"

#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "codegen/gl_glass.hpp"
#include "codegen/gl_scene.hpp"
#include "codegen/glsl_glass.hpp"
#include "litkit/glsl.hpp"
#include "litkit/samples.hpp"
#include "litkit/validate.hpp"
#include "scene/float_range.hpp"
#include "scene/transparency.hpp"

namespace litkit {

namespace {
namespace core {
#include "gl/opengl_core.inc"
#include "gl/opengl_samples.inc"
}  // namespace core

// libepoxy loads libEGL, and libOpenGL or libGL, on first use and aborts the
// process if it cannot; looking first turns that into an error the caller
// can report.
void require_gl_libraries() {
    if (dlopen("libEGL.so.1", RTLD_NOW | RTLD_GLOBAL) == nullptr) {
        const char* why = dlerror();
        throw GlError(std::string("OpenGL is not available: cannot load libEGL.so.1 (") +
                      (why ? why : "not found") + ")");
    }
    if (dlopen("libOpenGL.so.0", RTLD_NOW | RTLD_GLOBAL) == nullptr &&
        dlopen("libGL.so.1", RTLD_NOW | RTLD_GLOBAL) == nullptr) {
        throw GlError(
            "OpenGL is not available: cannot load libOpenGL.so.0 or libGL.so.1 (Debian: libopengl0 "
            "or libgl1)");
    }
}

core::LightData light_data(const equations::PreparedLight& light) {
    return {static_cast<int>(light.kind),
            light.radiance,
            light.position,
            light.direction,
            light.attenuation,
            light.cos_cutoff,
            light.cos_inner,
            light.exponent};
}

core::MaterialData material_data(const Material& material) {
    core::MaterialData data{material.color, material.ka,        material.kd,
                            material.ks,    material.shininess, {}};
    for_each_model_parameter(
        [&](const ModelParameter& parameter, const float& value) {
            data.parameters.emplace_back(parameter.key, value);
        },
        material);
    return data;
}

// Every light is a uniform struct of about 24 components (vec3s padded to
// four); a shader that will not link with many lights most likely ran out.
int lights_room() {
    GLint vertex = 0, fragment = 0;
    glGetIntegerv(GL_MAX_VERTEX_UNIFORM_COMPONENTS, &vertex);
    glGetIntegerv(GL_MAX_FRAGMENT_UNIFORM_COMPONENTS, &fragment);
    return std::min(vertex, fragment) / 24;
}

std::string lights_hint(int lights) {
    if (lights < 16) return "";
    return " (the scene has " + std::to_string(lights) +
           " lights; this OpenGL has room for about " + std::to_string(lights_room()) +
           " in a shader)";
}

std::string gl_string(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "?";
}

// The glass programs' scene as opengl_core.inc takes it.
core::GlassScene glass_scene(const detail::GlassData& data) {
    return {data.triangles, data.nodes,        data.objects,
            data.faces,     data.node_count,   data.room_ior,
            data.max_depth, data.min_distance, data.background_light};
}

}  // namespace

struct GlRenderer::Impl {
    // Declaration order is destruction order reversed: GL objects go before
    // the context that owns them.
    std::optional<core::HeadlessContext> context;
    Scene scene;  // as drawn
    RenderOptions options;
    // By reflection, shading and glass (t > 0).
    std::map<std::tuple<Reflection, Shading, bool>, GLuint> programs;
    std::vector<core::GpuMesh> meshes;
    std::vector<core::DrawItem> items;
    std::vector<core::LightData> lights;
    std::optional<core::OffscreenTarget> target;
    // Where some object is glass: the scene for its rays, on the CPU (for
    // updates of the materials) and on the GPU.
    detail::GlassData glass_data;
    std::vector<detail::GlObject> glass_objects;  // materials and models only
    std::vector<Reflection> models;  // the objects' reflection models, each once (glass programs)
    std::optional<core::GlassBuffers> glass;
    core::FrameSettings frame{};
    std::size_t triangles = 0;
    std::vector<std::uint8_t> bands[2];  // read_rgb_in_step's band buffers, kept between frames
    // Anti-aliasing (docs/spec.md §11), made on first use: each program's
    // SampleLight twin, by the program's id, the passes' float target, the
    // sums, and for draw_to the picture and what shows it.
    std::map<GLuint, GLuint> sample_programs;
    std::optional<core::OffscreenTarget> sample_target;
    core::SampleSums sample_sums;
    Image resolved;
    std::optional<core::PictureBlit> blit;

    ~Impl() {
        if (context) {
            try {
                context->make_current();  // another renderer's may be current
            } catch (const std::runtime_error&) {
                return;  // the context goes with its objects
            }
        }
        target.reset();
        sample_target.reset();
        blit.reset();
        glass.reset();
        for (core::GpuMesh& mesh : meshes) core::release_mesh(mesh);
        for (const auto& [key, program] : programs) glDeleteProgram(program);
        for (const auto& [key, program] : sample_programs) glDeleteProgram(program);
    }
};

namespace {

// The camera, background, gamma and framebuffer size of a frame.
void set_frame(GlRenderer::Impl& gl, const Scene& scene) {
    const Observer& o = scene.observer;
    const float aspect =
        static_cast<float>(scene.output.width) / static_cast<float>(scene.output.height);
    gl.frame.view_projection =
        core::view_projection(o.position, o.look_at, o.up, o.fov_degrees, aspect, o.near, o.far);
    gl.frame.eye = o.position;
    // The bytes the CPU renderer writes, as OpenGL's exact 8-bit values.
    gl.frame.background = from_rgb8(to_rgb8(scene.output.background));
    gl.frame.gamma = scene.output.gamma;
    if (!gl.target || gl.target->width() != scene.output.width ||
        gl.target->height() != scene.output.height) {
        gl.target.reset();
        gl.target.emplace(scene.output.width, scene.output.height);
    }
}

}  // namespace

GlRenderer::GlRenderer(const Scene& scene, RenderOptions options)
    : GlRenderer(scene, options, CurrentContext{}, true) {}

void GlRenderer::update(const Scene& input) {
    check_renderable(input);  // litkit/validate.hpp: the renderers' preconditions
    // Drawn as the CPU renderer draws it: lengths brought into a float's
    // range by a power of two (scene/float_range.hpp; 1 for ordinary scenes).
    const Scene scene = scale_lengths(input, float_safe_length_scale(input));
    Impl& gl = *impl_;
    // What the programs and the uploaded meshes depend on: the objects'
    // geometry and models, and how many lights the shaders hold.
    const auto models = [](const Scene& s, const RenderOptions& o, std::size_t i) {
        const SceneObject& object = s.objects[i];
        return std::pair(object.reflection.value_or(s.reflection.value_or(o.fallback_reflection)),
                         object.shading.value_or(s.shading.value_or(o.fallback_shading)));
    };
    // The programs are specialised to the lights' kinds and to a gamma of
    // 1 or not (glsl::generate_for_scene): new values keep them, another kind or
    // number of lights, or gamma leaving or reaching 1, does not.
    bool same = scene.objects.size() == gl.scene.objects.size() &&
                scene.lights.size() == gl.scene.lights.size() &&
                (scene.output.gamma == 1.0f) == (gl.scene.output.gamma == 1.0f);
    for (std::size_t i = 0; same && i < scene.lights.size(); ++i)
        same = scene.lights[i].light.kind.index() == gl.scene.lights[i].light.kind.index();
    for (std::size_t i = 0; same && i < scene.objects.size(); ++i)
        same = same_geometry(scene.objects[i], gl.scene.objects[i]) &&
               normal_options(scene, scene.objects[i]) ==
                   normal_options(gl.scene, gl.scene.objects[i]) &&
               models(scene, gl.options, i) == models(gl.scene, gl.options, i) &&
               (scene.objects[i].material.transmission > 0.0f) ==
                   (gl.scene.objects[i].material.transmission > 0.0f);
    if (!same) {
        GlRenderer fresh(scene, gl.options, CurrentContext{}, gl.context.has_value());
        std::swap(impl_, fresh.impl_);
        return;
    }
    try {
        if (gl.context) gl.context->make_current();
        gl.lights.clear();
        for (const equations::PreparedLight& light : detail::prepared_lights(scene))
            gl.lights.push_back(light_data(light));
        for (std::size_t i = 0; i < scene.objects.size(); ++i)
            gl.items[i].material = material_data(scene.objects[i].material);
        if (gl.glass) {
            for (std::size_t i = 0; i < scene.objects.size(); ++i)
                gl.glass_objects[i].material = scene.objects[i].material;
            detail::update_glass_data(gl.glass_data, scene, gl.glass_objects);
            gl.glass->update(glass_scene(gl.glass_data));
        }
        set_frame(gl, scene);
        gl.scene = scene;
    } catch (const std::runtime_error& error) {
        throw GlError(error.what());
    }
}

GlRenderer::GlRenderer(const Scene& scene, RenderOptions options, CurrentContext context)
    : GlRenderer(scene, options, context, false) {}

GlRenderer::GlRenderer(const Scene& input, RenderOptions options, CurrentContext, bool headless)
    : impl_(std::make_unique<Impl>()) {
    check_renderable(input);  // before any OpenGL is set up
    const Scene scene = scale_lengths(input, float_safe_length_scale(input));  // as in update
    Impl& gl = *impl_;
    if (headless) {
        require_gl_libraries();
        try {
            gl.context.emplace();
        } catch (const std::runtime_error& error) {
            throw GlError(std::string("OpenGL is not available: ") + error.what());
        }
    }
    try {
        for (const equations::PreparedLight& light : detail::prepared_lights(scene))
            gl.lights.push_back(light_data(light));
        const int capacity = std::max<int>(1, static_cast<int>(gl.lights.size()));
        // Far beyond the room: refused at once, rather than after the
        // driver has compiled a shader of thousands of lights to find out
        // (llvmpipe under AddressSanitizer took minutes). Near the room, the
        // link decides.
        if (capacity >= 16 && capacity > 2 * lights_room())
            throw GlError("the shaders cannot hold the scene's lights" + lights_hint(capacity));
        std::vector<Light> lights;
        for (const SceneLight& light : scene.lights) lights.push_back(light.light);

        const Reflection scene_reflection = scene.reflection.value_or(options.fallback_reflection);
        const Shading scene_shading = scene.shading.value_or(options.fallback_shading);
        // Glass (docs/spec.md §10): the programs of objects with t > 0 trace
        // rays that may meet any object, so they know every model.
        const bool glass = detail::has_glass(scene);
        std::vector<Reflection>& models = gl.models;
        for (const SceneObject& object : scene.objects) {
            const Reflection reflection = object.reflection.value_or(scene_reflection);
            if (std::find(models.begin(), models.end(), reflection) == models.end())
                models.push_back(reflection);
        }
        gl.meshes.reserve(scene.objects.size());
        for (const SceneObject& object : scene.objects) {
            const Reflection reflection = object.reflection.value_or(scene_reflection);
            const Shading shading = object.shading.value_or(scene_shading);
            const bool glass_object = object.material.transmission > 0.0f;
            auto [found, added] = gl.programs.try_emplace({reflection, shading, glass_object}, 0);
            if (added) {
                const glsl::Shaders shaders =
                    glass_object
                        ? glsl::generate_glass(
                              {reflection, shading, models, lights, scene.output.gamma})
                        : glsl::generate_for_scene(reflection, shading, lights, scene.output.gamma);
                try {
                    found->second = core::link_program(shaders.vertex, shaders.fragment);
                } catch (const std::runtime_error& error) {
                    throw GlError(error.what() + lights_hint(capacity));
                }
            }
            detail::GlObject data =
                detail::gl_object(object, reflection, shading, normal_options(scene, object),
                                  scene.built_meshes.get());
            gl.meshes.push_back(core::upload_mesh(data.vertices, data.indices));
            gl.triangles += data.triangles;
            if (glass) gl.glass_objects.push_back(std::move(data));
        }
        if (glass) {
            gl.glass_data = detail::glass_data(scene, gl.glass_objects);
            gl.glass.emplace(glass_scene(gl.glass_data));
            // Only the materials and models are kept, for update().
            for (detail::GlObject& object : gl.glass_objects)
                object.vertices = {}, object.indices = {};
            gl.glass_data.triangles = {}, gl.glass_data.nodes = {}, gl.glass_data.faces = {};
        }
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const SceneObject& object = scene.objects[i];
            const bool glass_object = object.material.transmission > 0.0f;
            gl.items.push_back(
                {gl.programs.at({object.reflection.value_or(scene_reflection),
                                 object.shading.value_or(scene_shading), glass_object}),
                 &gl.meshes[i], material_data(object.material),
                 glass_object ? static_cast<int>(i) : -1, glass ? gl.glass_data.face_base[i] : 0});
        }

        set_frame(gl, scene);
        gl.scene = scene;
        gl.options = options;
    } catch (const std::runtime_error& error) {
        // Errors in the input (an unreadable mesh file, docs/spec.md §9.2's
        // missing file normal) are the input's, not OpenGL's.
        if (dynamic_cast<const IoError*>(&error) || dynamic_cast<const SceneError*>(&error) ||
            dynamic_cast<const ArgumentError*>(&error))
            throw;
        throw GlError(error.what());
    }
}

GlRenderer::~GlRenderer() = default;

Image GlRenderer::render() {
    Image image;
    render_into(image);
    return image;
}

namespace {

#if defined(__x86_64__) || defined(__i386__)
// OffscreenTarget::rgba_row_to_rgb with AVX2: eight pixels at a time, each
// 128-bit half's four shuffled to twelve bytes, the halves joined into 24.
// The same bytes; a fifth of the instructions, which at 1920×1080 was most of
// the frame's own time after OpenGL's (docs/performance.md).
__attribute__((target("avx2"))) void rgba_row_to_rgb_avx2(const std::uint8_t* from,
                                                          std::uint8_t* to, std::size_t count) {
    const __m256i drop_alpha =
        _mm256_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1,  //
                         0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1);
    const __m256i join = _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 7, 7);
    std::size_t x = 0;
    for (; x + 8 <= count; x += 8) {
        const __m256i rgba = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(from + 4 * x));
        const __m256i rgb =
            _mm256_permutevar8x32_epi32(_mm256_shuffle_epi8(rgba, drop_alpha), join);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(to + 3 * x), _mm256_castsi256_si128(rgb));
        _mm_storel_epi64(reinterpret_cast<__m128i*>(to + 3 * x + 16),
                         _mm256_extracti128_si256(rgb, 1));
    }
    if (x < count) core::OffscreenTarget::rgba_row_to_rgb(from + 4 * x, to + 3 * x, count - x);
}
#endif

using ConvertRow = core::OffscreenTarget::ConvertRow;

// OffscreenTarget::read_rgb with the conversion on a second thread: while
// this thread reads band k + 1 (OpenGL calls stay on the context's thread),
// a helper converts band k, each from a buffer of its own. The same bands,
// rows and bytes as read_rgb; the helper only hides the conversion, which
// took longer than the reading (docs/performance.md). False when no helper
// thread could be started (the caller reads as before).
bool read_rgb_in_step(const core::OffscreenTarget& target, std::uint8_t* rgb,
                      ConvertRow convert_row, std::vector<std::uint8_t> (&buffers)[2]) {
    const int band_count = target.band_count();
    for (auto& buffer : buffers) buffer.resize(target.band_bytes());
    std::atomic<int> read{-1};       // the last band read into its buffer
    std::atomic<int> converted{-1};  // the last band converted
    // Waiting on the atomic itself (C++20 wait/notify), never spinning:
    // with 2 cores shared with llvmpipe's threads, a spinning thread could
    // hold the core the one it waits for needs. Spinning only, a whole run
    // now and then drew at 20 ms a frame instead of 3.6; spinning 4096
    // pauses before the wait, 4 runs in 16 at 6-8.5 ms; waiting only, none
    // in 28 (docs/performance.md, "The GL read-back's helper: waiting, not
    // spinning").
    auto wait_until = [](const std::atomic<int>& counter, int at_least) {
        for (int seen; (seen = counter.load(std::memory_order_acquire)) < at_least;)
            counter.wait(seen, std::memory_order_acquire);
    };
    std::thread helper;
    try {
        helper = std::thread([&] {
            for (int k = 0; k < band_count; ++k) {
                wait_until(read, k);
                target.convert_band(k, buffers[k % 2].data(), rgb, convert_row);
                converted.store(k, std::memory_order_release);
                converted.notify_one();
            }
        });
    } catch (const std::system_error&) {
        return false;
    }
    target.begin_read();
    for (int k = 0; k < band_count; ++k) {
        wait_until(converted, k - 2);  // band k − 2, in the same buffer, is done with
        target.read_band(k, buffers[k % 2].data());
        read.store(k, std::memory_order_release);
        read.notify_one();
    }
    helper.join();
    return true;
}

// The frame at the scene's samples per pixel (more than one) into `image`:
// one pass per sample with the SampleLight programs, summed and resolved by
// opengl_samples.inc's draw_samples.
void draw_samples(GlRenderer::Impl& gl, Image& image) {
    try {
        if (gl.context) gl.context->make_current();
        const int width = gl.target->width(), height = gl.target->height();
        if (!gl.sample_target || gl.sample_target->width() != width ||
            gl.sample_target->height() != height) {
            gl.sample_target.reset();
            gl.sample_target.emplace(width, height, GL_RGBA32F);
        }
        if (gl.sample_programs.size() != gl.programs.size()) {  // their models and lights
            std::vector<Light> lights;
            for (const SceneLight& light : gl.scene.lights) lights.push_back(light.light);
            for (const auto& [key, program] : gl.programs) {
                if (gl.sample_programs.count(program)) continue;  // linked before a failure
                const auto& [reflection, shading, glass] = key;
                const glsl::Shaders shaders =
                    glass ? glsl::generate_glass({reflection, shading, gl.models, lights,
                                                  gl.scene.output.gamma,
                                                  glsl::FragmentOutput::SampleLight})
                          : glsl::generate_for_scene(reflection, shading, lights,
                                                     gl.scene.output.gamma,
                                                     glsl::FragmentOutput::SampleLight);
                gl.sample_programs[program] = core::link_program(shaders.vertex, shaders.fragment);
            }
        }
        std::vector<core::DrawItem> items = gl.items;
        for (core::DrawItem& item : items) item.program = gl.sample_programs.at(item.program);
        std::vector<core::SamplePoint> pattern;
        for (const SamplePosition& sample : sample_pattern(gl.scene.output.samples))
            pattern.push_back({sample.x, sample.y});
        if (image.width != width || image.height != height) image = Image(width, height);
        core::draw_samples(*gl.sample_target, gl.frame, gl.lights, items, pattern, gl.sample_sums,
                           image.rgb.data(), gl.glass ? &*gl.glass : nullptr);
    } catch (const std::runtime_error& error) {
        throw GlError(error.what());
    }
}

}  // namespace

void GlRenderer::render_into(Image& image) {
    Impl& gl = *impl_;
    if (gl.scene.output.samples > 1) return draw_samples(gl, image);
    try {
        if (gl.context) gl.context->make_current();
        core::draw_frame(*gl.target, gl.frame, gl.lights, gl.items,
                         gl.glass ? &*gl.glass : nullptr);
    } catch (const std::runtime_error& error) {
        throw GlError(error.what());
    }
    if (image.width != gl.target->width() || image.height != gl.target->height())
        image = Image(gl.target->width(), gl.target->height());
#if defined(__x86_64__) || defined(__i386__)
    static const auto convert_row = __builtin_cpu_supports("avx2")
                                        ? rgba_row_to_rgb_avx2
                                        : core::OffscreenTarget::rgba_row_to_rgb;
#else
    constexpr auto convert_row = core::OffscreenTarget::rgba_row_to_rgb;
#endif
    // Where there is a second core for the helper.
    static const bool in_step = std::thread::hardware_concurrency() >= 2;
    if (!in_step || !read_rgb_in_step(*gl.target, image.rgb.data(), convert_row, gl.bands))
        gl.target->read_rgb(image.rgb.data(), convert_row);
}

void GlRenderer::draw_to(unsigned framebuffer) {
    Impl& gl = *impl_;
    if (gl.scene.output.samples > 1) {
        // The resolved picture is in memory: shown through a texture.
        draw_samples(gl, gl.resolved);
        if (!gl.blit) gl.blit.emplace();
        gl.blit->show(gl.resolved.rgb.data(), gl.resolved.width, gl.resolved.height, framebuffer);
    } else {
        try {
            if (gl.context) gl.context->make_current();
            core::draw_frame(*gl.target, gl.frame, gl.lights, gl.items,
                             gl.glass ? &*gl.glass : nullptr);
        } catch (const std::runtime_error& error) {
            throw GlError(error.what());
        }
        // Both have OpenGL's bottom row first: a straight copy.
        const int w = gl.target->width(), h = gl.target->height();
        glBindFramebuffer(GL_READ_FRAMEBUFFER, gl.target->framebuffer());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
        glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    // draw_frame leaves depth testing and culling on; leave the context as
    // a window's drawing (a panel, say) expects it.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(0);
    glBindVertexArray(0);
}

std::size_t GlRenderer::triangle_count() const { return impl_->triangles; }

std::string GlRenderer::description() const {
    if (impl_->context) impl_->context->make_current();
    return gl_string(GL_RENDERER) + ", OpenGL " + gl_string(GL_VERSION);
}

}  // namespace litkit
