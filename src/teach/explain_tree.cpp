// SPDX-License-Identifier: MIT
// The ray tree of a glass pixel in `litkit explain` (docs/spec.md §10.3): a
// short block per ray, indented by depth, in text; every node in JSON.
#include <algorithm>
#include <string>
#include <vector>

#include "core/json.hpp"
#include "litkit/explain.hpp"
#include "teach/explain_text.hpp"

namespace litkit::detail {

namespace {

float largest(const glm::vec3& v) { return std::max({v.x, v.y, v.z}); }

const char* kind_name(RayNode::Kind kind) {
    switch (kind) {
        case RayNode::Kind::Camera:
            return "camera";
        case RayNode::Kind::Reflected:
            return "reflected";
        default:
            return "refracted";
    }
}

const char* outcome_name(RayNode::Outcome outcome) {
    switch (outcome) {
        case RayNode::Outcome::Surface:
            return "surface";
        case RayNode::Outcome::Interface:
            return "interface";
        case RayNode::Outcome::Background:
            return "background";
        case RayNode::Outcome::Lost:
            return "lost";
        default:
            return "untraced";
    }
}

bool hits_object(const RayNode& n) {
    return n.outcome == RayNode::Outcome::Surface || n.outcome == RayNode::Outcome::Interface;
}

// What each node and the rays it spawned add to the pixel together: the
// nodes come after their parents, so one pass from the back sums them.
std::vector<glm::vec3> subtree_totals(const std::vector<RayNode>& tree) {
    std::vector<glm::vec3> total(tree.size());
    for (std::size_t i = tree.size(); i-- > 0;) {
        total[i] += tree[i].contribution;
        if (tree[i].parent >= 0) total[static_cast<std::size_t>(tree[i].parent)] += total[i];
    }
    return total;
}

// The first line of a node: which ray, and what it met. (std::string("…") +
// a temporary, not a bare literal: GCC 12 warns falsely, -Wrestrict, GCC bug
// 105329, on a literal + a temporary std::string.)
std::string headline(const RayNode& n, std::size_t index, const Scene& scene) {
    std::string text =
        std::string("#") + std::to_string(index) + " " + kind_name(n.kind) + " ray, depth " +
        std::to_string(n.depth) + ", " +
        (n.inside ? std::string("inside ") + object_label(scene, n.object) : "in the room") + ": ";
    switch (n.outcome) {
        case RayNode::Outcome::Surface:
            return text + "hits opaque " + object_label(scene, n.object) + ", triangle " +
                   std::to_string(n.triangle) + ", length l = " + num(n.length) + "\n";
        case RayNode::Outcome::Interface:
            text += (n.inside ? "leaves through triangle " + std::to_string(n.triangle)
                              : "enters " + object_label(scene, n.object) + ", triangle " +
                                    std::to_string(n.triangle));
            if (n.kind != RayNode::Kind::Camera) text += ", length l = " + num(n.length);
            return text + "\n";
        case RayNode::Outcome::Background:
            return text + "leaves the scene: the background\n";
        case RayNode::Outcome::Lost:
            return text + "finds no exit: L = 0\n";
        default:
            return text + "not traced (deeper than max_depth, or weight below 2^-10): L = 0\n";
    }
}

// The lines under the headline: the interface's numbers, then the weight
// and what the node adds.
std::string details(const RayNode& n, const std::string& indent) {
    std::string text;
    if (n.outcome == RayNode::Outcome::Interface) {
        if (n.inside) text += indent + "A = (a/255)^(l/D) = " + vec(n.absorption) + "\n";
        text += indent + "n1 = " + num(n.n1) + ", n2 = " + num(n.n2) +
                ", theta1 = " + num(n.theta1) + " deg, ";
        if (n.total_internal_reflection) {
            text += "k = " + num(n.k) + " <= 0: total internal reflection, F = 1";
        } else {
            text +=
                "theta2 = " + num(n.theta2) + " deg, k = " + num(n.k) + ", F = " + num(n.fresnel);
        }
        if (n.geometric_normal) text += " (with the face normal N_g)";
        text += "\n";
    }
    text += indent + "weight w = " + vec(n.weight);
    switch (n.outcome) {
        case RayNode::Outcome::Surface:
            text += ", its colour I = " + vec(n.local);
            break;
        case RayNode::Outcome::Interface:
            if (!n.inside) {
                text += ", t = " + num(n.transmission) +
                        ", local part (1 - t) I_ad + I_s = " + vec(n.local);
            }
            break;
        case RayNode::Outcome::Background:
            text += ", (background/255)^gamma = " + vec(n.local);
            break;
        default:
            break;
    }
    return text + "\n" + indent + "adds w * own light = " + vec(n.contribution) + "\n";
}

std::string node_json(const RayNode& n, std::size_t index, const Scene& scene) {
    const bool hit = hits_object(n);
    const SceneObject* object = hit ? &scene.objects[n.object] : nullptr;
    const std::string name =
        object ? (object->name.empty() ? "objects[" + std::to_string(n.object) + "]" : object->name)
               : "";
    return "{\"index\": " + std::to_string(index) +
           ", \"kind\": " + json::string(kind_name(n.kind)) +
           ", \"outcome\": " + json::string(outcome_name(n.outcome)) +
           ", \"depth\": " + std::to_string(n.depth) +
           ", \"parent\": " + (n.parent >= 0 ? std::to_string(n.parent) : "null") +
           ", \"inside\": " + (n.inside ? "true" : "false") +
           ", \"object\": " + (object ? json::string(name) : "null") +
           ", \"object_index\": " + (hit ? std::to_string(n.object) : "null") +
           ", \"triangle\": " + (hit ? std::to_string(n.triangle) : "null") +
           ", \"origin\": " + json_vec(n.origin) + ", \"direction\": " + json_vec(n.direction) +
           ", \"point\": " + (hit ? json_vec(n.point) : "null") +
           ", \"length\": " + json::number(n.length) +
           ", \"absorption\": " + json_vec(n.absorption) + ", \"n1\": " + json::number(n.n1) +
           ", \"n2\": " + json::number(n.n2) + ", \"theta1\": " + json::number(n.theta1) +
           ", \"theta2\": " + json::number(n.theta2) + ", \"k\": " + json::number(n.k) +
           ", \"fresnel\": " + json::number(n.fresnel) +
           ", \"total_internal_reflection\": " + (n.total_internal_reflection ? "true" : "false") +
           ", \"geometric_normal\": " + (n.geometric_normal ? "true" : "false") +
           ", \"transmission\": " + json::number(n.transmission) +
           ", \"weight\": " + json_vec(n.weight) + ", \"local\": " + json_vec(n.local) +
           ", \"contribution\": " + json_vec(n.contribution) +
           ", \"radiance\": " + json_vec(n.radiance) + "}";
}

}  // namespace

std::string ray_tree_text(const PixelExplanation& e, const Scene& scene) {
    const std::vector<RayNode>& tree = e.ray_tree;
    if (tree.empty()) return "";
    std::string text =
        "ray tree (docs/spec.md §10.2): " + std::to_string(tree.size()) +
        " rays, indented by depth\n"
        "  entering glass from the room: L = (1 - t) I_ad + I_s + t [F L(R) + (1 - F) L(T)]\n"
        "  inside, at the way out: L = A [F L(R) + (1 - F) L(T)], A = (a/255)^(l/D) over the\n"
        "  length l inside; a ray's weight w is the product of the factors in front of its L\n"
        "  (t, F, 1 - F, A) and it adds w times its own light (the local part, an opaque\n"
        "  surface's colour I, the background) to the pixel's L\n";
    // A ray that brings, with the rays it spawned, less than 1/255 of the
    // pixel's largest channel is counted, not shown; so are its descendants.
    const float threshold = largest(e.sum) / 255.0f;
    const std::vector<glm::vec3> totals = subtree_totals(tree);
    std::vector<bool> hidden(tree.size(), false);
    std::size_t hidden_count = 0;
    glm::vec3 hidden_sum{0.0f}, sum{0.0f};
    for (std::size_t i = 0; i < tree.size(); ++i) {
        const RayNode& n = tree[i];
        sum += n.contribution;
        hidden[i] = (n.parent >= 0 && hidden[static_cast<std::size_t>(n.parent)]) ||
                    largest(totals[i]) < threshold;
        if (hidden[i]) {
            ++hidden_count;
            hidden_sum += n.contribution;
            continue;
        }
        const std::string indent(2 * static_cast<std::size_t>(n.depth - 1), ' ');
        text += indent + headline(n, i, scene) + details(n, indent + "    ");
    }
    if (hidden_count > 0) {
        text += "not shown: " + std::to_string(hidden_count) +
                " rays that bring (with the rays they spawn) less than 1/255 of L's largest\n"
                "channel, " +
                num(threshold) + "; together they add " + vec(hidden_sum) + "\n";
    }
    return text + "sum of what the rays add = " + vec(sum) + "\n";
}

std::string ray_tree_json(const PixelExplanation& e, const Scene& scene) {
    std::string out = "[";
    for (std::size_t i = 0; i < e.ray_tree.size(); ++i)
        out += (i ? ", " : "") + node_json(e.ray_tree[i], i, scene);
    return out + "]";
}

}  // namespace litkit::detail
