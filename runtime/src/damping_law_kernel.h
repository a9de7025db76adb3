/* A damping law's value, sum_k c_k basis_k(x) over the basis terms 1, x,
 * x|x|, x^2, x^3, |x| (codes HC_DAMPING_*, damping_kernel.h): ONE source for
 * libhydrocoef_runtime and the C++ library's DampingModel (double) and
 * DampingLanes (8 lanes of an Eigen array, each lane the scalar operations
 * in the same order). Written, as motion_kernel.h, over a number type
 * HC_DAMPING_T with HC_DAMPING_SPLAT(v) and HC_DAMPING_ABS(x); double by
 * default. No include guard: each inclusion defines the function for the
 * current type, then undefines the macros. */

#ifndef HC_DAMPING_T
#define HC_DAMPING_T double
#define HC_DAMPING_SPLAT(v) (v)
#define HC_DAMPING_ABS(x) fabs(x)
#endif

/* sum_k coefficients[k] basis_{terms[k]}(*x), in term order from 0; every
 * code below HC_DAMPING_TERM_CODES (the callers check). x by address (an
 * Eigen array is not passed by value). */
static inline HC_DAMPING_T hc_damping_law_value(const int* terms, const HC_DAMPING_T* coefficients, size_t count,
                                                const HC_DAMPING_T* at) {
  const HC_DAMPING_T x = *at;
  const HC_DAMPING_T magnitude = HC_DAMPING_ABS(x);
  const HC_DAMPING_T basis[6] = {HC_DAMPING_SPLAT(1.0), x, x * magnitude, x * x, x * x * x, magnitude};
  HC_DAMPING_T value = HC_DAMPING_SPLAT(0.0);
  for (size_t k = 0; k < count; ++k) value += coefficients[k] * basis[terms[k]];
  return value;
}

#undef HC_DAMPING_T
#undef HC_DAMPING_SPLAT
#undef HC_DAMPING_ABS
