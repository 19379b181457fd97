/* Shock propagation's kernel (shock_kernel.h) with AVX-512's registers:
 * four doubles a register, as the AVX2 kernel's, compiled for AVX-512F and
 * AVX-512VL (32 registers, masks in mask registers) for
 * contact_batch_avx512.c's table. */
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
#define SHOCK_KERNEL_LINKAGE

#include "batch_lanes.h"
#include "shock_kernel.h"

#else

/* (a compiler that cannot target AVX-512 builds none: solver_path_available) */
typedef int shock_avx512_not_built;

#endif
