// SPDX-License-Identifier: MIT
// litkit compare: the scene under every reflection × shading pair, one tile
// each, with the models' names in a margin.
#include "litkit/compare.hpp"
#include "litkit/error.hpp"
#include "litkit/limits.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>

#include "litkit/render.hpp"
#include "teach/labels.hpp"

namespace litkit {

namespace {

constexpr Rgb8 margin_color{24, 24, 28};
constexpr Rgb8 label_color{235, 235, 235};

// The scene as one tile shows it: these models for every object, at the
// tile's size.
Scene tile_scene(const Scene& scene, Reflection reflection, Shading shading, int width,
                 int height) {
    Scene tile = scene;
    tile.reflection = reflection;
    tile.shading = shading;
    tile.output.width = width;
    tile.output.height = height;
    for (SceneObject& object : tile.objects) {
        object.reflection.reset();
        object.shading.reset();
    }
    return tile;
}

void copy_tile(const Image& tile, Image& grid, int left, int top) {
    const std::size_t row_bytes = static_cast<std::size_t>(tile.width) * 3;
    for (int y = 0; y < tile.height; ++y)
        std::copy_n(tile.pixel(0, y), row_bytes, grid.pixel(left, top + y));
}

}  // namespace

CompareGrid compare_models(const Scene& scene, const CompareOptions& options) {
    CompareGrid grid;
    grid.tile_width =
        options.tile_width > 0 ? options.tile_width : std::max(1, scene.output.width / 2);
    grid.tile_height =
        options.tile_height > 0 ? options.tile_height : std::max(1, scene.output.height / 2);
    if (grid.tile_width > max_image_side || grid.tile_height > max_image_side)
        throw ArgumentError("compare_models: tiles are at most " + std::to_string(max_image_side) +
                            " pixels a side");

    const Reflection own_reflection = scene.reflection.value_or(options.fallback_reflection);
    const Shading own_shading = scene.shading.value_or(options.fallback_shading);
    if (options.vary != CompareOptions::Vary::Shading) {
        for (const ReflectionModel& model : reflection_models()) grid.rows.push_back(model.id);
    } else {
        grid.rows.push_back(own_reflection);
    }
    if (options.vary != CompareOptions::Vary::Reflection) {
        for (int s = 0; s < shading_count; ++s) grid.columns.push_back(static_cast<Shading>(s));
    } else {
        grid.columns.push_back(own_shading);
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].reflection || scene.objects[i].shading)
            grid.overridden_objects.push_back(i);

    // The margins, measured before anything is drawn.
    std::unique_ptr<detail::Font> font;
    int pad = 0;
    if (options.labels) {
        const int pixels = std::clamp(grid.tile_height / 14, 12, 32);
        font = std::make_unique<detail::Font>(pixels);
        pad = pixels / 2 + 4;
        int widest = 0;
        for (Reflection reflection : grid.rows)
            widest = std::max(widest, font->width(to_string(reflection)));
        grid.left_margin = widest + 2 * pad;
        grid.top_margin = font->ascent() + font->descent() + 2 * pad;
    }
    const int columns = static_cast<int>(grid.columns.size());
    const int rows = static_cast<int>(grid.rows.size());
    const long long width = grid.left_margin + static_cast<long long>(columns) * grid.tile_width;
    const long long height = grid.top_margin + static_cast<long long>(rows) * grid.tile_height;
    if (width > 65535 || height > 65535)
        throw ArgumentError("compare_models: the grid would be " + std::to_string(width) + "x" +
                            std::to_string(height) + " pixels; make the tiles smaller");
    grid.image = Image(static_cast<int>(width), static_cast<int>(height));
    for (std::size_t i = 0; i < grid.image.rgb.size(); i += 3)
        std::copy(margin_color.begin(), margin_color.end(),
                  grid.image.rgb.begin() + static_cast<long>(i));

    // Tiles in parallel, one single-threaded renderer each; an error in any
    // tile is rethrown here.
    const int tiles = rows * columns;
    unsigned workers = options.threads > 0 ? static_cast<unsigned>(options.threads)
                                           : std::max(1u, std::thread::hardware_concurrency());
    workers = std::min(workers, static_cast<unsigned>(tiles));
    std::atomic<int> next{0};
    std::vector<std::exception_ptr> failures(workers);
    auto work = [&](unsigned worker) {
        try {
            for (int t = next++; t < tiles; t = next++) {
                const int row = t / columns, column = t % columns;
                const Scene tile = tile_scene(scene, grid.rows[static_cast<std::size_t>(row)],
                                              grid.columns[static_cast<std::size_t>(column)],
                                              grid.tile_width, grid.tile_height);
                RenderOptions render_options;
                render_options.threads = 1;
                const Image image = Renderer(tile, render_options).render();
                copy_tile(image, grid.image, grid.left_margin + column * grid.tile_width,
                          grid.top_margin + row * grid.tile_height);
            }
        } catch (...) {
            failures[worker] = std::current_exception();
            next = tiles;  // the others stop too
        }
    };
    std::vector<std::thread> threads;
    for (unsigned w = 1; w < workers; ++w) threads.emplace_back(work, w);
    work(0);
    for (std::thread& thread : threads) thread.join();
    for (const std::exception_ptr& failure : failures)
        if (failure) std::rethrow_exception(failure);

    if (font) {
        // Column names centred over their tiles; row names right-aligned
        // beside theirs, centred vertically.
        const int baseline = pad + font->ascent();
        for (int column = 0; column < columns; ++column) {
            const std::string_view name = to_string(grid.columns[static_cast<std::size_t>(column)]);
            const int x = grid.left_margin + column * grid.tile_width +
                          (grid.tile_width - font->width(name)) / 2;
            font->draw(grid.image, x, baseline, name, label_color);
        }
        for (int row = 0; row < rows; ++row) {
            const std::string_view name = to_string(grid.rows[static_cast<std::size_t>(row)]);
            const int x = grid.left_margin - pad - font->width(name);
            const int y = grid.top_margin + row * grid.tile_height +
                          (grid.tile_height + font->ascent() - font->descent()) / 2;
            font->draw(grid.image, x, y, name, label_color);
        }
    }
    return grid;
}

}  // namespace litkit
