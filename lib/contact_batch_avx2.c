/* The batch kernels of contact_batch.h on AVX2 registers: four doubles a
 * register, compiled for AVX2 whatever the library's flags, and run only
 * where the CPU has it (solver_path_best). */
#include "contact_batch.h"

#ifdef BATCH_X86_KERNELS

#include "contact_batch_w256.h"
#include "shock_batch.h"
#include "solver.h"

/* a mask: all ones or all zeros in each lane */
typedef __m256d wmask;

#define M_GT(a, b) _mm256_cmp_pd ((a), (b), _CMP_GT_OQ)
#define M_GE(a, b) _mm256_cmp_pd ((a), (b), _CMP_GE_OQ)
#define M_LT(a, b) _mm256_cmp_pd ((a), (b), _CMP_LT_OQ)
/* a != b, true where either is NaN */
#define M_NE(a, b) _mm256_cmp_pd ((a), (b), _CMP_NEQ_UQ)
#define M_AND _mm256_and_pd
#define M_OR _mm256_or_pd
#define M_ANDNOT(m, n) _mm256_andnot_pd ((n), (m))
#define W_SEL(m, a, b) _mm256_blendv_pd ((b), (a), (m))
#define M_ANY(m) (_mm256_movemask_pd (m) != 0)
#define KERNEL(name) name##_avx2
#define KERNEL_ATTR __attribute__ ((target ("avx2")))

#include "contact_batch_kernel.h"
#include "shock_kernel.h"

const batch_kernels batch_kernels_avx2
    = { contact_batch_warm_start_avx2, contact_batch_solve_avx2, contact_batch_push_out_avx2,
        contact_batch_solve_push_out_avx2, shock_batch_solve_avx2 };

#else

/* (a compiler that cannot target AVX2 builds none: solver_path_available) */
typedef int contact_batch_avx2_not_built;

#endif
