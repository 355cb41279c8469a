// SPDX-License-Identifier: MIT
/// \file
/// The ray tree of one pixel that sees glass (docs/spec.md §10.2, §10.3): what
/// `litkit explain` shows and Renderer::probe records, one node per ray.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace litkit {

/// One ray of a pixel's ray tree and what it met (docs/spec.md §10.2).
/// Lengths in the scene's units, angles in degrees, colours linear and
/// unclamped, per channel.
struct RayNode {
    /// How the ray came about.
    enum class Kind {
        Camera,     ///< the pixel's own ray, to the surface it sees first (depth 1)
        Reflected,  ///< the mirror ray R of its parent's interface
        Refracted   ///< the refracted ray T of its parent's interface
    };
    /// What the ray did.
    enum class Outcome {
        Surface,     ///< hit an opaque object (t = 0): lit there, no further ray
        Interface,   ///< hit a glass object's surface: reflected and refracted there
        Background,  ///< left the scene from the room's medium: the background
        Lost,        ///< inside an object, found no exit: L = 0
        Untraced     ///< deeper than max_depth or weighted below 2⁻¹⁰: L = 0
    };
    Kind kind = Kind::Camera;             ///< how the ray came about
    Outcome outcome = Outcome::Untraced;  ///< what it did
    int depth = 1;                        ///< the first hit is 1, the rays it spawns 2, ...
    int parent = -1;            ///< index of the node that spawned this ray; −1 for the camera's
    bool inside = false;        ///< travels inside an object (hits its back faces only)
    glm::vec3 origin{0.0f};     ///< where the ray starts (the eye for the camera's)
    glm::vec3 direction{0.0f};  ///< unit
    // What it hit (Surface, Interface).
    std::size_t object = 0;    ///< index into Scene::objects
    std::size_t triangle = 0;  ///< within the object's mesh
    glm::vec3 point{0.0f};     ///< the hit point
    float length = 0.0f;       ///< ℓ, from the origin to the hit (0 for the camera's ray)
    /// A(ℓ) = (a/255)^(ℓ/D) of a ray inside an object; 1 elsewhere.
    glm::vec3 absorption{1.0f};
    // The interface (Interface only): items 1–6.
    float n1 = 1.0f;                         ///< the refractive index on the ray's side
    float n2 = 1.0f;                         ///< the refractive index beyond the surface
    float theta1 = 0.0f;                     ///< angle of incidence θ₁, degrees
    float theta2 = 0.0f;                     ///< angle of refraction θ₂, degrees (0 under TIR)
    float k = 0.0f;                          ///< 1 − η²(1 − c₁²)
    float fresnel = 0.0f;                    ///< F (1 under total internal reflection)
    bool total_internal_reflection = false;  ///< k ≤ 0: no refracted ray
    bool geometric_normal = false;           ///< items 2 or 6 fell back from N_s to N_g
    float transmission = 0.0f;               ///< t of the object entered from the room (else 0)
    /// The product of the factors in front of this ray's L (t, F, 1 − F and
    /// the A of the segments before it): the path weight is its largest channel.
    glm::vec3 weight{1.0f};
    /// The light this node adds itself: at a Surface its colour I, at an
    /// Interface entered from the room its local part (1 − t)·I_ad + I_s, at
    /// the Background (background/255)^γ; 0 elsewhere.
    glm::vec3 local{0.0f};
    /// weight × local: its share of the pixel's L. The shares of all
    /// nodes add up to the pixel's L.
    glm::vec3 contribution{0.0f};
    /// L of this ray (after A, for a ray inside).
    glm::vec3 radiance{0.0f};
};

}  // namespace litkit
