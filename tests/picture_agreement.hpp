// SPDX-License-Identifier: MIT
// How close two pictures of one scene are, away from the edges of objects:
// the measure the OpenGL backend and the exported program are held to
// against the CPU backend (≥ 99.5% of such pixels within 2/255).
//
// "Away from edges": the CPU backend draws the scene once more with every
// object in a colour of its own (ambient light only, k_a = 1), which labels
// each pixel with the object covering it; a pixel counts when its 3×3
// neighbourhood carries one label. Rasterisers may disagree about which
// surface owns a pixel on a silhouette; they must not disagree about its
// lighting. With several samples per pixel the silhouettes' pixels are held
// to it as well (edge_agreement): they are averages of many samples.
#pragma once

#include <algorithm>
#include <cstdlib>

#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

namespace litkit_test {

inline constexpr double required_fraction = 0.995;

// Object i's label colour: (i + 1, 0, 255), exact under ambient light 1 and k_a 1.
inline litkit::Image labels(litkit::Scene scene) {
    litkit::Light ambient{litkit::AmbientLight{}};
    scene.lights = {litkit::SceneLight{"label", ambient}};
    scene.output.background = glm::vec3(0.0f);
    scene.output.gamma = 1.0f;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        litkit::SceneObject& object = scene.objects[i];
        object.material = {glm::vec3(static_cast<float>(i + 1), 0.0f, 255.0f) / 255.0f, 1.0f, 0.0f,
                           0.0f, 1.0f};
        object.shading = litkit::Shading::Flat;
    }
    return litkit::render(scene, {.fallback_shading = litkit::Shading::Flat});
}

struct Agreement {
    std::size_t counted = 0;  // interior pixels covered by an object
    std::size_t within = 0;   // of those, every channel within 2/255
    int worst = 0;
    std::size_t background_counted = 0;    // pixels with only background around them
    std::size_t background_differing = 0;  // of those, not exactly equal
    std::size_t pixels = 0;                // every pixel, edges included
    std::size_t pixels_within = 0;         // of those, every channel within 2/255
    double fraction() const { return counted ? double(within) / double(counted) : 0.0; }
    double fraction_of_all() const { return pixels ? double(pixels_within) / double(pixels) : 0.0; }
};

// Compares the pixels of `a` and `b` whose 3×3 neighbourhood in `label` is
// one object; also counts the background pixels that differ at all (both
// backends clear to the same colour exactly) and, for a coarse check that
// includes edges, every pixel.
inline Agreement agreement(const litkit::Image& a, const litkit::Image& b,
                           const litkit::Image& label) {
    Agreement result;
    auto label_at = [&](int x, int y) {
        const std::uint8_t* p = label.pixel(x, y);
        return (p[0] << 16) | (p[1] << 8) | p[2];
    };
    auto difference_at = [&](int x, int y) {
        int difference = 0;
        for (int c = 0; c < 3; ++c)
            difference =
                std::max(difference, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
        return difference;
    };
    for (int y = 0; y < label.height; ++y) {
        for (int x = 0; x < label.width; ++x) {
            ++result.pixels;
            result.pixels_within += difference_at(x, y) <= 2;
        }
    }
    for (int y = 1; y + 1 < label.height; ++y) {
        for (int x = 1; x + 1 < label.width; ++x) {
            const int centre = label_at(x, y);
            bool interior = true;
            for (int dy = -1; dy <= 1 && interior; ++dy)
                for (int dx = -1; dx <= 1 && interior; ++dx)
                    interior = label_at(x + dx, y + dy) == centre;
            if (!interior) continue;
            const int difference = difference_at(x, y);
            if (centre == 0) {
                ++result.background_counted;
                result.background_differing += difference != 0;
                continue;
            }
            ++result.counted;
            result.within += difference <= 2;
            result.worst = std::max(result.worst, difference);
        }
    }
    return result;
}

// With several samples per pixel (docs/spec.md §11): the pixels a
// silhouette crosses, some of their samples seeing an object and some the
// background, so that labels() drawn with the scene's samples (gamma 1,
// background black, every label's blue 255) has a blue strictly between 0
// and 255 there; `within`: of those, the pixels of `a` and `b` within 2/255
// in every channel.
struct EdgeAgreement {
    std::size_t edges = 0;
    std::size_t within = 0;
    double fraction() const { return edges ? double(within) / double(edges) : 0.0; }
};

inline EdgeAgreement edge_agreement(const litkit::Image& a, const litkit::Image& b,
                                    const litkit::Image& sampled_labels) {
    EdgeAgreement result;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const int blue = sampled_labels.pixel(x, y)[2];
            if (blue == 0 || blue == 255) continue;
            ++result.edges;
            int difference = 0;
            for (int c = 0; c < 3; ++c)
                difference =
                    std::max(difference, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
            result.within += difference <= 2;
        }
    }
    return result;
}

}  // namespace litkit_test
