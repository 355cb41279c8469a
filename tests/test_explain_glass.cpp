// SPDX-License-Identifier: MIT
// Tests of `litkit explain` on pixels that see glass (docs/spec.md §10.3):
// the ray tree in text and JSON. The scenes are built in code; the angles
// and Fresnel factors are checked against the laws' angle form, computed
// here, not against the tracer's vector form.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <string>

#include "litkit/explain.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;

// A glass ball (t = 1, n = 1.5, a faint blue tint) in front of four opaque
// cubes, on a grey-blue background, under an ambient and a directional light.
litkit::Scene glass_scene(int width, int height) {
    litkit::Scene scene;
    scene.room = {20.0f, 20.0f, 20.0f};
    scene.observer.position = {0.0f, 0.0f, 6.0f};
    scene.output = {width, height, litkit::from_rgb8({40, 60, 90}), 2.2f};
    scene.reflection = litkit::Reflection::Phong;
    scene.shading = litkit::Shading::Phong;
    scene.lights = {
        {"sun", {litkit::DirectionalLight{{-0.3f, -0.4f, -1.0f}}, glm::vec3(1.0f), 1.0f}},
        {"fill", {litkit::AmbientLight{}, glm::vec3(1.0f), 0.3f}}};
    const glm::vec3 colors[] = {
        {1.0f, 0.2f, 0.2f}, {0.2f, 1.0f, 0.2f}, {0.2f, 0.2f, 1.0f}, {1.0f, 1.0f, 0.2f}};
    for (int i = 0; i < 4; ++i) {
        litkit::SceneObject cube;
        cube.name = "cube" + std::to_string(i);
        cube.shape = litkit::CubeShape{1.2f};
        cube.position = {-0.8f + 1.6f * static_cast<float>(i % 2),
                         -0.8f + 1.6f * static_cast<float>(i / 2), -3.0f};
        cube.material.color = colors[i];
        scene.objects.push_back(cube);
    }
    litkit::SceneObject ball;
    ball.name = "lens";
    ball.shape = litkit::SphereShape{1.5f, 48, 24};
    ball.position = {0.0f, 0.0f, 1.0f};
    ball.material.color = glm::vec3(1.0f);
    ball.material.transmission = 1.0f;
    ball.material.ior = 1.5f;
    ball.material.absorption_color = {0.8f, 0.9f, 1.0f};
    ball.material.absorption_distance = 2.0f;
    scene.objects.push_back(ball);
    return scene;
}

glm::vec3 contributions(const litkit::PixelExplanation& e) {
    glm::vec3 sum{0.0f};
    for (const litkit::RayNode& n : e.ray_tree) sum += n.contribution;
    return sum;
}

}  // namespace

TEST(ExplainGlass, FirstInterfaceFollowsSnellAndFresnel) {
    const litkit::Scene scene = glass_scene(80, 60);
    // Off centre, so that θ₁ is well away from 0.
    const litkit::PixelExplanation e = litkit::explain_pixel(scene, 52, 20);
    ASSERT_TRUE(e.hit);
    ASSERT_EQ(e.object_name, "lens");
    ASSERT_FALSE(e.ray_tree.empty());
    const litkit::RayNode& first = e.ray_tree[0];
    EXPECT_EQ(first.kind, litkit::RayNode::Kind::Camera);
    EXPECT_EQ(first.outcome, litkit::RayNode::Outcome::Interface);
    EXPECT_EQ(first.depth, 1);
    EXPECT_EQ(first.parent, -1);
    EXPECT_FALSE(first.inside);
    EXPECT_EQ(first.object, e.object);
    EXPECT_EQ(first.triangle, e.triangle);
    EXPECT_FLOAT_EQ(first.n1, 1.0f);
    EXPECT_FLOAT_EQ(first.n2, 1.5f);
    // θ₁ from the eye, the point hit and the normal there: the corners'
    // vertex normals mixed by the point's barycentric weights, renormalised
    // (phong), all in double precision.
    const glm::dvec3 p(first.point);
    const glm::dvec3 a(e.corners[0]), b(e.corners[1]), c(e.corners[2]);
    const glm::dvec3 area = glm::cross(b - a, c - a);
    const double whole = glm::dot(area, area);
    const double wa = glm::dot(glm::cross(b - p, c - p), area) / whole;
    const double wb = glm::dot(glm::cross(c - p, a - p), area) / whole;
    const glm::dvec3 normal =
        glm::normalize(wa * glm::dvec3(e.corner_normals[0]) + wb * glm::dvec3(e.corner_normals[1]) +
                       (1.0 - wa - wb) * glm::dvec3(e.corner_normals[2]));
    const glm::dvec3 d = glm::normalize(p - glm::dvec3(scene.observer.position));
    const double c1 = -glm::dot(d, normal);
    const double theta1 = std::acos(c1);
    const double theta2 = std::asin(std::sin(theta1) / 1.5);
    constexpr double degrees = 180.0 / M_PI;
    EXPECT_GT(theta1 * degrees, 10.0);
    EXPECT_NEAR(first.theta1, theta1 * degrees, 1e-3);
    EXPECT_NEAR(first.theta2, theta2 * degrees, 1e-3);
    EXPECT_NEAR(first.k, std::cos(theta2) * std::cos(theta2), 1e-5);
    const double rs = std::sin(theta1 - theta2) / std::sin(theta1 + theta2);
    const double rp = std::tan(theta1 - theta2) / std::tan(theta1 + theta2);
    EXPECT_NEAR(first.fresnel, (rs * rs + rp * rp) / 2, 1e-5);
    EXPECT_FALSE(first.total_internal_reflection);
    // Its two children: the mirror ray, weight t·F, and the refracted one,
    // weight t·(1 − F), both at depth 2.
    int children = 0;
    for (const litkit::RayNode& n : e.ray_tree) {
        if (n.parent != 0) continue;
        ++children;
        EXPECT_EQ(n.depth, 2);
        const float expected =
            n.kind == litkit::RayNode::Kind::Reflected ? first.fresnel : 1.0f - first.fresnel;
        EXPECT_NEAR(n.weight.x, expected, 1e-6f);
    }
    EXPECT_EQ(children, 2);
}

TEST(ExplainGlass, ContributionsAddUpToThePixelEverywhere) {
    // Every other pixel of every other row (each explained pixel draws the
    // picture again), of a coarser ball.
    litkit::Scene scene = glass_scene(40, 30);
    scene.objects.back().shape = litkit::SphereShape{1.5f, 24, 12};
    const litkit::Image image = litkit::render(scene);
    litkit::PixelExplainer explainer(scene, litkit::RenderOptions{.threads = 1});
    int glass = 0;
    for (int y = 0; y < scene.output.height; y += 2) {
        for (int x = 0; x < scene.output.width; x += 2) {
            const litkit::PixelExplanation e = explainer.explain(x, y);
            const std::uint8_t* pixel = image.pixel(x, y);
            ASSERT_EQ(e.rgb, (litkit::Rgb8{pixel[0], pixel[1], pixel[2]})) << x << "," << y;
            if (!e.hit || e.object_name != "lens") {
                EXPECT_TRUE(e.ray_tree.empty()) << x << "," << y;
                continue;
            }
            ++glass;
            ASSERT_FALSE(e.ray_tree.empty()) << x << "," << y;
            const glm::vec3 sum = contributions(e);
            EXPECT_NEAR(sum.x, e.sum.x, 1e-5f) << x << "," << y;
            EXPECT_NEAR(sum.y, e.sum.y, 1e-5f) << x << "," << y;
            EXPECT_NEAR(sum.z, e.sum.z, 1e-5f) << x << "," << y;
            // Each node after its parent, one level deeper.
            for (std::size_t i = 1; i < e.ray_tree.size(); ++i) {
                const int parent = e.ray_tree[i].parent;
                ASSERT_GE(parent, 0);
                ASSERT_LT(static_cast<std::size_t>(parent), i);
                EXPECT_EQ(e.ray_tree[i].depth,
                          e.ray_tree[static_cast<std::size_t>(parent)].depth + 1);
            }
        }
    }
    EXPECT_GT(glass, 60);
}

TEST(ExplainGlass, TextShowsTheTreeAndSumsUp) {
    const litkit::Scene scene = glass_scene(80, 60);
    const litkit::PixelExplanation e = litkit::explain_pixel(scene, 40, 30);
    ASSERT_GT(e.ray_tree.size(), 4u);
    const std::string text = litkit::explanation_text(e, scene);
    for (const char* expected :
         {"visible: objects[4] 'lens' (sphere)", "ray tree (docs/spec.md §10.2)",
          "#0 camera ray, depth 1, in the room: enters objects[4] 'lens' (sphere), triangle ",
          "n1 = 1, n2 = 1.5, theta1 = ", "  #1 reflected ray, depth 2, in the room",
          "refracted ray, depth 2, inside objects[4] 'lens' (sphere): leaves through triangle ",
          "A = (a/255)^(l/D) = ", "local part (1 - t) I_ad + I_s = ", "sum of what the rays add = ",
          "rgb = round(255 * that)"})
        EXPECT_NE(text.find(expected), std::string::npos) << expected << " in\n" << text;
    EXPECT_NE(text.find("\nL = ("), std::string::npos) << text;
    // Each node is listed or counted in the summary line.
    std::size_t listed = 0;
    for (std::size_t i = 0; i < e.ray_tree.size(); ++i)
        listed += text.find("#" + std::to_string(i) + " ") != std::string::npos;
    const auto summary = text.find("not shown: ");
    const std::size_t counted =
        summary == std::string::npos ? 0 : std::stoul(text.substr(summary + 11));
    EXPECT_EQ(listed + counted, e.ray_tree.size()) << text;
}

// A tree made by hand: the camera's node brings 0.5 of the red channel's
// 0.51, one child 0.009 (shown: above 0.51/255 = 0.002), the other 0.001
// (below: counted, not shown).
TEST(ExplainGlass, RaysBelowOneLevelAreSummarised) {
    const litkit::Scene scene = glass_scene(80, 60);
    litkit::PixelExplanation e = litkit::explain_pixel(scene, 40, 30);
    ASSERT_TRUE(e.hit);
    litkit::RayNode camera, dim, bright;
    camera.outcome = litkit::RayNode::Outcome::Interface;
    camera.object = 4;
    camera.contribution = {0.5f, 0.3f, 0.2f};
    dim.kind = litkit::RayNode::Kind::Reflected;
    dim.outcome = litkit::RayNode::Outcome::Background;
    dim.depth = 2;
    dim.parent = 0;
    dim.contribution = {0.001f, 0.0f, 0.0f};
    bright = dim;
    bright.kind = litkit::RayNode::Kind::Refracted;
    bright.contribution = {0.009f, 0.0f, 0.0f};
    e.ray_tree = {camera, dim, bright};
    e.sum = {0.51f, 0.3f, 0.2f};
    const std::string text = litkit::explanation_text(e, scene);
    EXPECT_NE(text.find("#0 camera ray"), std::string::npos) << text;
    EXPECT_EQ(text.find("#1 "), std::string::npos) << text;
    EXPECT_NE(text.find("  #2 refracted ray, depth 2"), std::string::npos) << text;
    EXPECT_NE(text.find("not shown: 1 rays"), std::string::npos) << text;
    EXPECT_NE(text.find("together they add (0.001, 0, 0)"), std::string::npos) << text;
    EXPECT_NE(text.find("sum of what the rays add = (0.51, 0.3, 0.2)"), std::string::npos) << text;
    // JSON keeps every node.
    const std::string json = litkit::explanation_json(e, scene);
    EXPECT_NE(json.find("\"contribution\": [0.001, 0, 0]"), std::string::npos) << json;
}

TEST(ExplainGlass, JsonHasEveryNodeAndItsContributionsAddUp) {
    const litkit::Scene scene = glass_scene(80, 60);
    const litkit::PixelExplanation e = litkit::explain_pixel(scene, 52, 20);
    ASSERT_FALSE(e.ray_tree.empty());
    const fs::path file = fs::temp_directory_path() /
                          ("litkit-explain-glass-" + std::to_string(::getpid()) + ".json");
    std::ofstream(file) << litkit::explanation_json(e, scene);
    // Python's json module reads it: every node, with the keys of
    // docs/learning.md, the contributions adding up to "sum" within 1e-5.
    const auto parsed = litkit_test::run_command(
        "python3 -c \"import json,sys; d=json.load(open('" + file.string() +
        "')); t=d['ray_tree']; ks=['index','kind','outcome','depth','parent','inside','object',"
        "'object_index','triangle','length','absorption','n1','n2','theta1','theta2','k',"
        "'fresnel','total_internal_reflection','weight','local','contribution','radiance']; "
        "missing=[k for n in t for k in ks if k not in n]; "
        "s=[sum(n['contribution'][c] for n in t) for c in range(3)]; "
        "off=max(abs(s[c]-d['sum'][c]) for c in range(3)); print(len(t), missing, off); "
        "sys.exit(1 if missing or off > 1e-5 or len(t) != " +
        std::to_string(e.ray_tree.size()) + " or t[0]['kind'] != 'camera' else 0)\"");
    fs::remove(file);
    EXPECT_EQ(parsed.status, 0) << parsed.output;
}

TEST(ExplainGlass, OpaquePixelsHaveNoTree) {
    litkit::Scene scene = glass_scene(80, 60);
    scene.objects.pop_back();  // no glass at all
    litkit::PixelExplainer explainer(scene);
    litkit::PixelExplanation e;
    for (int y = 0; y < 30 && !e.hit; ++y) e = explainer.explain(y * 4 / 3, y);  // a cube
    ASSERT_TRUE(e.hit);
    EXPECT_TRUE(e.ray_tree.empty());
    EXPECT_EQ(litkit::explanation_text(e, scene).find("ray tree"), std::string::npos);
    EXPECT_EQ(litkit::explanation_json(e, scene).find("ray_tree"), std::string::npos);
}
