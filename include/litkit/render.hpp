// SPDX-License-Identifier: MIT
/// \file
/// The CPU renderer: draws a scene exactly as docs/spec.md §1–§4 define it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include <glm/vec3.hpp>

#include "litkit/image.hpp"
#include "litkit/ray_tree.hpp"
#include "litkit/scene.hpp"

namespace litkit {

/// The most threads a Renderer starts: the largest RenderOptions::threads allowed.
inline constexpr int max_render_threads = 1024;

/// How a Renderer draws: its threads, the models used where the scene gives
/// none, and the per-pixel kernels.
struct RenderOptions {
    /// The threads that draw a frame: 0 for one per hardware thread (1 if that
    /// is unknown), else 1–max_render_threads. Outside 0–max_render_threads
    /// the Renderer throws ArgumentError.
    int threads = 0;
    /// The reflection model used where the scene leaves [lighting] out (R10);
    /// the caller decides, per R11, whether that is allowed.
    Reflection fallback_reflection = default_reflection;
    /// The shading model used where the scene leaves it out (as fallback_reflection).
    Shading fallback_shading = default_shading;
    /// Per-pixel kernels: the fastest this CPU runs (AVX-512, else AVX2+FMA,
    /// else portable), or one set by name (for comparing them; a set the CPU
    /// lacks is an ArgumentError, see kernel_set_available). Every set draws
    /// the same bytes.
    enum class Kernels {
        Best,      ///< AVX-512 where the CPU has it, else AVX2+FMA, else portable.
        Portable,  ///< The portable kernels, on any CPU.
        Avx2,      ///< The AVX2+FMA kernels (8 lanes).
        Avx512     ///< The AVX-512 kernels (16 lanes).
    };
    /// Which per-pixel kernels to run.
    Kernels kernels = Kernels::Best;
};

/// One sample of a pixel with several (docs/spec.md §11), as the renderer
/// shaded it.
struct SampleProbe {
    SamplePosition position{0.5f, 0.5f};  ///< within the pixel (litkit/samples.hpp)
    bool hit = false;                     ///< false: the background
    std::size_t object = 0;               ///< index into Scene::objects, when hit
    /// L_k: the sample's light clamped to [0, 1], or (background)^γ.
    glm::vec3 light{0.0f};
};

/// What the renderer computed at one pixel (litkit explain): the triangle it
/// shows, the perspective-correct weights of its corners, the values the
/// fragment stage interpolated from them, the colour before clamping and the
/// pixel written.
struct PixelProbe {
    bool hit = false;                         ///< false: the background
    std::size_t object = 0;                   ///< index into Scene::objects
    std::size_t triangle = 0;                 ///< within the object's mesh
    std::array<std::uint32_t, 3> vertices{};  ///< the mesh vertex at each corner
    bool clipped = false;                     ///< a piece of a triangle crossing the near plane
    std::array<float, 3> weights{};           ///< q0, q1, q2: perspective-correct, summing to 1
    glm::vec3 position{
        0.0f};  ///< Phong shading: p, on the pixel's ray at its depth (docs/spec.md §3)
    glm::vec3 normal{0.0f};     ///< Phong shading: N interpolated, before renormalising
    glm::vec3 intensity{0.0f};  ///< I before clamping and gamma, as shaded
    Rgb8 rgb{};                 ///< the pixel
    /// The pixel's ray tree where its first surface is glass (t > 0,
    /// docs/spec.md §10.2), its first node the camera's ray; else empty.
    std::vector<RayNode> ray_tree;
    /// With several samples per pixel: each sample, in the order of
    /// docs/spec.md §11's table, whose mean gives `rgb`; every field above
    /// but `rgb` then describes the pixel's centre, as one sample would.
    /// Empty with one sample.
    std::vector<SampleProbe> samples;
};

/// Whether this CPU runs the given set of per-pixel kernels.
bool kernel_set_available(RenderOptions::Kernels kernels);

/// The CPU renderer. Holds a scene's prepared geometry (meshes, world-space
/// vertices, normals) so that several frames can be drawn without
/// rebuilding it.
///
/// Preconditions, checked (never assumed, in any build type): the scene
/// passes check_renderable (litkit/validate.hpp: every value in range and
/// finite, a usable view, an image of 1–max_image_side pixels each way, in-memory
/// meshes well formed), else SceneError listing every problem; options.threads
/// in 0–max_render_threads, else ArgumentError. Both derive from
/// litkit::Error. The constructor and update() check them; a failed update
/// leaves the renderer drawing the scene it had. The relations between
/// entities (overlaps, objects outside the room) are validate_scene's, which
/// load_scene runs: the renderer does not repeat that (costly) check and
/// draws such a scene as it is.
class Renderer {
  public:
    /// Checks the preconditions (SceneError, ArgumentError), then builds every
    /// object's mesh; throws IoError for an unreadable mesh file.
    explicit Renderer(const Scene& scene, RenderOptions options = {});
    /// Stops the worker threads.
    ~Renderer();
    /// Not copyable: it owns a thread pool and the prepared meshes.
    Renderer(const Renderer&) = delete;
    /// Not copyable either.
    Renderer& operator=(const Renderer&) = delete;

    /// Draws one frame at the scene's output size.
    Image render();
    /// Draws into `image`, reusing its storage (resized if needed).
    void render_into(Image& image);

    /// The scene to draw from now on. Meshes and normals are kept when every
    /// object keeps its shape, parameters and place (a new observer, image
    /// size, models, materials, lights or gamma cost only the rendering);
    /// otherwise they are built again. A mesh file is not read again unless
    /// its object changed.
    void update(const Scene& scene);
    /// How often the meshes were built (once at construction; again by an
    /// update that moved, reshaped, added or removed an object).
    std::size_t mesh_builds() const;

    /// Draws the pixel's band of rows (every stage before it for the whole
    /// frame) and reports how pixel (x, y) got its value. Throws
    /// ArgumentError outside the image.
    PixelProbe probe(int x, int y);

    /// The triangles of every object together, as prepared.
    std::size_t triangle_count() const;
    /// The threads that draw a frame (RenderOptions::threads, 0 resolved).
    int thread_count() const;
    /// The set of per-pixel kernels in use: "avx512", "avx2" or "portable".
    const char* kernel_set() const;
    /// Pixels the last frame covered, each shaded once (hidden ones are not;
    /// after probe(), those of the pixel's band); with several samples per
    /// pixel, the samples that saw an object.
    std::size_t shaded_pixel_count() const;
    /// Rays the last frame cast from the surfaces of glass (docs/spec.md
    /// §10: the pixels' own rays are not cast, the rasterizer finds their
    /// first hit); 0 for a scene without glass.
    std::uint64_t traced_ray_count() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// One-shot convenience: Renderer(scene, options).render(), with the same
/// preconditions and the same errors.
Image render(const Scene& scene, RenderOptions options = {});

}  // namespace litkit
