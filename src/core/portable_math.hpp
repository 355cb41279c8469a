// SPDX-License-Identifier: MIT
// Sine, cosine and powers that give the same bits in every build.
//
// C libraries round sinf, cosf and powf (and, more rarely, their double
// forms) differently in the last bit: glibc's and the WebAssembly build's
// (emscripten's musl) for one, so that a rotated or shiny scene could differ
// by a pixel between `litkit render` and the playground (docs/web.md). These
// are written with + − × ÷, fmod and bit operations only, which IEEE
// arithmetic gives the same way everywhere (without FMA contraction, which
// src/CMakeLists.txt turns off here and WebAssembly lacks); each is within a few units in
// the last place of a double, so rounded to float it is the correctly
// rounded value but for rare near-ties (tests/test_portable_math.cpp).
#pragma once

namespace litkit {

// sin and cos of an angle in degrees, any finite value. The angle is reduced
// by whole turns exactly (fmod), so 10000° is 280° to the bit, and the four
// right angles give exact 0 and ±1.
struct SineCosine {
    double sine = 0.0;
    double cosine = 1.0;
};
SineCosine sin_cos_degrees(double degrees);

// cos(θ) and sin(θ) alone.
inline double cos_degrees(double degrees) { return sin_cos_degrees(degrees).cosine; }
inline double sin_degrees(double degrees) { return sin_cos_degrees(degrees).sine; }

// base^exponent as C's powf defines it (its special cases: 0^0 = 1, a
// negative base only with a whole exponent, infinities), computed in double
// as exp(exponent · log base) and rounded once to float.
float power(float base, float exponent);

}  // namespace litkit
