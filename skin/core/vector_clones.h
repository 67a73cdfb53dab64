// HYLIOS_VECTOR_CLONES: marks a per-wavelength kernel (a loop over contiguous values) to be
// compiled three times with GCC on x86-64 (AVX-512, AVX2 and the SSE2 baseline), the best one
// chosen when the program loads. Elementwise loops compute the same bits in every clone when the
// source file is built without fused multiply-adds (-ffp-contract=off, skin/CMakeLists.txt).
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__)
#define HYLIOS_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define HYLIOS_VECTOR_CLONES
#endif
