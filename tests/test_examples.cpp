// SPDX-License-Identifier: MIT
// Every scene under examples/ loads and draws something.
//
// A scene is either one .toml file directly in examples/, or a folder of
// examples/ whose .toml files are rendered together (examples/multi-file:
// objects.toml + lights.toml, as docs/examples.md renders it). Each is drawn
// small and must cover a visible part of the picture, so that an example
// whose objects all miss the camera fails here rather than in the gallery.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

namespace {

namespace fs = std::filesystem;

// examples/ has one scene per light type (4), reflection model (4), shading
// model (3) and shape (5), the four models side by side and the multi-file
// scene: fewer than this means the search below went wrong.
constexpr std::size_t minimum_example_count = 18;

constexpr int test_width = 160;
constexpr int test_height = 120;
constexpr double minimum_covered_fraction = 0.02;

struct Example {
    std::string name;             // "spot-light", "multi-file"
    std::vector<fs::path> files;  // loaded together, in this order
};

// How GoogleTest shows a parameter in its messages.
void PrintTo(const Example& example, std::ostream* out) {
    *out << example.name << " (";
    for (std::size_t i = 0; i < example.files.size(); ++i)
        *out << (i ? " " : "") << example.files[i].filename().string();
    *out << ")";
}

bool is_scene_file(const fs::directory_entry& entry) {
    return entry.is_regular_file() && entry.path().extension() == ".toml";
}

std::vector<Example> find_examples() {
    const fs::path root = fs::path(LITKIT_SOURCE_DIR) / "examples";
    std::vector<Example> examples;
    if (!fs::is_directory(root)) return examples;
    for (const fs::directory_entry& entry : fs::directory_iterator(root)) {
        if (is_scene_file(entry)) {
            examples.push_back({entry.path().stem().string(), {entry.path()}});
        } else if (entry.is_directory()) {
            // A folder is one scene split over its files (docs/spec.md §5); the
            // lights and objects arrays do not depend on which file comes
            // first, so sorted order is as good as any.
            Example example{entry.path().filename().string(), {}};
            for (const fs::directory_entry& file : fs::directory_iterator(entry.path()))
                if (is_scene_file(file)) example.files.push_back(file.path());
            std::sort(example.files.begin(), example.files.end());
            if (!example.files.empty()) examples.push_back(std::move(example));
        }
    }
    std::sort(examples.begin(), examples.end(),
              [](const Example& a, const Example& b) { return a.name < b.name; });
    return examples;
}

std::string test_name(const testing::TestParamInfo<Example>& info) {
    std::string name = info.param.name;
    std::replace_if(
        name.begin(), name.end(),
        [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
}

std::size_t pixels_unlike_background(const litkit::Image& image, const litkit::Rgb8& background) {
    std::size_t count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* pixel = image.pixel(x, y);
            if (pixel[0] != background[0] || pixel[1] != background[1] || pixel[2] != background[2])
                ++count;
        }
    return count;
}

class ExampleScene : public testing::TestWithParam<Example> {};

TEST_P(ExampleScene, LoadsRendersAndCoversAVisiblePartOfThePicture) {
    const Example& example = GetParam();
    litkit::Scene scene;
    ASSERT_NO_THROW(scene = litkit::load_scene(example.files));

    // Every example states its models in [lighting], so that it renders
    // without asking (R11).
    EXPECT_TRUE(scene.reflection.has_value()) << "no [lighting] reflection";
    EXPECT_TRUE(scene.shading.has_value()) << "no [lighting] shading";

    scene.output.width = test_width;
    scene.output.height = test_height;
    litkit::Image image;
    ASSERT_NO_THROW(image = litkit::render(scene));
    ASSERT_EQ(image.width, test_width);
    ASSERT_EQ(image.height, test_height);

    const std::size_t covered =
        pixels_unlike_background(image, litkit::to_rgb8(scene.output.background));
    const std::size_t total = static_cast<std::size_t>(test_width) * test_height;
    EXPECT_GE(static_cast<double>(covered), minimum_covered_fraction * static_cast<double>(total))
        << covered << " of " << total << " pixels differ from the background";
}

// Written back with scene_to_toml (the viewer's "Save as") into another
// folder, the scene reads as the same scene: the same picture, byte for byte.
TEST_P(ExampleScene, WrittenBackAsTomlReadsAsTheSamePicture) {
    const Example& example = GetParam();
    litkit::Scene scene = litkit::load_scene(example.files);
    scene.output.width = test_width;
    scene.output.height = test_height;
    const fs::path folder = fs::temp_directory_path() / ("litkit-written-" + example.name);
    fs::create_directories(folder / "deeper");
    const fs::path written = folder / "deeper" / (example.name + ".toml");
    {
        std::ofstream out(written);
        out << litkit::scene_to_toml(scene, written);
    }
    litkit::Scene read_back;
    ASSERT_NO_THROW(read_back = litkit::load_scene(std::span(&written, 1)))
        << litkit::scene_to_toml(scene, written);
    EXPECT_EQ(litkit::render(read_back).rgb, litkit::render(scene).rgb);
    // And writing it again gives the same text.
    EXPECT_EQ(litkit::scene_to_toml(read_back, written), litkit::scene_to_toml(scene, written));
    fs::remove_all(folder);
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleScene, testing::ValuesIn(find_examples()), test_name);

TEST(ExamplesFolder, HoldsEveryDocumentedExample) {
    EXPECT_GE(find_examples().size(), minimum_example_count)
        << "looked in " << (fs::path(LITKIT_SOURCE_DIR) / "examples");
}

}  // namespace
