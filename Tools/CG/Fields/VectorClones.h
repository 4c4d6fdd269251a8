// TALUS_CG_VECTOR_CLONES: a hot loop of the coarse graining compiled twice, for baseline x86-64
// and for AVX2, and the processor's clone chosen when the program loads (function
// multiversioning, GCC and Clang on x86-64). The AVX2 clone has twice the lanes and no fused
// multiply-add (not part of "avx2"), so both clones do the same operations in the same order and
// give the same sums to the bit (Documentation/CoarseGraining.md "Cost").
#pragma once

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define TALUS_CG_VECTOR_CLONES [[gnu::target_clones("avx2", "default")]]
#else
#define TALUS_CG_VECTOR_CLONES
#endif
