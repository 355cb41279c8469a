// SPDX-License-Identifier: MIT
/// \file
/// `litkit explain`: how one pixel of `litkit render` got its value, step by
/// step in the symbols of docs/spec.md, or the equations at a point of the
/// caller's choosing (docs/learning.md).
#pragma once

#include <array>
#include <cstddef>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

#include "litkit/lighting.hpp"
#include "litkit/ray_tree.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

namespace litkit {

/// One evaluation of the lighting equations (docs/spec.md §4): at p with unit
/// normal N, seen from the eye, and what each light gave.
struct PointEvaluation {
    glm::vec3 position{0.0f};  ///< p
    glm::vec3 normal{0.0f};    ///< N, unit
    glm::vec3 to_eye{0.0f};    ///< V
    ShadeTerms terms;          ///< per light, and I
};

/// How one pixel got its value: the triangle it shows and the evaluations
/// of the lighting that the shading model made for it.
struct PixelExplanation {
    /// \name The pixel
    //@{
    /// The pixel's column (from the left) and row (from the top).
    int x = 0, y = 0;
    //@}
    bool hit = false;  ///< false: no object covers the pixel; rgb is the background
    Rgb8 rgb{};        ///< the pixel `litkit render` writes
    /// The scene's gamma, which turned `sum` into `rgb`.
    float gamma = 1.0f;

    /// When hit: the index into Scene::objects of the object shown.
    std::size_t object = 0;
    std::string object_name;  ///< may be empty
    /// The triangle within the object's mesh.
    std::size_t triangle = 0;
    Reflection reflection = Reflection::Phong;  ///< the object's, after overrides
    /// The object's shading model, after overrides.
    Shading shading = Shading::Phong;
    std::array<glm::vec3, 3> corners{};         ///< the triangle's corners, world space
    std::array<glm::vec3, 3> corner_normals{};  ///< their vertex normals (DD9)
    glm::vec3 face_normal{0.0f};                ///< DD8
    bool clipped = false;            ///< crosses the near plane: weights are the clipped piece's
    std::array<float, 3> weights{};  ///< perspective-correct, of the corners
    /// flat: one, at the centroid with the face normal; gouraud: three, one per
    /// corner, whose colours the weights mix; phong: one, at the pixel.
    std::vector<PointEvaluation> evaluations;
    glm::vec3 sum{0.0f};  ///< I before clamping, exactly as the renderer had it
    /// Where the object seen is glass (t > 0, docs/spec.md §10): the pixel's
    /// ray tree, one node per ray, the camera's ray first, each after its
    /// parent (RayNode::parent); the nodes' contributions add up to `sum`,
    /// the pixel's L. Empty for an opaque object; `evaluations` then hold
    /// all of `sum`, and here the local lighting at the first hit (its I).
    std::vector<RayNode> ray_tree;
    /// With several samples per pixel (docs/spec.md §11): each sample's L_k,
    /// whose mean, after gamma, is `rgb`; everything else here is then the
    /// pixel's centre, lit as one sample would be. Empty with one sample.
    std::vector<SampleProbe> samples;
};

/// Renders the scene (CPU backend) and explains pixel (x, y). Objects' and
/// [lighting]'s models as `render` uses them; `options` as for render.
/// Throws ArgumentError for a pixel outside the image.
PixelExplanation explain_pixel(const Scene& scene, int x, int y, const RenderOptions& options = {});

/// Explains many pixels of one scene: what explain_pixel does, with the
/// renderer (meshes, normals, threads) built once, not once a pixel. Each
/// explain() draws again, as explain_pixel does (Renderer::probe).
class PixelExplainer {
  public:
    /// The preconditions and errors of Renderer's constructor. The scene is
    /// copied: later changes to the caller's scene are not seen.
    explicit PixelExplainer(const Scene& scene, RenderOptions options = {});
    ~PixelExplainer();
    /// Not copyable: it owns a Renderer.
    PixelExplainer(const PixelExplainer&) = delete;
    /// Not copyable either.
    PixelExplainer& operator=(const PixelExplainer&) = delete;

    /// Pixel (x, y), exactly as explain_pixel(scene, x, y, options) gives it.
    /// Throws ArgumentError for a pixel outside the image.
    PixelExplanation explain(int x, int y);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// The equations at point p with normal N (normalised here; it must not be
/// zero) under the scene's lights, seen from its observer, for a material and
/// model of the caller's choosing.
PointEvaluation explain_point(const Scene& scene, Reflection reflection, const Material& material,
                              const glm::vec3& position, const glm::vec3& normal);

/// The explanation as text, step by step in the symbols of docs/spec.md (what
/// `litkit explain` prints).
std::string explanation_text(const PixelExplanation& explanation, const Scene& scene);
/// The explanation as one JSON object (`--json`; its keys are listed in
/// docs/learning.md).
std::string explanation_json(const PixelExplanation& explanation, const Scene& scene);
/// An explain_point result as text, step by step (what `litkit explain --at` prints).
std::string evaluation_text(const PointEvaluation& point, const Scene& scene, Reflection reflection,
                            const Material& material);
/// An explain_point result as one JSON object (`--at` with `--json`).
std::string evaluation_json(const PointEvaluation& point, const Scene& scene,
                            Reflection reflection);

}  // namespace litkit
