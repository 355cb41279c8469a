// SPDX-License-Identifier: MIT
// Google Benchmark microbenchmarks of the inner loops: shading a block of
// pixels (each kernel set, and the scalar public function), and whole frames
// of small scenes, where triangle setup and rasterization dominate.
// Timing only: nothing here passes or fails.
#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/thread_pool.hpp"
#include "cpu/shade_kernel.hpp"
#include "litkit/image.hpp"
#include "litkit/lighting.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/shapes.hpp"
#include "trace/accel.hpp"

namespace {

// A row of 1024 pixels of a unit sphere seen from z = 4 (its middle row:
// each pixel's view depth and normal), lit by a point and an ambient light:
// a block of a full-screen Phong fill.
struct Block {
    std::vector<float> w, nx, ny, nz, r, g, b;
    std::vector<litkit::equations::PreparedLight> lights;
    litkit::Material material;
    // Looking down −z with a 1024-pixel row spanning x ∈ [−1, 1] at z = 0.
    litkit::RowRays rays{{0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, -1.0f}, {0.25f / 1024.0f, 0.0f, 0.0f}};

    explicit Block(std::size_t count) {
        for (std::size_t i = 0; i < count; ++i) {
            // The ray (x, 0, −1) from the eye meets the sphere at the nearer root.
            const float k = static_cast<float>(2 * i + 1) - static_cast<float>(count);
            const float x = k * rays.across[0];
            const float a = x * x + 1.0f, b = -8.0f, c = 15.0f;  // |eye + t·d|² = 1
            const float disc = std::max(b * b - 4.0f * a * c, 0.0f);
            const float t = (-b - std::sqrt(disc)) / (2.0f * a);
            w.push_back(t);
            const float px = t * x, pz = 4.0f - t;
            const float length = std::sqrt(px * px + pz * pz);
            nx.push_back(px / length), ny.push_back(0.0f), nz.push_back(pz / length);
        }
        r.resize(count), g.resize(count), b.resize(count);
        lights.push_back(litkit::equations::prepare_light(
            litkit::Light{litkit::PointLight{{2.0f, 2.0f, 3.0f}}, {1, 1, 1}, 12.0f}));
        lights.push_back(litkit::equations::prepare_light(
            litkit::Light{litkit::AmbientLight{}, {1, 1, 1}, 0.3f}));
    }
};

void shade_block(benchmark::State& state, const litkit::kernels::Kernels& kernels,
                 litkit::Reflection reflection) {
    Block block(1024);
    const litkit::kernels::SurfaceRun surface{
        &block.rays,     1.0f - static_cast<float>(block.w.size()),
        block.w.data(),  block.nx.data(),
        block.ny.data(), block.nz.data(),
        block.w.size()};
    for (auto _ : state) {
        kernels.shade_phong(reflection, block.lights, block.material, surface,
                            {block.r.data(), block.g.data(), block.b.data()});
        benchmark::DoNotOptimize(block.r.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(block.w.size()));
}

void BM_ShadeBlockAvx512Phong(benchmark::State& state) {
    if (!litkit::kernels::cpu_has_avx512()) {
        state.SkipWithError("this CPU lacks AVX-512");
        return;
    }
    shade_block(state, litkit::kernels::avx512_kernels, litkit::Reflection::Phong);
}
void BM_ShadeBlockAvx2Phong(benchmark::State& state) {
    if (!litkit::kernels::cpu_has_avx2()) {
        state.SkipWithError("this CPU lacks AVX2");
        return;
    }
    shade_block(state, litkit::kernels::avx2_kernels, litkit::Reflection::Phong);
}
void BM_ShadeBlockPortablePhong(benchmark::State& state) {
    shade_block(state, litkit::kernels::portable_kernels, litkit::Reflection::Phong);
}
void BM_ShadeBlockAvx2Lambert(benchmark::State& state) {
    if (!litkit::kernels::cpu_has_avx2()) {
        state.SkipWithError("this CPU lacks AVX2");
        return;
    }
    shade_block(state, litkit::kernels::avx2_kernels, litkit::Reflection::Lambert);
}

// The public scalar function, one point at a time (what a student calls).
void BM_ShadeScalarPublic(benchmark::State& state) {
    const litkit::Light lights[2] = {
        litkit::Light{litkit::PointLight{{2.0f, 2.0f, 3.0f}}, {1, 1, 1}, 12.0f},
        litkit::Light{litkit::AmbientLight{}, {1, 1, 1}, 0.3f}};
    const litkit::Material material;
    for (auto _ : state) {
        benchmark::DoNotOptimize(litkit::shade(litkit::Reflection::Phong, material, lights,
                                               {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f},
                                               {0.0f, 0.0f, 4.0f}));
    }
    state.SetItemsProcessed(state.iterations());
}

// Whole frames: vertex, setup, rasterize and shade of one object.
void frame(benchmark::State& state, litkit::Shape shape, int width, int height,
           litkit::Shading shading = litkit::Shading::Phong) {
    litkit::Scene scene = litkit::default_scene();
    scene.objects.resize(1);
    scene.objects[0].shape = shape;
    scene.objects[0].shading = shading;
    scene.output.width = width;
    scene.output.height = height;
    litkit::Renderer renderer(scene, {.threads = 1});
    litkit::Image image;
    for (auto _ : state) renderer.render_into(image);
    state.counters["triangles"] = static_cast<double>(renderer.triangle_count());
    state.counters["pixels"] = static_cast<double>(renderer.shaded_pixel_count());
}

void BM_FrameCube640x480(benchmark::State& state) {
    frame(state, litkit::CubeShape{2.0f}, 640, 480);
}
void BM_FrameSphere65kTriangles640x480(benchmark::State& state) {
    frame(state, litkit::SphereShape{1.0f, 256, 128}, 640, 480);
}

// PNG encoding of the default scene at 800×600 per level (1: ISA-L where
// the build has it; the others zlib): time, and the file size as a counter
// (the choice of level and deflater in image.cpp).
void BM_EncodeDefaultScenePng(benchmark::State& state) {
    const litkit::Image image = litkit::render(litkit::default_scene(), {.threads = 1});
    std::size_t bytes = 0;
    for (auto _ : state) bytes = litkit::encode_png(image, static_cast<int>(state.range(0))).size();
    state.counters["bytes"] = static_cast<double>(bytes);
}

// The stages in isolation, as far as a whole frame allows: a 261k-triangle
// sphere drawn 64×48 is all vertex work, clipping, setup and binning (each
// triangle covers almost no pixel); a flat-shaded sphere filling 1920×1080
// is all rasterization and visibility (one colour per triangle, no lighting
// per pixel).
void BM_StageSetup261kTriangles(benchmark::State& state) {
    frame(state, litkit::SphereShape{1.0f, 512, 256}, 64, 48, litkit::Shading::Phong);
}
void BM_StageRasterizeFlatFill1920x1080(benchmark::State& state) {
    // Radius 3 about the default cube's centre fills the default view.
    frame(state, litkit::SphereShape{3.0f, 64, 32}, 1920, 1080, litkit::Shading::Flat);
}

// docs/spec.md §9.2: the world mesh of a 261k-triangle sphere (build, weld,
// normals, transform) per way of computing normals, without and with a
// crease; against mean without crease, the cost of each option.
void BM_WorldMesh261kNormals(benchmark::State& state) {
    litkit::SceneObject object;
    object.shape = litkit::SphereShape{1.5f, 512, 256};
    const litkit::NormalOptions options{
        static_cast<litkit::Normals>(state.range(0)),
        state.range(1) ? std::optional<float>(60.0f) : std::nullopt};
    for (auto _ : state)
        benchmark::DoNotOptimize(litkit::world_mesh(object, options).normals.data());
    state.SetLabel(std::string(litkit::to_string(options.normals)) +
                   (state.range(1) ? ", crease 60" : ""));
}

// The tracer's hierarchy over a 261k-triangle sphere (radius 1, 512 × 256):
// its build on two threads, and rays per second on one thread (as the
// renderer's threads each trace their own rays) and on two.
struct TraceSphere {
    litkit::Mesh mesh = litkit::make_sphere(1.0f, 512, 256);
    std::vector<litkit::trace::MeshView> objects{{mesh.positions, mesh.triangles}};
};

litkit::ParallelFor lend(litkit::ThreadPool& pool) {
    return [&pool](std::size_t count, const litkit::ParallelJob& job) {
        pool.parallel_for(count, [&](std::size_t i, int) { job(i); });
    };
}

void BM_TraceBuild261k(benchmark::State& state) {
    const TraceSphere sphere;
    litkit::ThreadPool pool(static_cast<int>(state.range(0)));
    const litkit::ParallelFor parallel = state.range(0) > 1 ? lend(pool) : litkit::ParallelFor{};
    for (auto _ : state) {
        const litkit::trace::Accel accel(sphere.objects, parallel);
        benchmark::DoNotOptimize(&accel);
    }
    state.SetLabel(std::to_string(state.range(0)) + " thread(s)");
}

// (a) 800 × 600 camera rays from z = 3 towards the sphere (fov 45°, which
// it about fills vertically), nearest front faces; (b) rays from random
// points inside it in random directions, nearest back faces.
std::vector<litkit::trace::Ray> camera_rays() {
    std::vector<litkit::trace::Ray> rays;
    const float tan_half = 0.41421356f, aspect = 800.0f / 600.0f;
    for (int j = 0; j < 600; ++j)
        for (int i = 0; i < 800; ++i) {
            const float x = (2.0f * (i + 0.5f) / 800.0f - 1.0f) * tan_half * aspect;
            const float y = (1.0f - 2.0f * (j + 0.5f) / 600.0f) * tan_half;
            rays.push_back({{0.0f, 0.0f, 3.0f}, {x, y, -1.0f}});
        }
    return rays;
}

std::vector<litkit::trace::Ray> inside_rays() {
    std::mt19937 random(1);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<litkit::trace::Ray> rays;
    while (rays.size() < 480'000) {
        const glm::vec3 p(unit(random), unit(random), unit(random));
        if (glm::dot(p, p) > 0.81f) continue;
        rays.push_back({p, {unit(random), unit(random), unit(random)}});
    }
    return rays;
}

void trace_rays(benchmark::State& state, const std::vector<litkit::trace::Ray>& rays, bool inside) {
    const TraceSphere sphere;
    const litkit::trace::Accel accel(sphere.objects);
    const int threads = static_cast<int>(state.range(0));
    litkit::ThreadPool pool(threads);
    std::vector<std::size_t> found(static_cast<std::size_t>(threads) * 16);
    for (auto _ : state) {
        const std::size_t bands = 64, band = rays.size() / bands;
        pool.parallel_for(bands, [&](std::size_t b, int worker) {
            std::size_t hits = 0;
            for (std::size_t i = b * band; i < (b + 1) * band; ++i)
                hits += (inside ? accel.nearest_back(rays[i], 0) : accel.nearest_front(rays[i]))
                            .found();
            found[static_cast<std::size_t>(worker) * 16] += hits;
        });
    }
    benchmark::DoNotOptimize(found.data());
    state.SetItemsProcessed(state.iterations() * static_cast<long>(rays.size() / 64 * 64));
    state.SetLabel(std::to_string(threads) + " thread(s)");
}

void BM_TraceCameraRays800x600(benchmark::State& state) { trace_rays(state, camera_rays(), false); }
void BM_TraceInsideRays(benchmark::State& state) { trace_rays(state, inside_rays(), true); }

}  // namespace

BENCHMARK(BM_TraceBuild261k)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TraceCameraRays800x600)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TraceInsideRays)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WorldMesh261kNormals)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StageSetup261kTriangles)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StageRasterizeFlatFill1920x1080)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EncodeDefaultScenePng)
    ->Arg(0)
    ->Arg(1)
    ->Arg(3)
    ->Arg(6)
    ->Arg(9)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShadeBlockAvx512Phong);
BENCHMARK(BM_ShadeBlockAvx2Phong);
BENCHMARK(BM_ShadeBlockPortablePhong);
BENCHMARK(BM_ShadeBlockAvx2Lambert);
BENCHMARK(BM_ShadeScalarPublic);
BENCHMARK(BM_FrameCube640x480)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrameSphere65kTriangles640x480)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
