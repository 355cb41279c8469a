// SPDX-License-Identifier: MIT
// Sine, cosine and powers with + − × ÷ and exact operations only
// (portable_math.hpp says why).
#include "core/portable_math.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>

namespace litkit {

namespace {

constexpr double pi = 3.141592653589793;

// A double's bits and back (std::bit_cast, which the WebAssembly build's
// libc++ lacks).
std::uint64_t bits_of(double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    return bits;
}
double from_bits(std::uint64_t bits) {
    double x = 0.0;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}

// sin x and cos x for |x| ≤ π/4: Taylor series to x¹⁷/17! and x¹⁸/18!, whose
// next terms (below 1e-19 and 3e-21) are far under a double's last place.
double sin_kernel(double x) {
    const double x2 = x * x;
    double series = 1.0 / 355687428096000.0;  // 1/17!
    series = series * x2 - 1.0 / 1307674368000.0;
    series = series * x2 + 1.0 / 6227020800.0;
    series = series * x2 - 1.0 / 39916800.0;
    series = series * x2 + 1.0 / 362880.0;
    series = series * x2 - 1.0 / 5040.0;
    series = series * x2 + 1.0 / 120.0;
    series = series * x2 - 1.0 / 6.0;
    return x + x * x2 * series;
}

double cos_kernel(double x) {
    const double x2 = x * x;
    double series = -1.0 / 6402373705728000.0;  // −1/18!
    series = series * x2 + 1.0 / 20922789888000.0;
    series = series * x2 - 1.0 / 87178291200.0;
    series = series * x2 + 1.0 / 479001600.0;
    series = series * x2 - 1.0 / 3628800.0;
    series = series * x2 + 1.0 / 40320.0;
    series = series * x2 - 1.0 / 720.0;
    series = series * x2 + 1.0 / 24.0;
    return 1.0 - 0.5 * x2 + x2 * x2 * series;
}

// ln 2 in two parts: the first has 32 significant bits, so k · ln2_high
// (and k · ln2_high / 32) is exact for every |k| < 2²¹ (fdlibm's split).
constexpr double ln2_high = 6.93147180369123816490e-01;
constexpr double ln2_low = 1.90821492927058770002e-10;

// ln c for c in [1, 2) by 2·atanh((c − 1)/(c + 1)), |s| ≤ 1/3, to s⁶¹: for
// the tables below, computed by the compiler (each step an IEEE operation).
constexpr double log_of_table_point(double c) {
    const double s = (c - 1.0) / (c + 1.0);
    double sum = 0.0, term = 2.0 * s;
    for (int n = 1; n <= 61; n += 2, term *= s * s) sum += term / n;
    return sum;
}

// ln c_j of the table points c_j = 1 + j/32, j = 0..31 (ln c_0 = 0 exactly).
constexpr std::array<double, 32> log_table = [] {
    std::array<double, 32> table{};
    for (int j = 0; j < 32; ++j) table[j] = log_of_table_point(1.0 + j / 32.0);
    return table;
}();

// 2^(j/32), j = 0..31: e^x for x = j·ln2/32 < 0.7 by its Taylor series to x³⁰.
constexpr std::array<double, 32> exp2_table = [] {
    std::array<double, 32> table{};
    for (int j = 0; j < 32; ++j) {
        const double x = j * (0.693147180559945309 / 32.0);
        double sum = 0.0, term = 1.0;
        for (int n = 1; n <= 31; ++n) {
            sum += term;
            term = term * x / n;
        }
        table[j] = sum;
    }
    return table;
}();

// ln x for a finite x > 0 (a float's value, so a normal double): x = m·2^e,
// m in [1, 2), c the table point at or below m; ln m = ln c + 2·atanh(s)
// with s = (m − c)/(m + c), 0 ≤ s < 1/64, to s⁹ (the next term is below
// 3e-21). ln 1 is 0 exactly.
double log_positive(double x) {
    const auto bits = bits_of(x);
    const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
    const auto mantissa = bits & 0x000fffffffffffffull;
    const double m = from_bits(mantissa | (1023ull << 52));  // [1, 2)
    const auto j = static_cast<int>(mantissa >> 47);         // m's first 5 bits
    const double c = 1.0 + j / 32.0;
    const double s = (m - c) / (m + c);  // m − c is exact
    const double s2 = s * s;
    const double atanh_twice =
        2.0 * s + s * s2 * (2.0 / 3 + s2 * (2.0 / 5 + s2 * (2.0 / 7 + s2 * (2.0 / 9))));
    return e * ln2_high + (log_table[j] + atanh_twice + e * ln2_low);
}

// e^t where only its float matters: 0 below e^-120 and ∞ above e^100 (both
// beyond a float's range); else t = (32q + j)·ln2/32 + r, |r| ≤ ln2/64, and
// e^t = 2^q · 2^(j/32) · e^r, e^r by its Taylor series to r⁶/6! (the next
// term is below 4e-18).
double exp_for_float(double t) {
    if (t < -120.0) return 0.0;
    if (t > 100.0) return std::numeric_limits<double>::infinity();
    const double scaled = t * (32.0 / 0.693147180559945309);
    const int k = static_cast<int>(scaled < 0.0 ? scaled - 0.5 : scaled + 0.5);
    const double r = (t - k * (ln2_high / 32.0)) - k * (ln2_low / 32.0);
    const double e_r =
        1.0 +
        r * (1.0 + r * (1.0 / 2 + r * (1.0 / 6 + r * (1.0 / 24 + r * (1.0 / 120 + r / 720)))));
    const double two_to_q = from_bits(static_cast<std::uint64_t>((k >> 5) + 1023) << 52);
    return two_to_q * exp2_table[k & 31] * e_r;
}

}  // namespace

SineCosine sin_cos_degrees(double degrees) {
    // Whole turns off exactly, then whole right angles: r in [0, 90], also exact.
    double r = std::fmod(degrees, 360.0);
    if (r < 0.0) r += 360.0;  // may round up to 360 for a tiny negative angle: the same angle
    int quadrant = 0;
    while (r >= 90.0 && quadrant < 3) {
        r -= 90.0;
        ++quadrant;
    }
    // sin and cos of r, from the nearer end of [0°, 90°].
    double s = 0.0, c = 1.0;
    if (r <= 45.0) {
        const double x = r * (pi / 180.0);
        s = sin_kernel(x);
        c = cos_kernel(x);
    } else {
        const double x = (90.0 - r) * (pi / 180.0);
        s = cos_kernel(x);
        c = sin_kernel(x);
    }
    // Turned by the quadrant's right angles; + 0.0 makes a −0 zero.
    switch (quadrant) {
        case 1:
            return {c, -s + 0.0};
        case 2:
            return {-s + 0.0, -c + 0.0};
        case 3:
            return {-c + 0.0, s};
        default:
            return {s, c};
    }
}

float power(float base, float exponent) {
    constexpr float infinity = std::numeric_limits<float>::infinity();
    // C's special cases (C17 F.10.4.4), in its order.
    if (exponent == 0.0f || base == 1.0f) return 1.0f;
    if (std::isnan(base) || std::isnan(exponent)) return std::numeric_limits<float>::quiet_NaN();
    const double x = base, y = exponent;
    if (std::isinf(exponent)) {
        const double magnitude = std::fabs(x);
        if (magnitude == 1.0) return 1.0f;
        return (magnitude < 1.0) == (y > 0.0) ? 0.0f : infinity;
    }
    // Every float of magnitude 2^24 or more is a whole, even number.
    bool whole = true, odd = false;
    if (std::fabs(exponent) < 16777216.0f) {
        const auto n = static_cast<std::int32_t>(exponent);
        whole = static_cast<float>(n) == exponent;
        odd = whole && (n & 1) != 0;
    }
    if (x == 0.0 || std::isinf(x)) {
        // |x|^y is 0 or ∞; an odd whole power keeps the sign of x.
        const bool large = (x == 0.0) == (y < 0.0);
        const float magnitude = large ? infinity : 0.0f;
        return odd && std::signbit(base) ? -magnitude : magnitude;
    }
    if (x < 0.0 && !whole) return std::numeric_limits<float>::quiet_NaN();
    double result = 1.0;
    if (whole && std::fabs(y) <= 64.0) {
        // A whole exponent (shininess 32, a spot's exponent 2): |x|^|y| by
        // repeated squaring, at most 11 products, each exact to half a
        // double's last place: within 2^-46 of the power, relative, as
        // close as exp and log come, at a fraction of their cost.
        double square = std::fabs(x);
        for (auto bits = static_cast<unsigned>(std::fabs(y)); bits != 0; bits >>= 1) {
            if (bits & 1u) result *= square;
            if (bits > 1u) square *= square;
        }
        if (y < 0.0) result = 1.0 / result;
    } else {
        result = exp_for_float(y * log_positive(std::fabs(x)));
    }
    return static_cast<float>(x < 0.0 && odd ? -result : result);
}

}  // namespace litkit
