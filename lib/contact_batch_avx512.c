/* The batch kernels of contact_batch.h with AVX-512's registers: the AVX2
 * kernels' four doubles a register, compiled for AVX-512F and AVX-512VL,
 * so that they have 32 such registers instead of 16 and keep their masks
 * in mask registers. The AVX2 kernels keep a quarter of their values on
 * the stack for want of registers (172 of the 662 instructions of the
 * solve pass read or write it); here 43 of 572. Run only where the CPU has
 * both (solver_path_best). Eight lanes to a register instead was measured
 * and not taken (docs/performance.md). */
#include "contact_batch.h"

#ifdef BATCH_X86_KERNELS

#include "contact_batch_w256.h"
#include "shock_batch.h"
#include "solver.h"

typedef __mmask8 wmask; /* lanes 0-3 in bits 0-3 */

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

#include "contact_batch_kernel.h"
#include "shock_kernel.h"

const batch_kernels batch_kernels_avx512
    = { contact_batch_warm_start_avx512, contact_batch_solve_avx512, contact_batch_push_out_avx512,
        contact_batch_solve_push_out_avx512, shock_batch_solve_avx512 };

#else

/* (a compiler that cannot target AVX-512 builds none: solver_path_available) */
typedef int contact_batch_avx512_not_built;

#endif
