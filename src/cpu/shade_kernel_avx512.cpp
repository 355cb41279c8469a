// The kernels for AVX-512 (F, BW, DQ, VL) with FMA: 16 pixels per
// instruction. This file alone is compiled with those flags; it runs only
// where select_kernels finds them (and the OS saves the ZMM registers).
#include "cpu/shade_kernel_impl.hpp"

namespace litkit::kernels {

using Avx512Impl = detail::Impl<xsimd::avx512bw>;
const Kernels avx512_kernels{"avx512", &Avx512Impl::interpolate, &Avx512Impl::shade_phong, &Avx512Impl::encode};

}  // namespace litkit::kernels
