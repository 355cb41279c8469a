// SPDX-License-Identifier: MIT
// Tests of the teaching tools (src/teach): `litkit compare` and `litkit
// turntable`, through the library and the command line. Every picture is
// checked against `litkit render` of the same settings, never against a
// stored picture.
#include <gif_lib.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>

#include "core/json.hpp"
#include "litkit/compare.hpp"
#include "litkit/explain.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/turntable.hpp"
#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;
using litkit_test::run_command;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

class Teach : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("litkit-teach-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    litkit_test::CommandRun cli(const std::string& arguments) const {
        return run_command("cd " + quoted(dir) + " && '" LITKIT_CLI "' " + arguments);
    }
    litkit::Image png(const std::string& name) const { return litkit::read_png(dir / name); }

    fs::path dir;
};

// The w×h block of `image` at (left, top).
litkit::Image crop(const litkit::Image& image, int left, int top, int w, int h) {
    litkit::Image out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) std::copy_n(image.pixel(left + x, top + y), 3, out.pixel(x, y));
    return out;
}

const char* const shadings[] = {"flat", "gouraud", "phong", "faceted"};
const char* const reflections[] = {"lambert",     "half-lambert", "phong",
                                   "blinn-phong", "oren-nayar",   "cook-torrance",
                                   "toon",        "minnaert",     "gooch"};

}  // namespace

TEST_F(Teach, CompareWithoutLabelsIsExactlyTheRenderOfEachPair) {
    const auto made = cli("compare --no-labels --width 80 --height 60 -o grid.png");
    ASSERT_EQ(made.status, 0) << made.output;
    const litkit::Image grid = png("grid.png");
    ASSERT_EQ(grid.width, 4 * 80);
    ASSERT_EQ(grid.height, 9 * 60);
    for (int row = 0; row < 9; ++row) {
        for (int column = 0; column < 4; ++column) {
            const std::string name = std::to_string(row) + "-" + std::to_string(column) + ".png";
            const auto rendered =
                cli(std::string("render --reflection ") + reflections[row] + " --shading " +
                    shadings[column] + " --width 80 --height 60 -o " + name);
            ASSERT_EQ(rendered.status, 0) << rendered.output;
            EXPECT_EQ(crop(grid, column * 80, row * 60, 80, 60).rgb, png(name).rgb)
                << reflections[row] << " x " << shadings[column];
        }
    }
}

TEST_F(Teach, CompareDefaultTilesAreTheScenesSizeHalved) {
    litkit::CompareOptions options;
    options.labels = false;
    const litkit::CompareGrid grid = litkit::compare_models(litkit::default_scene(), options);
    EXPECT_EQ(grid.tile_width, 400);
    EXPECT_EQ(grid.tile_height, 300);
    EXPECT_EQ(grid.image.width, litkit::shading_count * 400);
    EXPECT_EQ(grid.image.height, litkit::reflection_count * 300);
    EXPECT_EQ(grid.rows.size(), static_cast<std::size_t>(litkit::reflection_count));
}

TEST_F(Teach, LabelsSitInAMarginAndLeaveTheTilesAlone) {
    litkit::CompareOptions options;
    options.tile_width = 120;
    options.tile_height = 90;
    options.labels = false;
    const litkit::Scene scene = litkit::default_scene();
    const litkit::CompareGrid bare = litkit::compare_models(scene, options);
    options.labels = true;
    const litkit::CompareGrid labelled = litkit::compare_models(scene, options);
    ASSERT_GT(labelled.left_margin, 0);
    ASSERT_GT(labelled.top_margin, 0);
    EXPECT_EQ(labelled.image.width, labelled.left_margin + litkit::shading_count * 120);
    EXPECT_EQ(labelled.image.height, labelled.top_margin + litkit::reflection_count * 90);
    // The tiles are untouched by the labels.
    EXPECT_EQ(crop(labelled.image, labelled.left_margin, labelled.top_margin,
                   litkit::shading_count * 120, litkit::reflection_count * 90)
                  .rgb,
              bare.image.rgb);
    // Text was drawn: light pixels in the margin beside each row and over each column.
    auto has_text = [&](int left, int top, int w, int h) {
        for (int y = top; y < top + h; ++y)
            for (int x = left; x < left + w; ++x)
                if (labelled.image.pixel(x, y)[0] > 150) return true;
        return false;
    };
    for (int row = 0; row < litkit::reflection_count; ++row)
        EXPECT_TRUE(has_text(0, labelled.top_margin + row * 90, labelled.left_margin, 90)) << row;
    for (int column = 0; column < litkit::shading_count; ++column)
        EXPECT_TRUE(has_text(labelled.left_margin + column * 120, 0, 120, labelled.top_margin))
            << column;
    // The corner above the row labels stays empty.
    EXPECT_FALSE(has_text(0, 0, labelled.left_margin, labelled.top_margin));
}

TEST_F(Teach, VaryGivesOneColumnOrOneRowWithTheScenesOtherModel) {
    litkit::Scene scene = litkit::default_scene();
    scene.reflection = litkit::Reflection::Toon;
    scene.shading = litkit::Shading::Gouraud;
    litkit::CompareOptions options;
    options.labels = false;
    options.tile_width = 64;
    options.tile_height = 48;
    options.vary = litkit::CompareOptions::Vary::Reflection;
    const litkit::CompareGrid column = litkit::compare_models(scene, options);
    ASSERT_EQ(column.columns.size(), 1u);
    EXPECT_EQ(column.columns[0], litkit::Shading::Gouraud);
    EXPECT_EQ(column.rows.size(), static_cast<std::size_t>(litkit::reflection_count));
    EXPECT_EQ(column.image.width, 64);
    options.vary = litkit::CompareOptions::Vary::Shading;
    const litkit::CompareGrid row = litkit::compare_models(scene, options);
    ASSERT_EQ(row.rows.size(), 1u);
    EXPECT_EQ(row.rows[0], litkit::Reflection::Toon);
    EXPECT_EQ(row.columns.size(), static_cast<std::size_t>(litkit::shading_count));
    // The toon/gouraud tile appears in both, identical.
    EXPECT_EQ(crop(column.image, 0, 6 * 48, 64, 48).rgb, crop(row.image, 64, 0, 64, 48).rgb);
}

TEST_F(Teach, CompareReplacesObjectsOwnModelsAndSaysSo) {
    const fs::path example = fs::path(LITKIT_SOURCE_DIR) / "examples" / "reflection-models.toml";
    const auto made =
        cli("compare " + quoted(example) + " --no-labels --width 80 --height 60 -o grid.png");
    ASSERT_EQ(made.status, 0) << made.output;
    EXPECT_NE(made.output.find("set their own models"), std::string::npos) << made.output;
    EXPECT_NE(made.output.find("'blinn-phong'"), std::string::npos) << made.output;
    // Tile (lambert, flat) is the scene with every override removed.
    litkit::Scene scene = litkit::load_scene(std::span(&example, 1));
    for (litkit::SceneObject& object : scene.objects) object.reflection.reset();
    scene.reflection = litkit::Reflection::Lambert;
    scene.shading = litkit::Shading::Flat;
    scene.output.width = 80;
    scene.output.height = 60;
    EXPECT_EQ(crop(png("grid.png"), 0, 0, 80, 60).rgb, litkit::render(scene).rgb);
}

TEST_F(Teach, CompareRefusesToWriteOverItsScene) {
    std::ofstream(dir / "scene.toml") << litkit::default_scene_toml();
    const auto refused = cli("compare scene.toml -o scene.toml");
    EXPECT_EQ(refused.status, 2) << refused.output;
    EXPECT_NE(refused.output.find("refusing to write over input"), std::string::npos);
    std::ifstream in(dir / "scene.toml");
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first, "# litkit scene: the built-in default scene.");
}

// Frame k of N is the scene with its observer turned k·360°/N about the up
// axis through look_at: computed here independently (the default scene's up
// is +y, so a rotation in the xz-plane) and rendered by `litkit render`.
TEST_F(Teach, TurntableFrameKIsTheRenderWithTheObserverTurned) {
    constexpr int frames = 8;
    // The default scene in a room large enough for `render` to accept every
    // observer on the circle (the turntable itself draws any).
    std::string base(litkit::default_scene_toml());
    for (const std::string key : {"width = 10", "height = 10", "depth = 10"}) {
        const std::size_t at = base.find(key);
        ASSERT_NE(at, std::string::npos) << key;
        base.replace(at, key.size(), key.substr(0, key.size() - 2) + "30");
    }
    std::ofstream(dir / "base.toml") << base;
    const auto made = cli("turntable base.toml --frames 8 --width 160 --height 120 -o frames/");
    ASSERT_EQ(made.status, 0) << made.output;
    const fs::path base_path = dir / "base.toml";
    const litkit::Scene scene = litkit::load_scene(std::span(&base_path, 1));
    const double px = scene.observer.position.x - scene.observer.look_at.x;
    const double pz = scene.observer.position.z - scene.observer.look_at.z;
    for (int k : {0, 1, 3, 6}) {
        const double angle = 2.0 * M_PI * k / frames;
        // Counter-clockwise seen from above (+y): x' = x cos + z sin, z' = −x sin + z cos.
        const double x = scene.observer.look_at.x + px * std::cos(angle) + pz * std::sin(angle);
        const double z = scene.observer.look_at.z - px * std::sin(angle) + pz * std::cos(angle);
        std::string text = base;
        const std::string old_position = "position = [3.5, 1, 4]";
        const std::size_t at = text.find(old_position);
        ASSERT_NE(at, std::string::npos);
        char position[128];
        std::snprintf(position, sizeof position, "position = [%.9g, 1, %.9g]",
                      static_cast<double>(static_cast<float>(x)),
                      static_cast<double>(static_cast<float>(z)));
        text.replace(at, old_position.size(), position);
        const std::string name = "turned-" + std::to_string(k);
        std::ofstream(dir / (name + ".toml")) << text;
        const auto rendered =
            cli("render " + name + ".toml --width 160 --height 120 -o " + name + ".png");
        ASSERT_EQ(rendered.status, 0) << rendered.output;
        char frame[32];
        std::snprintf(frame, sizeof frame, "frames/frame-%03d.png", k);
        EXPECT_EQ(png(frame).rgb, png(name + ".png").rgb) << "frame " << k;
    }
    EXPECT_TRUE(fs::exists(dir / "frames" / "frame-007.png"));
    EXPECT_FALSE(fs::exists(dir / "frames" / "frame-008.png"));
}

TEST_F(Teach, TurntableGifHasEveryFrameReducedToAPalette) {
    const auto gif_made = cli("turntable --frames 6 --width 96 --height 72 -o spin.gif");
    ASSERT_EQ(gif_made.status, 0) << gif_made.output;
    const auto png_made = cli("turntable --frames 6 --width 96 --height 72 -o frames/");
    ASSERT_EQ(png_made.status, 0) << png_made.output;
    // No progress bar without a terminal: one summary line.
    EXPECT_EQ(gif_made.output.find('\r'), std::string::npos) << gif_made.output;
    EXPECT_EQ(gif_made.output.find("frames/s"), std::string::npos) << gif_made.output;

    int error = 0;
    GifFileType* gif = DGifOpenFileName((dir / "spin.gif").c_str(), &error);
    ASSERT_NE(gif, nullptr) << GifErrorString(error);
    ASSERT_EQ(DGifSlurp(gif), GIF_OK);
    ASSERT_EQ(gif->ImageCount, 6);
    EXPECT_EQ(gif->SWidth, 96);
    EXPECT_EQ(gif->SHeight, 72);
    for (int k = 0; k < gif->ImageCount; ++k) {
        const SavedImage& image = gif->SavedImages[k];
        const ColorMapObject* map =
            image.ImageDesc.ColorMap ? image.ImageDesc.ColorMap : gif->SColorMap;
        ASSERT_NE(map, nullptr);
        char name[32];
        std::snprintf(name, sizeof name, "frames/frame-%03d.png", k);
        const litkit::Image expected = png(name);
        // The palette picture is close to the frame (2.5-2.9 measured): mean error under 4
        // levels a channel, no pixel off by more than 48 (median cut on a
        // smooth render).
        double total = 0.0;
        int worst = 0;
        for (int i = 0; i < 96 * 72; ++i) {
            const GifColorType c = map->Colors[image.RasterBits[i]];
            const int channels[3] = {c.Red, c.Green, c.Blue};
            for (int ch = 0; ch < 3; ++ch) {
                const int d = std::abs(channels[ch] - expected.rgb[3 * i + ch]);
                total += d;
                worst = std::max(worst, d);
            }
        }
        EXPECT_LT(total / (96 * 72 * 3), 4.0) << "frame " << k;
        EXPECT_LE(worst, 48) << "frame " << k;
    }
    DGifCloseFile(gif, &error);
}

TEST_F(Teach, TurntableShowsProgressOnATerminal) {
    // `script` gives the command a pseudo-terminal.
    const auto made =
        run_command("cd " + quoted(dir) +
                    " && script -qec \"'" LITKIT_CLI
                    "' turntable --frames 4 --width 32 --height 24 -o spin.gif\" /dev/null");
    ASSERT_EQ(made.status, 0) << made.output;
    EXPECT_NE(made.output.find("4/4 frames"), std::string::npos) << made.output;
    EXPECT_NE(made.output.find("frames/s"), std::string::npos) << made.output;
}

TEST(Orbit, TurnsAboutTheUpAxisThroughLookAt) {
    litkit::Observer observer;
    observer.position = {2, 1, 0};
    observer.look_at = {1, 1, 0};
    observer.up = {0, 0, 2};  // about +z, not normalised
    const litkit::Observer quarter = litkit::orbit(observer, 90.0);
    // (1, 0, 0) from look_at, turned 90° counter-clockwise about +z: (0, 1, 0).
    EXPECT_NEAR(quarter.position.x, 1.0f, 1e-6f);
    EXPECT_NEAR(quarter.position.y, 2.0f, 1e-6f);
    EXPECT_NEAR(quarter.position.z, 0.0f, 1e-6f);
    EXPECT_EQ(quarter.look_at, observer.look_at);
    EXPECT_EQ(quarter.up, observer.up);
    const litkit::Observer full = litkit::orbit(observer, 360.0);
    EXPECT_NEAR(full.position.x, 2.0f, 1e-6f);
    EXPECT_NEAR(full.position.y, 1.0f, 1e-6f);
}

TEST(Gif, RefusesFramesOfDifferentSizesAndWritesNothing) {
    const fs::path path =
        fs::temp_directory_path() / ("litkit-gif-" + std::to_string(::getpid()) + ".gif");
    std::vector<litkit::Image> frames{litkit::Image(4, 4), litkit::Image(5, 4)};
    EXPECT_THROW(litkit::write_gif(frames, path), litkit::IoError);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_THROW(litkit::write_gif(std::span<const litkit::Image>{}, path), litkit::IoError);
}

// ---- litkit explain ----

namespace {

// Nine small balls, one per reflection model, under all four kinds of light,
// every object drawn with `shading`.
litkit::Scene model_balls(litkit::Shading shading, float gamma) {
    litkit::Scene scene;
    scene.room = {12.0f, 12.0f, 12.0f};
    scene.observer.position = {0.0f, 0.5f, 5.0f};
    scene.output = {54, 40, litkit::from_rgb8({10, 20, 30}), gamma};
    scene.reflection = litkit::Reflection::Phong;
    scene.shading = shading;
    litkit::Light ambient{litkit::AmbientLight{}, glm::vec3(1.0f), 0.2f};
    litkit::Light sun{litkit::DirectionalLight{{-1.0f, -1.0f, -0.7f}}, glm::vec3(1.0f, 0.95f, 0.9f),
                      0.6f};
    litkit::Light bulb{litkit::PointLight{{2.0f, 2.0f, 2.0f}, {0.5f, 0.0f, 0.1f}}, glm::vec3(1.0f),
                       2.0f};
    litkit::SpotLight cone;
    cone.position = {-1.5f, 2.5f, 2.0f};
    cone.direction = {0.5f, -1.0f, -0.8f};
    cone.cutoff_degrees = 25.0f;
    cone.exponent = 2.0f;
    cone.penumbra = 0.3f;
    litkit::Light spot{cone, glm::vec3(1.0f, 0.8f, 0.6f), 3.0f};
    scene.lights = {{"fill", ambient}, {"sun", sun}, {"bulb", bulb}, {"spot", spot}};
    int i = 0;
    for (const litkit::ReflectionModel& model : litkit::reflection_models()) {
        litkit::SceneObject ball;
        ball.name = std::string(model.name);
        ball.shape = litkit::SphereShape{0.45f, 16, 8};
        ball.position = {-1.1f + 1.1f * static_cast<float>(i % 3),
                         1.1f - 1.1f * static_cast<float>(i / 3), 0.0f};
        ball.reflection = model.id;
        ball.material.color = glm::vec3(0.8f, 0.5f, 0.3f);
        scene.objects.push_back(ball);
        ++i;
    }
    return scene;
}

// Every pixel of the scene: explain's rgb is render's pixel; the parts add
// up to the sum; the sum gives the pixel.
// One explainer serves every pixel in turn, so a pixel's explanation must
// not lean on the one before. It draws on one thread (each pixel's drawing
// is too small to share), the picture it is held to on the default count.
void expect_every_pixel_explained(const litkit::Scene& scene, const std::string& label) {
    const litkit::Image image = litkit::render(scene);
    litkit::PixelExplainer explainer(scene, litkit::RenderOptions{.threads = 1});
    int hits = 0, checked = 0;
    for (int y = 0; y < scene.output.height; ++y) {
        for (int x = 0; x < scene.output.width; ++x) {
            const litkit::PixelExplanation e = explainer.explain(x, y);
            const std::uint8_t* pixel = image.pixel(x, y);
            ASSERT_EQ(e.rgb, (litkit::Rgb8{pixel[0], pixel[1], pixel[2]}))
                << label << " pixel " << x << "," << y;
            ++checked;
            if (!e.hit) {
                EXPECT_EQ(e.rgb, litkit::to_rgb8(scene.output.background))
                    << label << " " << x << "," << y;
                continue;
            }
            ++hits;
            // The parts: each light's contribution (Gouraud: each corner's
            // sum, mixed with the weights) add up to I, to float rounding.
            glm::vec3 total{0.0f};
            if (e.shading == litkit::Shading::Gouraud) {
                ASSERT_EQ(e.evaluations.size(), 3u);
                for (int k = 0; k < 3; ++k) {
                    glm::vec3 corner{0.0f};
                    for (const litkit::LightTerms& light :
                         e.evaluations[static_cast<std::size_t>(k)].terms.lights)
                        corner += light.contribution;
                    total += e.weights[static_cast<std::size_t>(k)] * corner;
                }
            } else {
                ASSERT_EQ(e.evaluations.size(), 1u);
                for (const litkit::LightTerms& light : e.evaluations[0].terms.lights)
                    total += light.contribution;
            }
            if (!e.clipped) {
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(total[c], e.sum[c], 2e-5f * std::max(1.0f, std::abs(e.sum[c])))
                        << label << " pixel " << x << "," << y << " channel " << c;
            }
            // round(255 · clamp(I)^(1/γ)) is the pixel.
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(litkit::to_pixel(e.sum[c], scene.output.gamma),
                          e.rgb[static_cast<std::size_t>(c)])
                    << label << " pixel " << x << "," << y << " channel " << c;
        }
    }
    EXPECT_GT(hits, checked / 10) << label << ": the objects cover too little to test";
}

}  // namespace

TEST(Explain, EveryPixelOfEveryModelPairAndLightKind) {
    for (litkit::Shading shading : {litkit::Shading::Flat, litkit::Shading::Gouraud,
                                    litkit::Shading::Phong, litkit::Shading::Faceted}) {
        for (float gamma : {1.0f, 2.2f}) {
            const std::string label =
                std::string(litkit::to_string(shading)) + " gamma " + std::to_string(gamma);
            expect_every_pixel_explained(model_balls(shading, gamma), label);
        }
    }
}

TEST(Explain, EveryPixelOfTheDefaultScene) {
    litkit::Scene scene = litkit::default_scene();
    scene.output.width = 64;
    scene.output.height = 48;
    expect_every_pixel_explained(scene, "default");
}

TEST(Explain, AnExplainerGivesWhatExplainPixelGivesInAnyOrder) {
    litkit::Scene scene = model_balls(litkit::Shading::Gouraud, 2.2f);
    litkit::PixelExplainer explainer(scene);
    // Pixels on two different balls and the background, the first again
    // last, and the scene changed after the explainer copied it.
    const std::array<std::array<int, 2>, 4> pixels{{{14, 10}, {41, 29}, {0, 0}, {14, 10}}};
    const litkit::Scene original = scene;
    scene.lights.clear();
    for (const auto& [x, y] : pixels) {
        const litkit::PixelExplanation a = explainer.explain(x, y);
        const litkit::PixelExplanation b = litkit::explain_pixel(original, x, y);
        EXPECT_EQ(a.rgb, b.rgb) << x << "," << y;
        EXPECT_EQ(a.hit, b.hit) << x << "," << y;
        EXPECT_EQ(a.object, b.object) << x << "," << y;
        EXPECT_EQ(a.triangle, b.triangle) << x << "," << y;
        EXPECT_EQ(a.corners, b.corners) << x << "," << y;
        EXPECT_EQ(a.sum, b.sum) << x << "," << y;
        ASSERT_EQ(a.evaluations.size(), b.evaluations.size()) << x << "," << y;
        for (std::size_t k = 0; k < a.evaluations.size(); ++k)
            EXPECT_EQ(a.evaluations[k].terms.total, b.evaluations[k].terms.total);
    }
    EXPECT_TRUE(explainer.explain(14, 10).hit);
    EXPECT_NE(explainer.explain(41, 29).object, explainer.explain(14, 10).object);
    EXPECT_THROW(explainer.explain(54, 0), litkit::ArgumentError);
    EXPECT_THROW(explainer.explain(0, -1), litkit::ArgumentError);
}

TEST(Explain, ShowsTheOrangeCubesCentreStepByStep) {
    // The default scene's pixel (400, 300): on the cube, phong/phong, one
    // point light. The text names the object, the models and every symbol.
    const litkit::Scene scene = litkit::default_scene();
    const litkit::PixelExplanation e = litkit::explain_pixel(scene, 400, 300);
    ASSERT_TRUE(e.hit);
    EXPECT_EQ(e.object_name, "cube");
    const std::string text = litkit::explanation_text(e, scene);
    for (const char* expected :
         {"visible: objects[0] 'cube' (cube)", "reflection phong, shading phong",
          "V = normalize(eye - p)", "lights[0] 'bulb' (point)", "N.L = ", "clamp to [0, 1]",
          "rgb = round(255 * that)"})
        EXPECT_NE(text.find(expected), std::string::npos) << expected << " in\n" << text;
    // The weights are perspective-correct barycentrics: they sum to 1, and
    // mixing the corners with them gives the point lit.
    EXPECT_NEAR(e.weights[0] + e.weights[1] + e.weights[2], 1.0f, 1e-6f);
    glm::vec3 p{0.0f};
    for (int k = 0; k < 3; ++k)
        p += e.weights[static_cast<std::size_t>(k)] * e.corners[static_cast<std::size_t>(k)];
    EXPECT_NEAR(glm::length(p - e.evaluations.at(0).position), 0.0f, 1e-5f);
}

TEST_F(Teach, ExplainJsonHasTheKeysAndParses) {
    const auto made = cli("explain --pixel 400,300 --json");
    ASSERT_EQ(made.status, 0) << made.output;
    std::ofstream(dir / "out.json") << made.output;
    // Python's json module parses it and finds the keys docs/learning.md lists.
    const auto parsed = run_command(
        "python3 -c \"import json,sys; d=json.load(open('" + (dir / "out.json").string() +
        "')); ks=['pixel','hit','object','triangle','reflection','shading','position','normal',"
        "'lights','sum','rgb']; missing=[k for k in ks if k not in d]; "
        "lk=['name','type','diffuse','specular','factor','contribution']; "
        "missing+=[k for k in lk if k not in d['lights'][0]]; print('missing', missing); "
        "sys.exit(1 if missing or d['pixel']!=[400,300] or not d['hit'] else 0)\"");
    EXPECT_EQ(parsed.status, 0) << parsed.output << made.output;
    // Background: only the pixel, hit false and rgb.
    const auto background = cli("explain --pixel 0,0 --json");
    ASSERT_EQ(background.status, 0);
    EXPECT_EQ(background.output, "{\"pixel\": [0, 0], \"hit\": false, \"rgb\": [25, 28, 36]}\n");
}

// JSON has no NaN or infinity: the one writer (core/json.hpp) that explain
// --json and the playground share writes a non-finite number as null.
TEST(JsonWriter, NonFiniteNumbersAreNullAndStringsAreEscaped) {
    EXPECT_EQ(litkit::json::number(std::nanf("")), "null");
    EXPECT_EQ(litkit::json::number(INFINITY), "null");
    EXPECT_EQ(litkit::json::number(-std::numeric_limits<double>::infinity()), "null");
    EXPECT_EQ(litkit::json::number(0.1f), "0.1");
    EXPECT_EQ(litkit::json::number(0.25), "0.25");
    EXPECT_EQ(litkit::json::number(-3.0f), "-3");
    EXPECT_EQ(litkit::json::string("a\"b\\c\nd\x01"), "\"a\\\"b\\\\c\\u000ad\\u0001\"");
    EXPECT_EQ(litkit::json::string("é"), "\"é\"");
}

TEST(JsonWriter, ExplainJsonWritesNonFiniteValuesAsNull) {
    const litkit::Scene scene = litkit::default_scene();
    litkit::PointEvaluation point;
    point.normal = {0.0f, 1.0f, 0.0f};
    point.terms.total = {std::nanf(""), INFINITY, 1.0f};
    const std::string json = litkit::evaluation_json(point, scene, litkit::Reflection::Phong);
    EXPECT_NE(json.find("\"sum\": [null, null, 1]"), std::string::npos) << json;
    EXPECT_EQ(json.find("nan"), std::string::npos) << json;
    EXPECT_EQ(json.find("inf"), std::string::npos) << json;
}

TEST_F(Teach, ExplainGouraudListsTheThreeVertices) {
    const auto made = cli("explain --pixel 400,300 --shading gouraud --json");
    ASSERT_EQ(made.status, 0) << made.output;
    EXPECT_NE(made.output.find("\"vertices\": [{"), std::string::npos) << made.output;
    EXPECT_NE(made.output.find("\"weights\": ["), std::string::npos) << made.output;
}

TEST_F(Teach, ExplainAtAPointChecksHomework) {
    // The default scene's light: a point light at the origin, intensity 15,
    // attenuation 1/d². At p = (0, -2, 0) with N = (0, 1, 0) and the cube's
    // material (C = (200, 80, 60)/255, k_d = 0.7, k_s = 0.5, α = 32), phong:
    // L = (0, 1, 0), d = 2, f = 1/4, N·L = 1, D = 1; R = (0, 1, 0);
    // V = normalize((3.5, 1, 4) − p) = (3.5, 3, 4)/√(37.25);
    // R·V = 3/6.10328 = 0.491539, S = 0.491539^32 = 1.3e-10 (tiny).
    // I_r = 15/4 · (0.7 · 200/255) = 2.058824 → clamped to 1 → 255.
    // I_g = 15/4 · (0.7 · 80/255) = 0.823529 → round(210.0) = 210.
    // I_b = 15/4 · (0.7 · 60/255) = 0.617647 → round(157.5) = 158.
    const auto made = cli("explain --at 0,-2,0 --normal 0,2,0 --json");
    ASSERT_EQ(made.status, 0) << made.output;
    EXPECT_NE(made.output.find("\"rgb\": [255, 210, 158]"), std::string::npos) << made.output;
    EXPECT_NE(made.output.find("\"factor\": 0.25"), std::string::npos) << made.output;
    // The sum, by hand: (2.058824, 0.823529, 0.617647).
    const std::size_t at = made.output.rfind("\"sum\": [");
    ASSERT_NE(at, std::string::npos) << made.output;
    float r = 0, g = 0, b = 0;
    ASSERT_EQ(std::sscanf(made.output.c_str() + at, "\"sum\": [%f, %f, %f]", &r, &g, &b), 3);
    EXPECT_NEAR(r, 2.058824f, 1e-5f);
    EXPECT_NEAR(g, 0.823529f, 1e-5f);
    EXPECT_NEAR(b, 0.617647f, 1e-5f);
    const auto text = cli("explain --at 0,-2,0 --normal 0,1,0");
    EXPECT_NE(text.output.find("L = (0, 1, 0), f = 0.25"), std::string::npos) << text.output;
    EXPECT_EQ(cli("explain --at 0,0,0").status, 2);
    EXPECT_EQ(cli("explain").status, 2);
    EXPECT_EQ(cli("explain --pixel 800,0").status, 2);
}
