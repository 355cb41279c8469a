// SPDX-License-Identifier: MIT
// litkit bench: frames rendered into memory, and the time per frame.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "backend_renderer.hpp"
#include "commands.hpp"
#include "litkit/image.hpp"
#include "options.hpp"

namespace litkit_cli {

namespace {

struct BenchArguments {
    SceneArguments scene;
    int frames = 20;
};

// Renders frames into memory and reports their times. One warm-up frame
// first; median and minimum of the rest (timing, not a test: nothing here
// passes or fails on speed).
int run_bench(const BenchArguments& arguments) {
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, true);

    using clock = std::chrono::steady_clock;
    const auto setup_start = clock::now();
    BackendRenderer renderer(arguments.scene.backend_id(), scene,
                             {.threads = arguments.scene.threads.value_or(0)});
    const double setup_ms =
        std::chrono::duration<double, std::milli>(clock::now() - setup_start).count();
    litkit::Image image;
    renderer.render_into(image);  // warm-up
    std::vector<double> frame_ms;
    for (int frame = 0; frame < arguments.frames; ++frame) {
        const auto start = clock::now();
        renderer.render_into(image);
        frame_ms.push_back(std::chrono::duration<double, std::milli>(clock::now() - start).count());
    }
    std::sort(frame_ms.begin(), frame_ms.end());
    const std::size_t n = frame_ms.size();
    const double median = n % 2 ? frame_ms[n / 2] : 0.5 * (frame_ms[n / 2 - 1] + frame_ms[n / 2]);
    const std::vector<std::string>& files = arguments.scene.scenes;
    std::printf("scene: %s\n", files.empty() ? "(default)" : files.front().c_str());
    std::printf("renderer: %s\n", renderer.description().c_str());
    std::printf("image: %dx%d, %zu triangles\n", image.width, image.height,
                renderer.triangle_count());
    std::printf("setup: %.3f ms (%s)\n", setup_ms, std::string(renderer.setup_steps()).c_str());
    if (const auto shaded = renderer.shaded_pixel_count()) {
        const int samples = scene.output.samples;
        const double share = 100.0 * static_cast<double>(*shaded) /
                             (static_cast<double>(image.width) * image.height * samples);
        if (samples == 1)
            std::printf("pixels shaded: %zu per frame (%.1f%% of the image)\n", *shaded, share);
        else
            std::printf("samples shaded: %zu per frame (%.1f%% of the image's %d per pixel)\n",
                        *shaded, share, samples);
    }
    std::printf("frames: %d, median %.3f ms, min %.3f ms\n", arguments.frames, median,
                frame_ms.front());
    if (const std::uint64_t rays = renderer.traced_ray_count()) {
        // Glass (docs/spec.md §10): the rays cast from surfaces, per frame.
        std::printf("rays traced: %llu per frame, %.2f million per second of the frame\n",
                    static_cast<unsigned long long>(rays),
                    static_cast<double>(rays) / (median * 1e3));
    }
    std::printf("median_frame_ms=%.3f fps=%.1f\n", median, 1000.0 / median);
    return exit_success;
}

}  // namespace

Command add_bench(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<BenchArguments>();
    CLI::App* bench =
        app.add_subcommand("bench", "Render frames into memory and report the time per frame");
    if (defines(*bench)) {
        add_scene_options(bench, arguments->scene);
        bench->add_option("--frames", arguments->frames, "Frames to time (after one warm-up)")
            ->check(CLI::Range(1, 100000));
    }
    return {.app = bench, .run = [arguments] { return run_bench(*arguments); }, .renders = true};
}

}  // namespace litkit_cli
