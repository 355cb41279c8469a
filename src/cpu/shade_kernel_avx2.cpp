// The kernels for AVX2 with FMA: 8 pixels per instruction. This file alone
// is compiled with -mavx2 -mfma; it runs only where select_kernels finds them.
#include "cpu/shade_kernel_impl.hpp"

namespace litkit::kernels {

using Avx2Impl = detail::Impl<xsimd::avx2>;
const Kernels avx2_kernels{"avx2", &Avx2Impl::interpolate, &Avx2Impl::shade_phong, &Avx2Impl::encode};

}  // namespace litkit::kernels
