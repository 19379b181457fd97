/* The batch kernels of contact_batch.h with AVX-512's registers: the AVX2
 * kernels' four doubles a register, compiled for AVX-512F and AVX-512VL,
 * so that they have 32 such registers instead of 16 and keep their masks
 * in mask registers. The AVX2 kernels keep a quarter of their values on
 * the stack for want of registers (172 of the 662 instructions of the
 * solve pass read or write it); here 43 of 572. Run only where the CPU has
 * both (solver_path_best); elsewhere, and with compilers without the
 * target attribute, these are the portable kernels. Eight lanes to a
 * register instead was measured and not taken (docs/performance.md). */
#include "contact_batch.h"

#include "shock_batch.h"
#include "solver.h"

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)

#include <immintrin.h>

typedef __m256d wide;
typedef __mmask8 wmask; /* lanes 0-3 in bits 0-3 */

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
#define M_GT(a, b) _mm256_cmp_pd_mask ((a), (b), _CMP_GT_OQ)
#define M_GE(a, b) _mm256_cmp_pd_mask ((a), (b), _CMP_GE_OQ)
#define M_LT(a, b) _mm256_cmp_pd_mask ((a), (b), _CMP_LT_OQ)
/* a != b, true where either is NaN */
#define M_NE(a, b) _mm256_cmp_pd_mask ((a), (b), _CMP_NEQ_UQ)
#define M_AND(m, n) ((wmask) ((m) & (n)))
#define M_OR(m, n) ((wmask) ((m) | (n)))
#define M_ANDNOT(m, n) ((wmask) ((m) & ~(n)))
#define W_SEL(m, a, b) _mm256_mask_blend_pd ((m), (b), (a))
#define M_ANY(m) ((m) != 0)
#define KERNEL(name) name##_avx512
#define KERNEL_ATTR __attribute__ ((target ("avx2,avx512f,avx512vl")))
#define KERNEL_TRANSPOSE 1

#include "contact_batch_kernel.h"
#include "shock_kernel.h"

#else

void contact_batch_warm_start_avx512 (contact_batch *c, int32_t n, struct solver_body *sb)
{
  contact_batch_warm_start_portable (c, n, sb);
}

void contact_batch_solve_avx512 (contact_batch *c, int32_t n, struct solver_body *sb, double inv_h)
{
  contact_batch_solve_portable (c, n, sb, inv_h);
}

void contact_batch_push_out_avx512 (contact_batch *c, int32_t n, struct solver_body *sb, double push_rate, int first)
{
  contact_batch_push_out_portable (c, n, sb, push_rate, first);
}

void contact_batch_solve_push_out_avx512 (contact_batch *c, int32_t n, struct solver_body *sb, double inv_h,
                                          double push_rate)
{
  contact_batch_solve_push_out_portable (c, n, sb, inv_h, push_rate);
}

void shock_batch_solve_avx512 (shock_batch *c, int32_t n, int points, struct solver_body *sb, double tol,
                               double inv_h, int32_t moves)
{
  shock_batch_solve_portable (c, n, points, sb, tol, inv_h, moves);
}

#endif
