// The kernels for any x86-64 (SSE2) or other CPU xsimd supports by default.
#include "cpu/shade_kernel_impl.hpp"

namespace litkit::kernels {

using PortableImpl = detail::Impl<xsimd::default_arch>;
const Kernels portable_kernels{"portable", &PortableImpl::interpolate, &PortableImpl::shade_phong, &PortableImpl::encode};

}  // namespace litkit::kernels
