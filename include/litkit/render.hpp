// The CPU renderer: draws a scene exactly as docs/spec.md §1–§4 define it.
#pragma once

#include <memory>

#include "litkit/image.hpp"
#include "litkit/scene.hpp"

namespace litkit {

struct RenderOptions {
    int threads = 0;  // 0: one per hardware thread
    // Used where the scene leaves [lighting] out (R10); the caller decides,
    // per R11, whether that is allowed.
    Reflection fallback_reflection = default_reflection;
    Shading fallback_shading = default_shading;
    // Per-pixel kernels: the fastest this CPU runs (AVX2+FMA where present),
    // or the portable ones (for comparing the two).
    enum class Kernels { Best, Portable };
    Kernels kernels = Kernels::Best;
};

// Holds a scene's prepared geometry (meshes, world-space vertices, normals)
// so that several frames can be drawn without rebuilding it.
class Renderer {
public:
    // Builds every object's mesh; throws IoError for an unreadable mesh file.
    explicit Renderer(const Scene& scene, RenderOptions options = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Draws one frame at the scene's output size.
    Image render();
    // Draws into `image`, reusing its storage (resized if needed).
    void render_into(Image& image);

    std::size_t triangle_count() const;
    int thread_count() const;
    // Pixels the last frame covered, each shaded once (hidden ones are not).
    std::size_t shaded_pixel_count() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// One-shot convenience: Renderer(scene, options).render().
Image render(const Scene& scene, RenderOptions options = {});

}  // namespace litkit
