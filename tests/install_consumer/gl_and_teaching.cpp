// SPDX-License-Identifier: MIT
// Shades one point through the installed library and checks the number:
// Lambert, N = L = (0, 1, 0), light 1 unit above, so I = k_d · C · 1 = 0.7.
// Then draws the default scene with litkit::gl, the OpenGL backend, and
// checks that the middle pixel is the cube's (not the black background).
// Includes only the umbrella header (and litkit::gl's own), catches a bad
// scene as litkit::Error with its place, and draws a labelled compare grid
// (so the installed package brings FreeType and giflib along).
#include <litkit/gl_renderer.hpp>
#include <litkit/litkit.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>

int main() {
    litkit::Light light{litkit::PointLight{{0.0f, 1.0f, 0.0f}}};
    litkit::Material material;
    glm::vec3 color = litkit::shade(litkit::Reflection::Lambert, material, {&light, 1},
                                    {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 5.0f});
    std::printf("%.4f\n", color.x);
    if (std::fabs(color.x - 0.7f) >= 1e-5f) return 1;

    try {
        litkit::parse_scene("[room]\nwidth = 0\n", "bad.toml");
        return 1;
    } catch (const litkit::Error& error) {
        std::printf("caught: %s\n", error.what());
        if (error.location().file != "bad.toml" || error.location().line == 0) return 1;
    }
    litkit::CompareOptions options;
    options.tile_width = 40;
    options.tile_height = 30;
    if (litkit::compare_models(litkit::default_scene(), options).image.width <= 3 * 40) return 1;

    litkit::GlRenderer gl(litkit::default_scene());
    const litkit::Image image = gl.render();
    const std::uint8_t* middle = image.pixel(image.width / 2, image.height / 2);
    std::printf("%s: middle pixel %d %d %d\n", gl.description().c_str(), middle[0], middle[1],
                middle[2]);
    return middle[0] > 0 ? 0 : 1;
}
