// SPDX-License-Identifier: MIT
// The vertex stage: every mesh vertex to clip space and to its window
// corner (clip.cpp's to_window, which the kernel set follows) once per
// frame, in parallel; Gouraud objects lit at each vertex. (Flat objects are
// lit per triangle in setup, only for triangles that survive culling.)
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "cpu/pipeline.hpp"

namespace litkit {

void Pipeline::vertex_stage(int width, int height) {
    // The camera (begin_frame): glm's lookAt and perspective, docs/spec.md §1.
    const glm::vec3 eye = camera.eye;
    const glm::mat4& view_projection = camera.view_projection;

    constexpr std::size_t chunk = 4096;
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const PreparedObject& object = objects[o];
        std::vector<glm::vec4>& clip = clip_positions[o];
        clip.resize(object.positions.size());
        std::vector<WindowCorner>& window = window_corners[o];
        window.resize(object.positions.size());
        const float half_width = 0.5f * static_cast<float>(width);
        const float half_height = 0.5f * static_cast<float>(height);
        std::vector<glm::vec3>& colors = vertex_colors[o];
        if (object.shading == Shading::Gouraud) colors.resize(object.positions.size());
        pool.parallel_for((clip.size() + chunk - 1) / chunk, [&](std::size_t c, int) {
            const std::size_t begin = c * chunk;
            const std::size_t end = std::min(clip.size(), begin + chunk);
            // clip = view_projection · (p, 1) and to_window(clip), a vector
            // of vertices at a time.
            kernels.transform_vertices(&object.positions[begin].x, end - begin,
                                       &view_projection[0][0], half_width, half_height,
                                       &clip[begin].x, &window[begin]);
            if (object.shading == Shading::Gouraud) {
                for (std::size_t i = begin; i < end; ++i)
                    colors[i] =
                        equations::shade_scalar(object.reflection, lights, object.material,
                                                object.positions[i], object.normals[i], eye);
            }
        });
        // Flat colours are computed in setup, only for triangles that
        // survive culling and clipping.
        if (object.shading == Shading::Flat) flat_colors[o].resize(object.triangles.size());
    }
}

}  // namespace litkit
