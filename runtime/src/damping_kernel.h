/* The damping arithmetic of the dynamics model, ONE source for the C++
 * library (src/dynamics/damping.cpp, DampingModel) and libhydrocoef_runtime
 * (runtime_vehicle.c): a damping law's value (terms of one relative
 * velocity component; damping_law_kernel.h, which the library also
 * instantiates for the Monte Carlo lanes) and a derivative model's value (terms that are
 * products of factors |x|^power, signed when odd, over the relative velocity
 * and disturbance parameters). Static inline C11, in the common subset of C
 * and C++; both libraries compile it with -ffp-contract=off, so their
 * numbers are the same bit for bit.
 *
 * Units and signs: the relative velocity nu_r = nu - nu_c in body axes (u,
 * v, w [m/s], p, q, r [rad/s]), disturbances in SI, coefficients with the
 * sign convention folded in: the result is the force or moment ON THE BODY
 * [N, N m] (damping negative). */
#ifndef HYDROCOEF_DAMPING_KERNEL_H
#define HYDROCOEF_DAMPING_KERNEL_H

#include <math.h>
#include <stddef.h>

/* A law's basis terms in x (src/core/damping_terms.hpp, DampingTerm). */
enum {
  HC_DAMPING_CONSTANT = 0,         /* 1 */
  HC_DAMPING_LINEAR = 1,           /* x */
  HC_DAMPING_SIGNED_QUADRATIC = 2, /* x|x| */
  HC_DAMPING_QUADRATIC = 3,        /* x^2 */
  HC_DAMPING_CUBIC = 4,            /* x^3 */
  HC_DAMPING_ABS_LINEAR = 5,       /* |x| */
  HC_DAMPING_TERM_CODES = 6
};

/* A law's value, hc_damping_law_value (damping_law_kernel.h), for double. */
#include "damping_law_kernel.h"

/* One name's factor of a derivative model's term: |x|^power, negated when
 * odd and x < 0; x is nu_r[source] for source < 6, else
 * disturbances[source - 6]. */
typedef struct hc_damping_factor {
  size_t source;
  int power; /* >= 1 */
  int odd;   /* 0 or 1 */
} hc_damping_factor;

static inline double hc_damping_factor_value(int power, int odd, double x) {
  const double magnitude = fabs(x);
  double out = magnitude;
  for (int k = 1; k < power; ++k) out *= magnitude;
  return odd && x < 0.0 ? -out : out;
}

/* sum_k coefficients[k] * prod_{i in [begin[k], begin[k + 1])} factor_i,
 * each term's product from 1.0 and the sum from 0.0 in term order. */
static inline double hc_damping_derivatives_value(const double* coefficients, size_t count, const size_t* begin,
                                                  const hc_damping_factor* factors, const double* nu_r,
                                                  const double* disturbances) {
  double sum = 0.0;
  for (size_t k = 0; k < count; ++k) {
    double term = 1.0;
    for (size_t i = begin[k]; i < begin[k + 1]; ++i) {
      const hc_damping_factor* f = &factors[i];
      term *= hc_damping_factor_value(f->power, f->odd, f->source < 6 ? nu_r[f->source] : disturbances[f->source - 6]);
    }
    sum += coefficients[k] * term;
  }
  return sum;
}

#endif
