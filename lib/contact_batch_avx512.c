/* The batch kernels of contact_batch.h with AVX-512's registers: eight
 * doubles a register, a batch's eight lanes at once, compiled for
 * AVX-512F and AVX-512VL whatever the library's flags (32 registers,
 * masks in mask registers), and run only where the CPU has them
 * (solver_path_best). Shock propagation's kernel, four lanes a batch, is
 * shock_avx512.c's. */
#include "contact_batch.h"

#ifdef BATCH_X86_KERNELS

#include <immintrin.h>
#include <stdint.h>

#include "shock_batch.h"
#include "solver.h"

typedef __m512d wide;
typedef __mmask8 wmask; /* lane i in bit i */

#define KERNEL_WIDTH 8
#define W_LOAD _mm512_loadu_pd
#define W_STORE _mm512_storeu_pd
#define W_SET1 _mm512_set1_pd
#define W_ADD _mm512_add_pd
#define W_SUB _mm512_sub_pd
#define W_MUL _mm512_mul_pd
#define W_DIV _mm512_div_pd
/* the sign bit flipped, as the other paths' negation (AVX-512F has no
 * xor of doubles) */
#define W_NEG(a) _mm512_castsi512_pd (_mm512_xor_si512 (_mm512_castpd_si512 (a), _mm512_set1_epi64 (INT64_MIN)))
/* vmaxpd and vminpd: a > b ? a : b and a < b ? a : b, lane by lane */
#define W_MAX _mm512_max_pd
#define W_MIN _mm512_min_pd
#define M_GT(a, b) _mm512_cmp_pd_mask ((a), (b), _CMP_GT_OQ)
#define M_GE(a, b) _mm512_cmp_pd_mask ((a), (b), _CMP_GE_OQ)
#define M_LT(a, b) _mm512_cmp_pd_mask ((a), (b), _CMP_LT_OQ)
/* a != b, true where either is NaN */
#define M_NE(a, b) _mm512_cmp_pd_mask ((a), (b), _CMP_NEQ_UQ)
#define M_AND(m, n) ((wmask) ((m) & (n)))
#define M_OR(m, n) ((wmask) ((m) | (n)))
#define M_ANDNOT(m, n) ((wmask) ((m) & ~(n)))
#define W_SEL(m, a, b) _mm512_mask_blend_pd ((m), (b), (a))
#define M_ANY(m) ((m) != 0)
/* lanes 0-3 where m has one of them, and lanes 4-7 where it has one */
#define M_GROUPS(m) ((wmask) ((((m) & 0x0f) != 0 ? 0x0f : 0) | (((m) & 0xf0) != 0 ? 0xf0 : 0)))
#define W_MERGE(g, a, b) W_SEL ((g), (a), (b))
/* the bodies gathered by 4 x 4 transposes, two to a register */
#define KERNEL_TRANSPOSE 1
#define KERNEL(name) name##_avx512
#define KERNEL_ATTR __attribute__ ((target ("avx2,avx512f,avx512vl")))

#include "contact_batch_kernel.h"

const batch_kernels batch_kernels_avx512
    = { contact_batch_warm_start_avx512, contact_batch_solve_avx512, contact_batch_push_out_avx512,
        contact_batch_solve_push_out_avx512, shock_batch_solve_avx512 };

#else

/* (a compiler that cannot target AVX-512 builds none: solver_path_available) */
typedef int contact_batch_avx512_not_built;

#endif
