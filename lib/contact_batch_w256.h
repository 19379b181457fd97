/* The lane arithmetic of batch_lanes.h on four doubles a 256-bit register,
 * shared by the AVX2 kernels and AVX-512's shock kernel (which differ in
 * their masks): each one IEEE rounding, as the portable kernels'. */
#ifndef CAROM_CONTACT_BATCH_W256_H
#define CAROM_CONTACT_BATCH_W256_H

#include <immintrin.h>

typedef __m256d wide;

#define W_LOAD _mm256_loadu_pd
#define W_STORE _mm256_storeu_pd
#define W_SET1 _mm256_set1_pd
#define W_ADD _mm256_add_pd
#define W_SUB _mm256_sub_pd
#define W_MUL _mm256_mul_pd
#define W_DIV _mm256_div_pd
#define W_NEG(a) _mm256_xor_pd ((a), _mm256_set1_pd (-0.0))
/* (v)maxpd and (v)minpd: a > b ? a : b and a < b ? a : b, lane by lane */
#define W_MAX _mm256_max_pd
#define W_MIN _mm256_min_pd
/* the kernels' gathering of bodies: 4 x 4 transposes (batch_lanes.h) */
#define KERNEL_TRANSPOSE 1

#endif
