// SPDX-License-Identifier: MIT
// The camera of docs/spec.md §1 and the ray through each pixel, defined
// once: the CPU rasterizer's vertex transform and the world position it
// lights at each pixel (its SIMD kernels, and Renderer::probe, which explain
// reads) come from here, and so should any other renderer's primary rays
// (row_rays and ray_direction), for the same rays to the bit.
//
// The ray through pixel (i, j) of a W × H image leaves the eye along
//     d = f + x · tan(fov/2) · aspect · r + y · tan(fov/2) · u
//     x = k / W, k = 2i + 1 − W;   y = 1 − 2(j + 0.5)/H
// with glm::lookAt's axes: forward f, right r = f × up, up u = r × f (the
// camera-space ray of §1 in world space). Its component along f is 1, so the
// point at view depth w (clip w, the rasterizer's) is p = eye + w · d, and a
// tracer's ray parameter along d is that same depth.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "litkit/scene.hpp"

namespace litkit {

// The rays of one row of pixels: pixel i's is d = centre + k · across, with
// the whole number k = 2i + 1 − W (exact in a float) at the pixel's centre,
// or k = 2(i + x) − W through the sample at x within it (docs/spec.md §11:
// k_shift = 2x − 1 is added, a multiple of 1/8, so k stays exact). Plain
// arrays, for the SIMD kernels.
struct RowRays {
    float eye[3];
    float centre[3];  // f + y · tan(fov/2) · u (the row's y): d at k = 0
    float across[3];  // tan(fov/2) · aspect / W · r: d's change per unit of k
    float k_shift = 0.0f;
};

// k of column i in a row of `width` pixels (RowRays).
constexpr float pixel_k(int i, int width) { return static_cast<float>(2 * i + 1 - width); }

// One coordinate of the ray with number k, d = centre + k · across, and of
// the point at view depth w on it, p = eye + w · d: the one text of both,
// for floats and for the SIMD kernels' batches. `round` keeps a product
// from fusing with the sum after it (the kernels are built with FMA; x86-64's
// baseline, which the rest is built for, has none, so floats need nothing).
// The kernels built for AVX2 and AVX-512 include this header: they may
// instantiate these templates on their batches, but must call nothing here
// on floats (a copy built for AVX could be the one the linker keeps).
template <class T, class Round>
T direction_coordinate(const T& centre, const T& across, const T& k, Round round) {
    return round(k * across) + centre;
}
template <class T, class Round>
T point_coordinate(const T& eye, const T& direction, const T& w, Round round) {
    return eye + round(w * direction);
}

// The observer's camera for an image of width × height pixels.
struct Camera {
    // World → clip space: glm's perspective (computed in double, rounded
    // once to float) times lookAt. Float tanf rounds differently in glibc
    // and in the WebAssembly build's C library (for a fov of 32 degrees,
    // enough to move a pixel); double tan rounded to float does not, so
    // every build draws the same bytes (docs/web.md).
    glm::mat4 view_projection{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f};  // f
    glm::vec3 up{0.0f};       // tan(fov/2) · u
    glm::vec3 across{0.0f};   // tan(fov/2) · aspect / W · r
    int width = 0, height = 0;

    // Row j's rays through the samples at `sample` in its pixels:
    // y = 1 − 2(j + sample.y)/H, k_shift = 2 · sample.x − 1; the pixels'
    // centres by default.
    RowRays row_rays(int j, SamplePosition sample = {0.5f, 0.5f}) const;
};

Camera make_camera(const Observer& observer, int width, int height);

// d of pixel i on the row whose rays are `rays`, k = pixel_k(i) + k_shift
// (not of unit length: its component along f is 1).
glm::vec3 ray_direction(const RowRays& rays, int width, int i);

// The world position at column i of that row at view depth w, eye + w · d:
// what the kernels' shade_phong lights there.
glm::vec3 point_on_ray(const RowRays& rays, int width, int i, float w);

}  // namespace litkit
