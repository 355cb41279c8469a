// SPDX-License-Identifier: MIT
#include "cpu/shade_kernel.hpp"

namespace litkit::kernels {

// __builtin_cpu_supports also checks that the OS saves the wider registers
// (XGETBV), so a kernel that keeps AVX-512 off is honoured.
bool cpu_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    return false;
#endif
}

bool cpu_has_avx512() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_cpu_init();
    return cpu_has_avx2() && __builtin_cpu_supports("avx512f") &&
           __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512vl");
#else
    return false;
#endif
}

const Kernels& select_kernels() {
#if defined(__x86_64__) || defined(__i386__)  // the SIMD sets are built for x86 only
    if (cpu_has_avx512()) return avx512_kernels;
    if (cpu_has_avx2()) return avx2_kernels;
#endif
    return portable_kernels;
}

}  // namespace litkit::kernels
