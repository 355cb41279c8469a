// SPDX-License-Identifier: MIT
// The CPU rasterizer's public face (include/litkit/render.hpp): Renderer
// holds the pipeline (pipeline.hpp, one file per stage) and runs its stages
// in order for each frame (render_into, below).
#include "litkit/render.hpp"
#include "litkit/error.hpp"
#include "litkit/validate.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include "core/portable_math.hpp"
#include "cpu/pipeline.hpp"
#include "scene/float_range.hpp"

namespace litkit {

namespace {

const kernels::Kernels& pick_kernels(RenderOptions::Kernels set) {
    if (!kernel_set_available(set))
        throw ArgumentError(std::string("this CPU lacks the instructions of the ") +
                            (set == RenderOptions::Kernels::Avx512 ? "AVX-512" : "AVX2") +
                            " kernel set");
    switch (set) {
        case RenderOptions::Kernels::Portable:
            return kernels::portable_kernels;
#if defined(__x86_64__) || defined(__i386__)  // the other sets exist on x86 only
        case RenderOptions::Kernels::Avx2:
            return kernels::avx2_kernels;
        case RenderOptions::Kernels::Avx512:
            return kernels::avx512_kernels;
#else
        case RenderOptions::Kernels::Avx2:
        case RenderOptions::Kernels::Avx512:
            break;  // refused above
#endif
        case RenderOptions::Kernels::Best:
            break;
    }
    return kernels::select_kernels();
}

// The renderer's preconditions (render.hpp), checked before anything is built.
void check_preconditions(const Scene& scene, const RenderOptions& options) {
    if (options.threads < 0 || options.threads > max_render_threads)
        throw ArgumentError("RenderOptions::threads must be 0 (one per hardware thread) to " +
                            std::to_string(max_render_threads) + ", found " +
                            std::to_string(options.threads));
    check_renderable(scene);
}

}  // namespace

bool kernel_set_available(RenderOptions::Kernels set) {
    switch (set) {
        case RenderOptions::Kernels::Avx2:
            return kernels::cpu_has_avx2();
        case RenderOptions::Kernels::Avx512:
            return kernels::cpu_has_avx512();
        default:
            return true;
    }
}

Pipeline::Pipeline(const Scene& s, RenderOptions o)
    : length_scale(float_safe_length_scale(s)),
      scene(scale_lengths(s, length_scale)),
      options(o),
      pool(o.threads),
      kernels(pick_kernels(o.kernels)) {}

void Pipeline::begin_frame(int width, int height) {
    camera = make_camera(scene.observer, width, height);
    band_count = (height + band_height - 1) / band_height;
    background_row.resize(3 * static_cast<std::size_t>(width));
    const Rgb8 background = to_rgb8(scene.output.background);
    for (std::size_t i = 0; i < background_row.size(); ++i) background_row[i] = background[i % 3];
    // docs/spec.md §11: a sample that sees nothing has L = (background/255)^γ.
    for (int c = 0; c < 3; ++c)
        background_light[c] = power(scene.output.background[c], scene.output.gamma);
    for (BandScratch& band_scratch : scratch)
        band_scratch.shaded_pixels = band_scratch.traced_rays = 0;
}

// Renderer's state is the pipeline's.
struct Renderer::Impl : Pipeline {
    using Pipeline::Pipeline;
};

Renderer::Renderer(const Scene& scene, RenderOptions options)
    : impl_((check_preconditions(scene, options), std::make_unique<Impl>(scene, options))) {
    impl_->prepare();
}

Renderer::~Renderer() = default;

std::size_t Renderer::triangle_count() const {
    std::size_t count = 0;
    for (const PreparedObject& object : impl_->objects) count += object.triangles.size();
    return count;
}

int Renderer::thread_count() const { return impl_->pool.size(); }

const char* Renderer::kernel_set() const { return impl_->kernels.name; }

std::uint64_t Renderer::traced_ray_count() const {
    std::uint64_t count = 0;
    for (const BandScratch& scratch : impl_->scratch) count += scratch.traced_rays;
    return count;
}

std::size_t Renderer::shaded_pixel_count() const {
    std::size_t count = 0;
    for (const BandScratch& scratch : impl_->scratch) count += scratch.shaded_pixels;
    return count;
}

// The pipeline's stages in the order they run (pipeline.hpp), one frame.
void Renderer::render_into(Image& image) {
    Impl& impl = *impl_;
    const int width = impl.scene.output.width;
    const int height = impl.scene.output.height;
    if (image.width != width || image.height != height) image = Image(width, height);
    impl.begin_frame(width, height);
    // A probe after a probe of the same scene finds the vertex and setup
    // stages' buffers as they were left (nothing but update() changes them).
    const int samples = impl.scene.output.samples;
    if (impl.probe_y < 0 || impl.stages_hold_samples != samples) {
        impl.stages_hold_samples = 0;  // until both stages are done
        // vertex: every vertex to clip space and window coordinates.
        impl.vertex_stage(width, height);
        // clip and setup, one chunk of triangles per job, binned to bands of rows.
        impl.pool.parallel_for(impl.chunks.size(), [&](std::size_t c, int worker) {
            impl.setup(impl.chunks[c], impl.scratch[static_cast<std::size_t>(worker)], width,
                       height);
        });
        impl.stages_hold_samples = samples;
    }
    // rasterize and fragment, one band of rows per job.
    auto draw_band = [&](int band, BandScratch& scratch) {
        if (impl.scene.output.samples > 1) {
            impl.draw_band_samples(band, scratch, image);
            return;
        }
        impl.rasterize_band(band, scratch, width, height);
        impl.shade_band(band, scratch, image);
    };
    // probe(): the pixel's band alone. A band's rows depend only on the
    // triangles binned to it, so the pixel comes out as in a whole frame.
    if (impl.probe_y >= 0) {
        draw_band(impl.probe_y / band_height, impl.scratch[0]);
        return;
    }
    impl.pool.parallel_for(
        static_cast<std::size_t>(impl.band_count), [&](std::size_t band, int worker) {
            draw_band(static_cast<int>(band), impl.scratch[static_cast<std::size_t>(worker)]);
        });
}

void Renderer::update(const Scene& new_scene) {
    check_renderable(new_scene);  // before anything of the old scene is replaced
    Impl& impl = *impl_;
    const float length_scale = float_safe_length_scale(new_scene);
    Scene scene = scale_lengths(new_scene, length_scale);
    bool same = scene.objects.size() == impl.scene.objects.size();
    for (std::size_t o = 0; same && o < scene.objects.size(); ++o)
        same = same_geometry(scene.objects[o], impl.scene.objects[o]) &&
               normal_options(scene, scene.objects[o]) ==
                   normal_options(impl.scene, impl.scene.objects[o]);
    impl.scene = std::move(scene);  // one copy of the scene per update, as before
    impl.length_scale = length_scale;
    if (same) {
        impl.prepare_surfaces();
    } else {
        impl.prepare();
    }
}

std::size_t Renderer::mesh_builds() const { return impl_->mesh_builds; }

PixelProbe Renderer::probe(int x, int y) {
    const OutputSettings& output = impl_->scene.output;
    if (x < 0 || y < 0 || x >= output.width || y >= output.height) {
        throw ArgumentError("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                            ") is outside the " + std::to_string(output.width) + "x" +
                            std::to_string(output.height) + " image");
    }
    impl_->probed = PixelProbe{};
    impl_->probe_x = x;
    impl_->probe_y = y;
    Image image;
    const int samples = output.samples;
    try {
        render_into(image);
        if (samples > 1) {
            // The pixel from its samples (recorded above); then the rest of
            // the record at its centre, as one sample per pixel draws it.
            std::vector<SampleProbe> recorded = std::move(impl_->probed.samples);
            impl_->probed = PixelProbe{};
            impl_->probed.samples = std::move(recorded);
            impl_->scene.output.samples = 1;
            Image centre;
            render_into(centre);
            impl_->scene.output.samples = samples;
        }
    } catch (...) {
        impl_->scene.output.samples = samples;
        impl_->probe_x = impl_->probe_y = -1;
        throw;
    }
    impl_->probe_x = impl_->probe_y = -1;
    PixelProbe result = impl_->probed;
    result.position /= impl_->length_scale;  // in the scene's own lengths
    for (RayNode& node : result.ray_tree) {
        node.origin /= impl_->length_scale;
        node.point /= impl_->length_scale;
        node.length /= impl_->length_scale;
    }
    const std::uint8_t* pixel = image.pixel(x, y);
    result.rgb = {pixel[0], pixel[1], pixel[2]};
    return result;
}

Image Renderer::render() {
    Image image;
    render_into(image);
    return image;
}

Image render(const Scene& scene, RenderOptions options) {
    Renderer renderer(scene, options);
    return renderer.render();
}

}  // namespace litkit
