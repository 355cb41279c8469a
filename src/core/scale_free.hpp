// SPDX-License-Identifier: MIT
// Directions of any length a float can hold: normalising v in float squares
// its components, and a length of 1e-30 or 1e+30 squares to 0 or to
// infinity (a NaN direction, a black picture). These functions first
// multiply v by the power of two that brings its largest component into
// [1, 2), which rounds nothing, so that the squares are ordinary numbers.
// For every v whose components' squares are normal floats (every scene of
// ordinary size), multiplying by a power of two and dividing it out again
// is exact at each step, and the results are glm's to the bit: no picture
// of an ordinary scene changes.
//
// src/gl/opengl_core.inc, which the C++ exporter pastes into its programs
// and so can include nothing of litkit, repeats look_at's arithmetic.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace litkit::scale_free {

// 2^k with the largest |component| of v times 2^k in [1, 2); 1 for the zero
// vector and for one that is not finite.
inline double power_of_two_scale(const glm::dvec3& v) {
    const double largest = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
    if (!(largest > 0.0) || !std::isfinite(largest)) return 1.0;
    int exponent = 0;
    std::frexp(largest, &exponent);  // largest = m · 2^exponent, m in [0.5, 1)
    return std::ldexp(1.0, 1 - exponent);
}

// v times that power of two (computed in double, so that a denormal v keeps
// its bits; every float times 2^k within [1, 2) is again a float).
inline glm::vec3 brought_to_one(const glm::dvec3& v) {
    return glm::vec3(v * power_of_two_scale(v));
}

// glm::normalize(v) free of scale: the zero vector stays zero.
inline glm::vec3 unit(const glm::vec3& v) {
    const glm::vec3 scaled = brought_to_one(glm::dvec3(v));
    if (scaled == glm::vec3(0.0f)) return scaled;
    return glm::normalize(scaled);
}

// glm::lookAt(eye, center, up) free of scale: the view direction
// center − eye (taken in double, where no float's difference overflows) and
// up are brought to [1, 2) before glm builds the rotation from them; the
// translation is glm's, −(s·eye, u·eye, −f·eye).
inline glm::mat4 look_at(const glm::vec3& eye, const glm::vec3& center, const glm::vec3& up) {
    const glm::vec3 forward = brought_to_one(glm::dvec3(center) - glm::dvec3(eye));
    glm::mat4 view = glm::lookAt(glm::vec3(0.0f), forward, brought_to_one(glm::dvec3(up)));
    const glm::vec3 s(view[0][0], view[1][0], view[2][0]);
    const glm::vec3 u(view[0][1], view[1][1], view[2][1]);
    const glm::vec3 f(-view[0][2], -view[1][2], -view[2][2]);
    view[3][0] = -glm::dot(s, eye);
    view[3][1] = -glm::dot(u, eye);
    view[3][2] = glm::dot(f, eye);
    return view;
}

}  // namespace litkit::scale_free
