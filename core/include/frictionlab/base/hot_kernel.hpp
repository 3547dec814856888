#pragma once
// Hot loops on raw pointers get AVX-512 and AVX2 clones next to the baseline one, picked once per
// process by the CPU (GCC function multiversioning). Code stays built for the baseline ISA, so
// Eigen's alignment, and hence the plugin ABI fingerprint, is unchanged. A library with such
// kernels is built with -ffp-contract=off: no clone forms FMAs, so all of them round identically
// and a run gives the same bits on every x86-64 machine.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define FRICTIONLAB_HOT_KERNEL __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define FRICTIONLAB_HOT_KERNEL
#endif
