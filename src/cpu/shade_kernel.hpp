// The per-pixel stages that run on many pixels at once: Phong-shading a run
// of pixels and turning intensities into pixel values. Compiled once per
// instruction set (AVX-512, AVX2+FMA and a portable baseline) from the same
// template text; `select_kernels` picks one at run time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "litkit/equations.hpp"
#include "litkit/lighting.hpp"

namespace litkit::kernels {

// A run of pixels in structure-of-arrays form: the interpolated world
// position and (not yet renormalised) normal of each.
struct SurfaceRun {
    const float* px;
    const float* py;
    const float* pz;
    const float* nx;
    const float* ny;
    const float* nz;
    std::size_t count;
};

struct ColorRun {
    float* r;
    float* g;
    float* b;
};

struct Kernels {
    const char* name;
    // docs/spec.md §3 Phong shading: renormalise the normal, light per pixel.
    void (*shade_phong)(Reflection reflection, std::span<const equations::PreparedLight> lights,
                        const Material& material, const float eye[3], const SurfaceRun& surface,
                        const ColorRun& out);
    // docs/spec.md §4 pixel values: round(255 · clamp(I, 0, 1)^(1/gamma)) per channel,
    // written as interleaved RGB bytes.
    void (*encode)(const float* r, const float* g, const float* b, std::size_t count, float gamma,
                   std::uint8_t* rgb);
};

extern const Kernels portable_kernels;
extern const Kernels avx2_kernels;    // only valid where the CPU has AVX2 and FMA
extern const Kernels avx512_kernels;  // only where it has AVX-512 F, BW, DQ, VL (and FMA)

bool cpu_has_avx2();
bool cpu_has_avx512();

// The fastest set this CPU runs: AVX-512, else AVX2, else portable.
const Kernels& select_kernels();

}  // namespace litkit::kernels
