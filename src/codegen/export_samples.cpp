// SPDX-License-Identifier: MIT
// Anti-aliasing in the exports (export_samples.hpp).
#include "codegen/export_samples.hpp"

#include "codegen/glsl_expr.hpp"
#include "litkit/image.hpp"
#include "litkit/samples.hpp"

namespace litkit::detail {

namespace {

// A C++ float literal that reads back as the same float (as export.cpp writes them).
std::string literal(float value) { return glsl::float_literal(value) + "f"; }

}  // namespace

// The rows of the program's sample_pattern: the scene's samples per pixel.
std::string samples_source(const Scene& scene) {
    std::string out;
    for (const SamplePosition& sample : sample_pattern(scene.output.samples)) {
        out += "    {";
        out += literal(sample.x);
        out += ", ";
        out += literal(sample.y);
        out += "},\n";
    }
    return out;
}

// `--format glsl` with several samples per pixel: what the host does with
// the programs' passes (docs/spec.md §11), for the fragment shader's
// heading comment.
std::string host_samples_comment(const Scene& scene) {
    const int samples = scene.output.samples;
    const Rgb8 bg = to_rgb8(scene.output.background);
    std::string text = "//\n// Anti-aliasing: the scene has ";
    text += std::to_string(samples);
    text +=
        " samples per pixel (litkit's docs/spec.md,\n"
        "// section 11), and this program writes one sample's light, not the pixel. The\n"
        "// host draws the frame once per sample k into an RGBA32F target cleared to\n"
        "// (0, 0, 0, 0), with\n"
        "//     u_view_projection = T_k * projection * view,\n"
        "// T_k the translation by (2 * (0.5 - x_k) / W, 2 * (y_k - 0.5) / H, 0) for a\n"
        "// picture of W x H pixels (here ";
    text += std::to_string(scene.output.width) + " x " + std::to_string(scene.output.height);
    text +=
        "), (x_k, y_k) the sample's place in its\n"
        "// pixel, from the pixel's top-left corner, y down:\n";
    int k = 0;
    for (const SamplePosition& sample : sample_pattern(samples)) {
        text += "//     k = " + std::to_string(k++) + ": (";
        text += glsl::float_literal(sample.x);
        text += ", ";
        text += glsl::float_literal(sample.y);
        text += ")\n";
    }
    text +=
        "// It reads each pass back as floats and, per pixel, adds the rgb of the passes\n"
        "// whose alpha is 1, in the order of k (S), and counts those whose alpha is 0,\n"
        "// which saw the background (n). The pixel is then\n"
        "//     round(255 * ((S + n * B^gamma) / ";
    text += std::to_string(samples);
    text +=
        ")^(1/gamma)), halves up,\n"
        "// B the background colour / 255 and gamma as the scene has them (here\n"
        "// [";
    text += std::to_string(bg[0]) + ", " + std::to_string(bg[1]) + ", " + std::to_string(bg[2]);
    text += "] / 255 and ";
    text += glsl::float_literal(scene.output.gamma);
    text +=
        "). A pixel whose samples all saw the background is\n"
        "// the background colour. `litkit export --format cpp` writes a program that\n"
        "// does all of this.\n";
    return text;
}

}  // namespace litkit::detail
