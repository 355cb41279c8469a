// SPDX-License-Identifier: MIT
// The angle at a triangle's corner for angle-weighted normals (docs/spec.md
// §9.2), with + − × ÷ only.
#pragma once

#include <cmath>

namespace litkit {

// θ in [0, π] with (cos θ, sin θ) along (x, y), for y > 0: std::atan2(y, x).
// Written out because C libraries round atan2 differently in the last bit
// (glibc's and the WebAssembly build's, for one), and every build must find
// the same normals; IEEE arithmetic alone gives the same bits everywhere.
// It is also about three times cheaper than glibc's atan2. Error below
// 1e-15 (tests/test_normals.cpp compares it with std::atan2).
inline double corner_angle(double y, double x) {
    constexpr double pi = 3.141592653589793;
    constexpr double half_pi = 1.5707963267948966;
    // atan(k / 4), k = 0..4, correctly rounded.
    constexpr double atan_of_quarter[5] = {0.0, 0.24497866312686414, 0.4636476090008061,
                                           0.6435011087932844, 0.7853981633974483};
    const double run = std::abs(x);
    const bool steep = y > run;
    const double t = steep ? run / y : y / run;  // in [0, 1]
    // atan(t) = atan(b) + atan(u), u = (t − b) / (1 + t·b), b the nearest quarter: |u| ≤ 1/8.
    const int k = static_cast<int>(t * 4.0 + 0.5);
    const double b = 0.25 * k;
    const double u = (t - b) / (1.0 + t * b);
    const double u2 = u * u;
    // atan(u) = u − u³/3 + … + u¹⁵/15 (Taylor; the next term is below 3e-17).
    double series = -1.0 / 15.0;
    series = series * u2 + 1.0 / 13.0;
    series = series * u2 - 1.0 / 11.0;
    series = series * u2 + 1.0 / 9.0;
    series = series * u2 - 1.0 / 7.0;
    series = series * u2 + 1.0 / 5.0;
    series = series * u2 - 1.0 / 3.0;
    series = series * u2 + 1.0;
    const double atan_t = atan_of_quarter[k] + u * series;
    const double from_x_axis = steep ? half_pi - atan_t : atan_t;  // in [0, π/2]
    return x < 0.0 ? pi - from_x_axis : from_x_axis;
}

}  // namespace litkit
