// SPDX-License-Identifier: MIT
// litkit explain from Python: how one pixel got its value (the text the
// command prints, the pixel's numbers) and, where the pixel sees glass, its
// ray tree as a list of dicts (docs/spec.md §10.3).
#include <pybind11/stl.h>

#include "convert.hpp"

namespace litkit_python {

namespace {

const char* kind_name(litkit::RayNode::Kind kind) {
    switch (kind) {
        case litkit::RayNode::Kind::Camera:
            return "camera";
        case litkit::RayNode::Kind::Reflected:
            return "reflected";
        default:
            return "refracted";
    }
}

const char* outcome_name(litkit::RayNode::Outcome outcome) {
    switch (outcome) {
        case litkit::RayNode::Outcome::Surface:
            return "surface";
        case litkit::RayNode::Outcome::Interface:
            return "interface";
        case litkit::RayNode::Outcome::Background:
            return "background";
        case litkit::RayNode::Outcome::Lost:
            return "lost";
        default:
            return "untraced";
    }
}

// One node, its keys those of `litkit explain --json`'s "ray_tree" entries.
py::dict node_dict(const litkit::RayNode& n, std::size_t index, const litkit::Scene& scene) {
    const bool hit = n.outcome == litkit::RayNode::Outcome::Surface ||
                     n.outcome == litkit::RayNode::Outcome::Interface;
    py::dict d;
    d["index"] = index;
    d["kind"] = kind_name(n.kind);
    d["outcome"] = outcome_name(n.outcome);
    d["depth"] = n.depth;
    d["parent"] = n.parent >= 0 ? py::object(py::int_(n.parent)) : py::object(py::none());
    d["inside"] = n.inside;
    if (hit) {
        const std::string& name = scene.objects.at(n.object).name;
        d["object"] = name.empty() ? "objects[" + std::to_string(n.object) + "]" : name;
        d["object_index"] = n.object;
        d["triangle"] = n.triangle;
        d["point"] = n.point;
    } else {
        for (const char* key : {"object", "object_index", "triangle", "point"}) d[key] = py::none();
    }
    d["origin"] = n.origin;
    d["direction"] = n.direction;
    d["length"] = n.length;
    d["absorption"] = n.absorption;
    d["n1"] = n.n1;
    d["n2"] = n.n2;
    d["theta1"] = n.theta1;
    d["theta2"] = n.theta2;
    d["k"] = n.k;
    d["fresnel"] = n.fresnel;
    d["total_internal_reflection"] = n.total_internal_reflection;
    d["geometric_normal"] = n.geometric_normal;
    d["transmission"] = n.transmission;
    d["weight"] = n.weight;
    d["local"] = n.local;
    d["contribution"] = n.contribution;
    d["radiance"] = n.radiance;
    return d;
}

py::dict explain(const litkit::Scene& scene, int x, int y, const Overrides& overrides,
                 int threads) {
    litkit::Scene copy = scene;
    overrides.apply_to(copy);
    const litkit::RenderOptions options{.threads = checked_threads(threads)};
    litkit::PixelExplanation e;
    std::string text;
    {
        py::gil_scoped_release unlocked;
        validate_or_throw(copy);
        e = litkit::explain_pixel(copy, x, y, options);
        text = litkit::explanation_text(e, copy);
    }
    py::dict d;
    d["x"] = e.x;
    d["y"] = e.y;
    d["hit"] = e.hit;
    d["rgb"] = py::make_tuple(e.rgb[0], e.rgb[1], e.rgb[2]);
    if (e.hit) {
        d["object"] =
            e.object_name.empty() ? "objects[" + std::to_string(e.object) + "]" : e.object_name;
        d["object_index"] = e.object;
        d["triangle"] = e.triangle;
        d["sum"] = e.sum;
    } else {
        for (const char* key : {"object", "object_index", "triangle", "sum"}) d[key] = py::none();
    }
    py::list tree;
    for (std::size_t i = 0; i < e.ray_tree.size(); ++i)
        tree.append(node_dict(e.ray_tree[i], i, copy));
    d["ray_tree"] = tree;
    py::list samples;
    for (const litkit::SampleProbe& sample : e.samples) {
        py::dict s;
        s["position"] = py::make_tuple(sample.position.x, sample.position.y);
        s["hit"] = sample.hit;
        s["object_index"] = sample.hit ? py::object(py::int_(sample.object)) : py::none();
        s["light"] = sample.light;
        samples.append(s);
    }
    d["samples"] = samples;
    d["text"] = text;
    return d;
}

}  // namespace

void bind_explain(py::module_& module) {
    module.def(
        "_explain",
        [](const litkit::Scene& scene, int x, int y, std::optional<std::string> reflection,
           std::optional<std::string> shading, std::optional<int> samples, int threads) {
            return explain(
                scene, x, y,
                Overrides{std::move(reflection), std::move(shading), {}, {}, {}, samples}, threads);
        },
        py::arg("scene"), py::arg("x"), py::arg("y"), py::kw_only(),
        py::arg("reflection") = py::none(), py::arg("shading") = py::none(),
        py::arg("samples") = py::none(), py::arg("threads") = 0);
}

}  // namespace litkit_python
