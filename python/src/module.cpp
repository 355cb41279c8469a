// SPDX-License-Identifier: MIT
// litkit._litkit: the extension module under the Python package litkit
// (python/litkit/__init__.py wraps it; docs/python.md is the user's view).
// Rendering: the one-shot render() and Renderer, the prepared scene that
// draws again with another observer, size or model at the cost of the
// rendering alone. Both release the GIL while they work, so other Python
// threads run meanwhile; they copy what they need from Python objects first.
#include <pybind11/stl.h>

#include <memory>
#include <mutex>

#include "convert.hpp"

namespace litkit_python {

namespace {

litkit::RenderOptions options_for(int threads) {
    return litkit::RenderOptions{.threads = checked_threads(threads)};
}

// R11 leaves the models of a scene without [lighting] to the caller: the
// library's defaults (phong / phong) here, as the command line's --yes.
py::array render_once(const litkit::Scene& scene, const Overrides& overrides, int threads) {
    litkit::Scene copy = scene;
    overrides.apply_to(copy);
    const litkit::RenderOptions options = options_for(threads);
    litkit::Image image;
    {
        py::gil_scoped_release unlocked;
        validate_or_throw(copy);
        image = litkit::render(copy, options);
    }
    return image_array(std::move(image));
}

// A scene prepared once (meshes, normals) and drawn many times.
class PreparedScene {
  public:
    PreparedScene(const litkit::Scene& scene, int threads) : scene_(scene) {
        const litkit::RenderOptions options = options_for(threads);
        py::gil_scoped_release unlocked;
        validate_or_throw(scene_);
        renderer_ = std::make_unique<litkit::Renderer>(scene_, options);
    }

    // `scene`: draw this one from now on (checked; meshes kept where its
    // objects did not move or change shape). `overrides` apply to this frame.
    py::array render(const std::optional<litkit::Scene>& scene, const Overrides& overrides) {
        std::optional<litkit::Scene> next = scene;  // copied with the GIL held
        litkit::Scene frame;
        overrides.apply_to(frame);  // argument errors before any work
        litkit::Image image;
        {
            py::gil_scoped_release unlocked;
            const std::lock_guard lock(mutex_);  // one frame at a time per renderer
            if (next) {
                validate_or_throw(*next);
                scene_ = std::move(*next);
            }
            frame = scene_;
            overrides.apply_to(frame);
            renderer_->update(frame);
            renderer_->render_into(image);
        }
        return image_array(std::move(image));
    }

    litkit::Scene scene() {
        py::gil_scoped_release unlocked;
        const std::lock_guard lock(mutex_);
        return scene_;
    }
    std::size_t mesh_builds() {
        py::gil_scoped_release unlocked;
        const std::lock_guard lock(mutex_);
        return renderer_->mesh_builds();
    }
    std::size_t triangle_count() {
        py::gil_scoped_release unlocked;
        const std::lock_guard lock(mutex_);
        return renderer_->triangle_count();
    }
    int thread_count() {
        py::gil_scoped_release unlocked;
        const std::lock_guard lock(mutex_);
        return renderer_->thread_count();
    }

  private:
    std::mutex mutex_;
    litkit::Scene scene_;  // as last checked
    std::unique_ptr<litkit::Renderer> renderer_;
};

Overrides overrides(std::optional<std::string> reflection, std::optional<std::string> shading,
                    std::optional<int> width, std::optional<int> height,
                    std::optional<int> max_depth, std::optional<int> samples) {
    return Overrides{std::move(reflection), std::move(shading), width, height, max_depth, samples};
}

}  // namespace

void bind_render(py::module_& module) {
    module.def(
        "_render",
        [](const litkit::Scene& scene, std::optional<std::string> reflection,
           std::optional<std::string> shading, std::optional<int> width, std::optional<int> height,
           std::optional<int> max_depth, std::optional<int> samples, int threads) {
            return render_once(
                scene, overrides(reflection, shading, width, height, max_depth, samples), threads);
        },
        py::arg("scene"), py::kw_only(), py::arg("reflection") = py::none(),
        py::arg("shading") = py::none(), py::arg("width") = py::none(),
        py::arg("height") = py::none(), py::arg("max_depth") = py::none(),
        py::arg("samples") = py::none(), py::arg("threads") = 0);

    py::class_<PreparedScene>(module, "_Renderer")
        .def(py::init<const litkit::Scene&, int>(), py::arg("scene"), py::kw_only(),
             py::arg("threads") = 0)
        .def(
            "render",
            [](PreparedScene& self, std::optional<litkit::Scene> scene,
               std::optional<std::string> reflection, std::optional<std::string> shading,
               std::optional<int> width, std::optional<int> height, std::optional<int> max_depth,
               std::optional<int> samples) {
                return self.render(
                    scene, overrides(reflection, shading, width, height, max_depth, samples));
            },
            py::arg("scene") = py::none(), py::kw_only(), py::arg("reflection") = py::none(),
            py::arg("shading") = py::none(), py::arg("width") = py::none(),
            py::arg("height") = py::none(), py::arg("max_depth") = py::none(),
            py::arg("samples") = py::none())
        .def_property_readonly("scene", &PreparedScene::scene)
        .def_property_readonly("mesh_builds", &PreparedScene::mesh_builds)
        .def_property_readonly("triangle_count", &PreparedScene::triangle_count)
        .def_property_readonly("thread_count", &PreparedScene::thread_count);

    module.def(
        "encode_png",
        [](py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> pixels) {
            if (pixels.ndim() != 3 || pixels.shape(2) != 3 || pixels.shape(0) < 1 ||
                pixels.shape(1) < 1) {
                throw litkit::ArgumentError(
                    "encode_png: expected an array of shape (height, "
                    "width, 3) with height, width >= 1");
            }
            litkit::Image image(static_cast<int>(pixels.shape(1)),
                                static_cast<int>(pixels.shape(0)));
            std::copy(pixels.data(), pixels.data() + image.rgb.size(), image.rgb.begin());
            return py::bytes(litkit::encode_png(image));
        },
        py::arg("pixels"), "The PNG file bytes of an (height, width, 3) uint8 array.");
}

}  // namespace litkit_python

PYBIND11_MODULE(_litkit, module) {
    module.doc() = "litkit's C++ library; import litkit, not this";
    module.attr("__version__") = LITKIT_VERSION;
    litkit_python::bind_errors(module);
    litkit_python::bind_scene(module);
    litkit_python::bind_lighting(module);
    litkit_python::bind_render(module);
    litkit_python::bind_explain(module);
}
