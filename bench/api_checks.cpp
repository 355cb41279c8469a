// SPDX-License-Identifier: MIT
// What the renderers' precondition check (check_renderable) costs
// next to the full validation and to a frame: timing only, nothing passes
// or fails. Run: cmake -DLITKIT_BUILD_BENCH=ON, build litkit_api_checks,
// then ./build/bench/litkit_api_checks.
#include <benchmark/benchmark.h>

#include <string>

#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/validate.hpp"

namespace {

// The default scene with `lights` point lights and `objects` small cubes in
// a grid (none overlapping), so that validate_scene has its full work.
litkit::Scene crowded(int lights, int objects) {
    litkit::Scene scene = litkit::default_scene();
    scene.room = {100.0f, 100.0f, 100.0f};
    scene.lights.clear();
    for (int i = 0; i < lights; ++i) {
        litkit::SceneLight light;
        light.light.kind = litkit::PointLight{.position = {-45.0f + 0.009f * i, 45.0f, 45.0f}};
        scene.lights.push_back(light);
    }
    const litkit::SceneObject cube = scene.objects.front();
    scene.objects.clear();
    for (int i = 0; i < objects; ++i) {
        litkit::SceneObject object = cube;
        object.position = {-40.0f + 2.0f * static_cast<float>(i % 40),
                           -40.0f + 2.0f * static_cast<float>(i / 40), 0.0f};
        scene.objects.push_back(object);
    }
    return scene;
}

void BM_CheckRenderable(benchmark::State& state) {
    const litkit::Scene scene =
        crowded(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    for (auto _ : state) litkit::check_renderable(scene);
}

void BM_ValidateScene(benchmark::State& state) {
    const litkit::Scene scene =
        crowded(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    for (auto _ : state) benchmark::DoNotOptimize(litkit::validate_scene(scene));
}

// A camera move through Renderer::update (the check included) and a frame
// of the default scene at 800x600.
void BM_UpdateCameraAndRenderDefault(benchmark::State& state) {
    litkit::Scene scene = litkit::default_scene();
    litkit::Renderer renderer(scene);
    litkit::Image image;
    float x = 3.5f;
    for (auto _ : state) {
        scene.observer.position.x = (x = -x);
        renderer.update(scene);
        renderer.render_into(image);
    }
}

}  // namespace

BENCHMARK(BM_CheckRenderable)->Args({1, 1})->Args({1000, 1000})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ValidateScene)->Args({1, 1})->Args({1000, 1000})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_UpdateCameraAndRenderDefault)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
