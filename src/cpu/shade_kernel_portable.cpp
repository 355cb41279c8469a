// SPDX-License-Identifier: MIT
// The kernels for any x86-64 (SSE2) or other CPU xsimd supports by default.
#include <cstring>

#include "cpu/shade_kernel_impl.hpp"

namespace litkit::kernels {

using PortableImpl = detail::Impl<xsimd::default_arch>;

void visibility_row_scalar(const std::int64_t v[3], const std::int64_t step[3],
                           const float weight[3], std::size_t count, float* depth,
                           const void** visible, const void* triangle, float* weight1,
                           float* weight2) {
    std::int64_t v0 = v[0], v1 = v[1], v2 = v[2];
    for (std::size_t i = 0; i < count; ++i, v0 += step[0], v1 += step[1], v2 += step[2]) {
        // Screen-space barycentrics scaled by 1/w: their sum is the
        // interpolated 1/w (1 / view depth, linear on screen).
        const float p0 = static_cast<float>(v0) * weight[0];
        const float p1 = static_cast<float>(v1) * weight[1];
        const float p2 = static_cast<float>(v2) * weight[2];
        const float inverse_w = p0 + p1 + p2;
        // Depth test on 1/w: larger is nearer (orders like OpenGL's z).
        if (inverse_w <= depth[i]) continue;
        depth[i] = inverse_w;
        std::memcpy(&visible[i], &triangle,
                    sizeof triangle);  // the caller's pointer type, as bytes
        weight1[i] = p1;               // divided by 1/w once, when shading
        weight2[i] = p2;
    }
}

const Kernels portable_kernels{"portable",
                               &PortableImpl::interpolate,
                               &PortableImpl::transform_vertices,
                               &PortableImpl::perspective_weights,
                               &PortableImpl::shade_phong,
                               &PortableImpl::encode,
                               &PortableImpl::accumulate,
                               &visibility_row_scalar,
                               nullptr};

}  // namespace litkit::kernels
