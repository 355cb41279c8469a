// Shades one point through the installed library and checks the number:
// Lambert, N = L = (0, 1, 0), light 1 unit above, so I = k_d · C · 1 = 0.7.
#include <litkit/lighting.hpp>

#include <cmath>
#include <cstdio>

int main() {
    litkit::Light light{litkit::PointLight{{0.0f, 1.0f, 0.0f}}};
    litkit::Material material;
    glm::vec3 color = litkit::shade(litkit::Reflection::Lambert, material, {&light, 1},
                                    {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 5.0f});
    std::printf("%.4f\n", color.x);
    return std::fabs(color.x - 0.7f) < 1e-5f ? 0 : 1;
}
