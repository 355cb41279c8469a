// SPDX-License-Identifier: MIT
// Programs specialised to a scene's lights: glsl::generate with
// the lights writes one block per light instead of the general loop, and the
// OpenGL backend draws with them up to 16 lights. The shaders must compile,
// hold the blocks in the scene's order, and draw the CPU backend's picture,
// also after GlRenderer::update changes what they were specialised to.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "litkit/gl_renderer.hpp"
#include "litkit/glsl.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "picture_agreement.hpp"

namespace {

using litkit::Reflection;
using litkit::Shading;

// One light of each kind: spot, ambient, directional, point (not in the
// order of the kinds' numbers, so that order mix-ups show).
std::vector<litkit::Light> four_kinds() {
    litkit::Light spot{litkit::SpotLight{
        {0.5f, 2.5f, 2.0f}, {1.0f, 0.0f, 0.02f}, {-0.3f, -1.0f, -0.9f}, 25.0f, 2.0f, 0.3f}};
    litkit::Light ambient{litkit::AmbientLight{}, glm::vec3(1.0f), 0.25f};
    litkit::Light directional{litkit::DirectionalLight{{1.0f, -1.0f, -0.5f}},
                              glm::vec3(0.6f, 0.7f, 1.0f), 0.5f};
    litkit::Light point{litkit::PointLight{{-1.5f, 1.0f, 2.0f}, {1.0f, 0.0f, 0.05f}},
                        glm::vec3(1.0f, 0.9f, 0.8f)};
    return {spot, ambient, directional, point};
}

litkit::Scene scene_with(const std::vector<litkit::Light>& lights, Reflection reflection,
                         Shading shading) {
    litkit::Scene scene;
    scene.output.width = 160;
    scene.output.height = 120;
    scene.output.background = litkit::from_rgb8({20, 30, 40});
    scene.observer.position = {0.0f, 1.0f, 4.0f};
    scene.reflection = reflection;
    scene.shading = shading;
    litkit::SceneObject sphere;
    sphere.shape = litkit::SphereShape{1.0f, 24, 12};
    sphere.position = {-0.6f, 0.0f, 0.0f};
    sphere.material = {glm::vec3(200.0f, 120.0f, 60.0f) / 255.0f, 0.2f, 0.7f, 0.6f, 24.0f};
    litkit::SceneObject cube;
    cube.shape = litkit::CubeShape{1.0f};
    cube.position = {1.0f, 0.0f, -0.5f};
    cube.rotation_degrees = {25.0f, 35.0f, 0.0f};
    cube.material = {glm::vec3(80.0f, 160.0f, 220.0f) / 255.0f, 0.3f, 0.6f, 0.4f, 8.0f};
    scene.objects = {sphere, cube};
    for (const litkit::Light& light : lights) scene.lights.push_back({"", light});
    return scene;
}

void expect_matches_cpu(const litkit::Image& gl, const litkit::Scene& scene,
                        const std::string& what) {
    const litkit::Image cpu = litkit::render(scene);
    const litkit_test::Agreement a = litkit_test::agreement(gl, cpu, litkit_test::labels(scene));
    EXPECT_GT(a.counted, 1000u) << what;
    EXPECT_GE(a.fraction(), litkit_test::required_fraction) << what << ": worst " << a.worst;
    EXPECT_EQ(a.background_differing, 0u) << what;
    EXPECT_GE(a.fraction_of_all(), 0.995) << what << ", edges included";
}

TEST(GlslSpecialised, OneBlockPerLightInTheScenesOrderAndNoLoop) {
    const std::vector<litkit::Light> lights = four_kinds();
    for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong, Shading::Faceted}) {
        const litkit::glsl::Shaders shaders =
            litkit::glsl::generate(Reflection::Phong, shading, lights, 1.0f);
        const std::string& lit = shading == Shading::Phong || shading == Shading::Faceted
                                     ? shaders.fragment
                                     : shaders.vertex;
        EXPECT_EQ(lit.find("for (int i = 0; i < u_light_count"), std::string::npos) << lit;
        EXPECT_EQ(lit.find("u_lights[i]."), std::string::npos);
        std::size_t at = 0;
        const char* const blocks[] = {"// light 0: spot", "// light 1: ambient",
                                      "// light 2: directional", "// light 3: point"};
        for (const char* block : blocks) {
            const std::size_t found = lit.find(block, at);
            ASSERT_NE(found, std::string::npos) << block << " (after offset " << at << ") in\n"
                                                << lit;
            at = found;
        }
        EXPECT_NE(lit.find("spot_factor(incidence.to_light, u_lights[0].direction"),
                  std::string::npos);
        EXPECT_NE(lit.find("ambient_term(u_lights[1].radiance, u_material)"), std::string::npos);
        EXPECT_NE(lit.find("directional_incidence(u_lights[2].direction)"), std::string::npos);
        EXPECT_NE(lit.find("point_incidence(u_lights[3].position, u_lights[3].attenuation, p)"),
                  std::string::npos);
        EXPECT_NE(lit.find("const int MAX_LIGHTS = 4;"), std::string::npos);
    }
    // The general program keeps its loop.
    EXPECT_NE(litkit::glsl::generate(Reflection::Phong, Shading::Phong, 4)
                  .fragment.find("for (int i = 0; i < u_light_count"),
              std::string::npos);
}

TEST(GlslSpecialised, GammaOneLeavesThePowerOut) {
    const std::vector<litkit::Light> lights = four_kinds();
    const std::string power = "c = pow(c, vec3(u_inv_gamma));";
    EXPECT_EQ(litkit::glsl::generate(Reflection::Lambert, Shading::Phong, lights, 1.0f)
                  .fragment.find(power),
              std::string::npos);
    EXPECT_NE(litkit::glsl::generate(Reflection::Lambert, Shading::Phong, lights, 2.2f)
                  .fragment.find(power),
              std::string::npos);
    EXPECT_NE(litkit::glsl::generate(Reflection::Lambert, Shading::Phong, 4).fragment.find(power),
              std::string::npos);
}

TEST(GlslSpecialised, NoLightsIsAProgramToo) {
    const litkit::glsl::Shaders shaders =
        litkit::glsl::generate(Reflection::Phong, Shading::Phong, {}, 1.0f);
    EXPECT_NE(shaders.fragment.find("const int MAX_LIGHTS = 1;"), std::string::npos);
    EXPECT_NE(shaders.fragment.find("vec3 total = vec3(0.0);\n    return total;"),
              std::string::npos);
}

int validator_exit(const std::string& arguments) {
    // Appended in place: GCC 12 at -O1 warns (-Warray-bounds, a false
    // positive) on the chain of operator+ temporaries.
    std::string command = LITKIT_GLSLANG_VALIDATOR;
    command.append(" ").append(arguments).append(" >/dev/null 2>&1");
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(GlslSpecialised, EveryModelCompilesAndLinksWithGlslangValidator) {
    ASSERT_FALSE(std::string(LITKIT_GLSLANG_VALIDATOR).empty())
        << "glslangValidator was not found when the build was configured (scripts/install-deps.sh)";
    const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                         ("litkit-specialised-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    for (const litkit::ReflectionModel& model : litkit::reflection_models()) {
        for (Shading shading :
             {Shading::Flat, Shading::Gouraud, Shading::Phong, Shading::Faceted}) {
            // Gamma 1 differs only by the power left out; one model is enough.
            std::vector<float> gammas{2.2f};
            if (model.id == Reflection::Phong) gammas.push_back(1.0f);
            for (float gamma : gammas) {
                const litkit::glsl::Shaders shaders =
                    litkit::glsl::generate(model.id, shading, four_kinds(), gamma);
                const std::filesystem::path vertex = folder / "p.vert",
                                            fragment = folder / "p.frag";
                std::ofstream(vertex) << shaders.vertex;
                std::ofstream(fragment) << shaders.fragment;
                EXPECT_EQ(
                    validator_exit("-l '" + vertex.string() + "' '" + fragment.string() + "'"), 0)
                    << model.name << " / " << litkit::to_string(shading) << " gamma " << gamma
                    << "\n"
                    << shaders.vertex << "\n"
                    << shaders.fragment;
            }
        }
    }
    std::filesystem::remove_all(folder);
}

TEST(GlSpecialised, EveryKindOfLightInOneSceneMatchesCpu) {
    for (Reflection reflection :
         {Reflection::Lambert, Reflection::BlinnPhong, Reflection::CookTorrance}) {
        for (Shading shading :
             {Shading::Flat, Shading::Gouraud, Shading::Phong, Shading::Faceted}) {
            litkit::Scene scene = scene_with(four_kinds(), reflection, shading);
            for (float gamma : {1.0f, 2.2f}) {
                scene.output.gamma = gamma;
                expect_matches_cpu(litkit::GlRenderer(scene).render(), scene,
                                   std::string(litkit::to_string(reflection)) + "/" +
                                       std::string(litkit::to_string(shading)) + " gamma " +
                                       std::to_string(gamma));
            }
        }
    }
}

TEST(GlSpecialised, UpdateFollowsNewKindsNewValuesAndGamma) {
    litkit::Scene scene = scene_with(four_kinds(), Reflection::Phong, Shading::Phong);
    litkit::GlRenderer gl(scene);
    expect_matches_cpu(gl.render(), scene, "as built");

    // New values only: the same programs, the new picture.
    litkit::Scene brighter = scene;
    brighter.lights[3].light.intensity = 2.5f;
    std::get<litkit::PointLight>(brighter.lights[3].light.kind).position = {1.5f, 0.5f, 2.5f};
    gl.update(brighter);
    const litkit::Image bright = gl.render();
    expect_matches_cpu(bright, brighter, "new light values");

    // The point light becomes a directional one: the programs must follow.
    litkit::Scene turned = brighter;
    turned.lights[3].light.kind = litkit::DirectionalLight{{-1.0f, -0.2f, -1.0f}};
    gl.update(turned);
    expect_matches_cpu(gl.render(), turned, "a point light made directional");

    // Gamma leaves 1, then comes back.
    litkit::Scene corrected = turned;
    corrected.output.gamma = 2.2f;
    gl.update(corrected);
    expect_matches_cpu(gl.render(), corrected, "gamma 2.2");
    gl.update(brighter);
    EXPECT_EQ(gl.render().rgb, bright.rgb) << "back to the earlier scene";
}

TEST(GlSpecialised, BeyondSixteenLightsTheGeneralProgramDraws) {
    // 17 lights take the general program, 16 the specialised one: both draw
    // the CPU's picture.
    for (int count : {16, 17}) {
        std::vector<litkit::Light> lights;
        for (int i = 0; i < count; ++i) {
            const float angle = 0.37f * static_cast<float>(i);
            lights.push_back(i % 4 == 1
                                 ? litkit::Light{litkit::AmbientLight{}, glm::vec3(1.0f), 0.02f}
                                 : litkit::Light{litkit::PointLight{{3.0f * std::cos(angle), 1.5f,
                                                                     3.0f * std::sin(angle)},
                                                                    {1.0f, 0.0f, 0.0f}},
                                                 glm::vec3(1.0f), 0.06f});
        }
        const litkit::Scene scene = scene_with(lights, Reflection::BlinnPhong, Shading::Phong);
        expect_matches_cpu(litkit::GlRenderer(scene).render(), scene,
                           std::to_string(count) + " lights");
    }
}

}  // namespace
