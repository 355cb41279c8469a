#include "cpu/shade_kernel.hpp"

namespace litkit::kernels {

const Kernels& select_kernels() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return avx2_kernels;
#endif
    return portable_kernels;
}

}  // namespace litkit::kernels
