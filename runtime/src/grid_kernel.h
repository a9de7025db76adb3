/* The arithmetic of a gridded table's evaluation, shared by the C++ library
 * (GridTable in src/surface/grid_table.cpp, the batch evaluation in
 * src/surface/batch_evaluation.cpp) and the C runtime library
 * (runtime/src/runtime_evaluate.c), so that both give the same numbers bit
 * for bit: the set-up of an axis's lookup, the cell search, the per-axis
 * weights of each method and extrapolation policy, the cubic Hermite
 * weights, the offsets of a cell's terms and the local sum over a cell's K^n
 * terms of weight times node value.
 *
 * C11 and C++20 alike: static inline functions only, no allocation, no
 * errno. Both libraries compile it with -ffp-contract=off, so every
 * expression rounds as written. The C++ library calls these functions with
 * compile-time constants (K, the axis count, the outputs per block), which
 * the compiler folds after inlining; the runtime calls them with the table's
 * numbers. The order of every operation is the same either way.
 *
 * Layout of the evaluated array (GridTable::hermite_data() for the cubic
 * methods, GridTable::values() for nearest and linear): per node a block of
 * node_block numbers; block = 2^n * n_out (cubic: per subset S of the axes,
 * bit a set for one derivative along axis a, the n_out outputs) or n_out. */
#ifndef HYDROCOEF_RUNTIME_GRID_KERNEL_H
#define HYDROCOEF_RUNTIME_GRID_KERNEL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#if defined(__GNUC__) || defined(__clang__)
#define HC_KERNEL_INLINE static inline __attribute__((always_inline))
#define HC_KERNEL_COLD static __attribute__((noinline, cold, unused))
#else
#define HC_KERNEL_INLINE static inline
#define HC_KERNEL_COLD static inline
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* The most axes of a table, and the terms per axis of the cubic methods. */
enum { HC_KERNEL_MAX_AXES = 6 };

/* Method codes (the C++ enum hydrocoef::Interpolation has these values). */
enum {
  HC_KERNEL_NEAREST = 0,
  HC_KERNEL_LINEAR = 1,
  HC_KERNEL_PCHIP = 2,
  HC_KERNEL_MAKIMA = 3,
  HC_KERNEL_NATURAL_SPLINE = 4
};
/* Extrapolation policy codes (hydrocoef::Extrapolation has these values). */
enum { HC_KERNEL_ERROR = 0, HC_KERNEL_CLAMP = 1, HC_KERNEL_EXTRAPOLATE_LINEAR = 2, HC_KERNEL_METHOD = 3 };
/* What hc_kernel_axis_cell reports. */
enum { HC_KERNEL_OK = 0, HC_KERNEL_OUTSIDE = 1, HC_KERNEL_NOT_FINITE = 2 };

/* Per-axis lookup data derived from the breakpoints (hc_kernel_axis_setup). */
typedef struct hc_kernel_axis {
  double lo;          /* first breakpoint */
  double hi;          /* last breakpoint */
  double inv_step;    /* 1 / spacing, used when evenly spaced */
  int even;           /* located by direct index */
  int extrapolation;  /* HC_KERNEL_ERROR .. HC_KERNEL_METHOD */
  size_t count;       /* breakpoints, >= 2 */
  size_t offset;      /* of the first breakpoint in the table's breakpoint array */
  size_t node_stride; /* nodes between neighbours along this axis */
} hc_kernel_axis;

/* Terms per axis of a method's local sum: 1 (nearest), 2 (linear), 4 (cubic). */
HC_KERNEL_INLINE size_t hc_kernel_terms_per_axis(int method) {
  return method == HC_KERNEL_NEAREST ? 1u : (method == HC_KERNEL_LINEAR ? 2u : 4u);
}

HC_KERNEL_INLINE size_t hc_kernel_power(size_t base, size_t exponent) {
  size_t result = 1;
  for (size_t i = 0; i < exponent; ++i) result *= base;
  return result;
}

/* Fills lo, hi, count, even and inv_step from finite, strictly increasing
 * breakpoints x[0 .. count-1] (count >= 2). "Even" when every breakpoint is
 * within 1e-12 of the range's magnitude of the even grid and that tolerance
 * is well below the spacing (the direct index is corrected by one cell at
 * most). A performance detail: both ways find the same cell. */
HC_KERNEL_INLINE void hc_kernel_axis_setup(const double* x, size_t count, hc_kernel_axis* axis) {
  axis->lo = x[0];
  axis->hi = x[count - 1];
  axis->count = count;
  const double step = (axis->hi - axis->lo) / (double)(count - 1);
  const double lo_magnitude = fabs(axis->lo), hi_magnitude = fabs(axis->hi);
  const double tolerance = 1e-12 * (lo_magnitude < hi_magnitude ? hi_magnitude : lo_magnitude);
  int even = tolerance < 0.25 * step;
  for (size_t i = 0; i < count && even; ++i) even = fabs(x[i] - (axis->lo + (double)i * step)) <= tolerance;
  axis->even = even;
  axis->inv_step = 1.0 / step;
}

/* Cubic Hermite basis on a cell of width h at t = (x - x_i) / h, in term
 * order (corner 0 value, corner 0 slope, corner 1 value, corner 1 slope);
 * slope terms carry h so that they multiply d/dx in axis units. */
HC_KERNEL_INLINE void hc_kernel_hermite_weights(double t, double h, double* w) {
  const double t2 = t * t;
  const double t3 = t2 * t;
  w[0] = 2.0 * t3 - 3.0 * t2 + 1.0;
  w[1] = h * (t3 - 2.0 * t2 + t);
  w[2] = 3.0 * t2 - 2.0 * t3;
  w[3] = h * (t3 - t2);
}

/* d/dx of hc_kernel_hermite_weights. */
HC_KERNEL_INLINE void hc_kernel_hermite_derivative_weights(double t, double h, double* dw) {
  const double t2 = t * t;
  dw[0] = 6.0 * (t2 - t) / h;
  dw[1] = 3.0 * t2 - 4.0 * t + 1.0;
  dw[2] = 6.0 * (t - t2) / h;
  dw[3] = 3.0 * t2 - 2.0 * t;
}

/* The weights of a linear (K = 2) or cubic (K = 4) cell of width h at
 * t = (x - x_i) / h, and with_gradient their derivatives d/dx. */
HC_KERNEL_INLINE void hc_kernel_cell_weights(size_t K, int with_gradient, double t, double h, double* w, double* dw) {
  if (K == 2) {
    w[0] = 1.0 - t;
    w[1] = t;
    if (with_gradient) {
      dw[0] = -1.0 / h;
      dw[1] = 1.0 / h;
    }
  } else {
    hc_kernel_hermite_weights(t, h, w);
    if (with_gradient) hc_kernel_hermite_derivative_weights(t, h, dw);
  }
}

/* The cell [x[cell], x[cell + 1]] of a value inside the axis's range
 * (lo <= value <= hi): the last breakpoint <= value among x[0 .. count-2]. */
HC_KERNEL_INLINE size_t hc_kernel_cell_inside(const hc_kernel_axis* axis, const double* x, double value) {
  const size_t last_cell = axis->count - 2;
  if (axis->even) {
    /* value >= lo here, so the signed conversion (one instruction, where the
     * unsigned one is several) gives the same index. */
    size_t cell = (size_t)(int64_t)((value - axis->lo) * axis->inv_step);
    if (cell > last_cell) cell = last_cell;
    /* Rounding in the breakpoints or the product can put the index one cell off. */
    if (value < x[cell]) {
      --cell;
    } else if (cell < last_cell && value >= x[cell + 1]) {
      ++cell;
    }
    return cell;
  }
  /* Branch-free binary search. */
  const double* first = x;
  size_t length = axis->count - 1;
  while (length > 1) {
    const size_t half = length / 2;
    first = first[half] <= value ? first + half : first;
    length -= half;
  }
  return (size_t)(first - x);
}

/* hc_kernel_axis_cell for a value outside the axis's range (or not finite):
 * HC_KERNEL_NOT_FINITE or HC_KERNEL_OUTSIDE (policy error) without writing
 * anything; else *cell, and *done = 1 when the weights are written (clamped,
 * or linear beyond a cubic's end), 0 when the end cell's polynomial
 * continues (the caller computes its weights at t outside [0, 1]). */
HC_KERNEL_COLD int hc_kernel_axis_cell_outside(const hc_kernel_axis* axis, size_t K, int with_gradient, double value,
                                               double* w, double* dw, size_t* cell, int* done) {
  if (!isfinite(value)) return HC_KERNEL_NOT_FINITE;
  if (axis->extrapolation == HC_KERNEL_ERROR) return HC_KERNEL_OUTSIDE;
  const int below = value < axis->lo;
  const size_t end_cell = below ? 0 : axis->count - 2;
  int policy = axis->extrapolation;
  if (K == 1) policy = HC_KERNEL_CLAMP; /* a constant's own continuation and its slope are both flat */
  if (K == 2 && policy == HC_KERNEL_EXTRAPOLATE_LINEAR) policy = HC_KERNEL_METHOD; /* the same line */
  *done = 1;
  if (policy == HC_KERNEL_CLAMP) {
    /* The end node's value alone; flat along this axis. */
    const size_t end = below || K == 1 ? 0 : (K == 4 ? 2 : 1);
    for (size_t e = 0; e < K; ++e) {
      w[e] = e == end ? 1.0 : 0.0;
      if (with_gradient) dw[e] = 0.0;
    }
    *cell = K == 1 && !below ? end_cell + 1 : end_cell;
    return HC_KERNEL_OK;
  }
  if (K == 4 && policy == HC_KERNEL_EXTRAPOLATE_LINEAR) {
    /* End value plus end slope times the distance beyond the end. */
    const double distance = value - (below ? axis->lo : axis->hi);
    const size_t end = below ? 0 : 2;
    for (size_t e = 0; e < K; ++e) {
      w[e] = e == end ? 1.0 : (e == end + 1 ? distance : 0.0);
      if (with_gradient) dw[e] = e == end + 1 ? 1.0 : 0.0;
    }
    *cell = end_cell;
    return HC_KERNEL_OK;
  }
  /* Extrapolation method: the end cell's polynomial at t outside [0, 1]. */
  *done = 0;
  *cell = end_cell;
  return HC_KERNEL_OK;
}

/* The weights w[0 .. K-1] (and with_gradient, their derivatives dw) of
 * `value` along an axis with breakpoints x, and in *node the node along the
 * axis the weights start at. HC_KERNEL_OK, or HC_KERNEL_OUTSIDE /
 * HC_KERNEL_NOT_FINITE (nothing written) as hc_kernel_axis_cell_outside. */
HC_KERNEL_INLINE int hc_kernel_axis_cell(const hc_kernel_axis* axis, const double* x, size_t K, int with_gradient,
                                         double value, double* w, double* dw, size_t* node) {
  size_t cell = 0;
  if (value >= axis->lo && value <= axis->hi) {
    cell = hc_kernel_cell_inside(axis, x, value);
  } else {
    int done = 0;
    const int status = hc_kernel_axis_cell_outside(axis, K, with_gradient, value, w, dw, &cell, &done);
    if (status != HC_KERNEL_OK) return status;
    if (done) {
      *node = cell;
      return HC_KERNEL_OK;
    }
  }
  const double h = x[cell + 1] - x[cell];
  const double t = (value - x[cell]) / h;
  if (K == 1) {
    w[0] = 1.0;
    if (with_gradient) dw[0] = 0.0;
    *node = t >= 0.5 ? cell + 1 : cell;
    return HC_KERNEL_OK;
  }
  hc_kernel_cell_weights(K, with_gradient, t, h, w, dw);
  *node = cell;
  return HC_KERNEL_OK;
}

/* The offsets of the K^n terms of the local sum from a cell's base, axis 0's
 * term fastest: offsets[t] for t < K^n. n_out outputs, node_block numbers per
 * node, node_stride[a] nodes between neighbours along axis a. */
HC_KERNEL_INLINE void hc_kernel_term_offsets(size_t n, int method, size_t n_out, size_t node_block,
                                             const size_t* node_stride, size_t* offsets) {
  const size_t K = hc_kernel_terms_per_axis(method);
  size_t axis_offsets[HC_KERNEL_MAX_AXES][4] = {{0}};
  for (size_t a = 0; a < n; ++a) {
    const size_t next_node = node_stride[a] * node_block;
    if (K == 4) {
      const size_t slope = ((size_t)1 << a) * n_out;
      axis_offsets[a][0] = 0;
      axis_offsets[a][1] = slope;
      axis_offsets[a][2] = next_node;
      axis_offsets[a][3] = next_node + slope;
    } else {
      axis_offsets[a][0] = 0;
      axis_offsets[a][1] = next_node;
    }
  }
  const size_t terms = hc_kernel_power(K, n);
  for (size_t t = 0; t < terms; ++t) {
    size_t rest = t, offset = 0;
    for (size_t a = 0; a < n; ++a) {
      offset += axis_offsets[a][rest % K];
      rest /= K;
    }
    offsets[t] = offset;
  }
}

/* The product of the weights of axes 0 .. n-2, inner[t] = prod_a w_a[e_a]
 * with t = sum_a e_a K^a (K^(n-1) entries), built one axis at a time; the
 * last axis's weights multiply partial sums instead, which saves K^n
 * multiplications. axis_weights: 4 per axis; axis `replaced` (if < n) uses
 * `replacement` instead (a partial derivative). */
HC_KERNEL_INLINE void hc_kernel_inner_weights(size_t n, size_t K, const double* axis_weights, size_t replaced,
                                              const double* replacement, double* inner) {
  inner[0] = 1.0;
  size_t length = 1;
  for (size_t a = 0; a + 1 < n; ++a) {
    const double* w = a == replaced ? replacement : axis_weights + 4 * a;
    for (size_t e = K; e-- > 1;) {
      for (size_t j = 0; j < length; ++j) inner[e * length + j] = inner[j] * w[e];
    }
    for (size_t j = 0; j < length; ++j) inner[j] *= w[0];
    length *= K;
  }
}

#if defined(__GNUC__) || defined(__clang__)
/* Two doubles side by side (GCC's and Clang's vector extension): two outputs
 * of a term in one instruction, each lane rounding exactly as the scalar
 * operation would (no contraction: the kernel is compiled with
 * -ffp-contract=off). */
typedef double hc_kernel_pair __attribute__((vector_size(16)));
#define HC_KERNEL_PAIRS 1
#endif

/* m outputs at once (m <= 6). The weight of term t = t_inner + e * k_inner
 * is inner[t_inner] * last[e], so out[j * out_stride] =
 * sum_e last[e] sum_t_inner inner[t_inner] * data[offsets[t] + j]. The K
 * partial sums over t_inner run side by side (K * m independent additions
 * per step instead of one chain of K * k_inner), each in the order of
 * t_inner, and are combined in the order of e: every output is the same
 * sequence of roundings as one partial sum after the other. An even m takes
 * the outputs two by two (hc_kernel_pair), with the same roundings. */
HC_KERNEL_INLINE void hc_kernel_accumulate(size_t m, size_t k_inner, size_t K, const double* inner, const double* last,
                                           const size_t* offsets, const double* data, double* out, size_t out_stride) {
#ifdef HC_KERNEL_PAIRS
  if (m == 2 || m == 4 || m == 6) {
    const size_t pairs = m / 2;
    const hc_kernel_pair zero = {0.0, 0.0};
    hc_kernel_pair part[4][3] = {{zero, zero, zero}, {zero, zero, zero}, {zero, zero, zero}, {zero, zero, zero}};
    for (size_t t = 0; t < k_inner; ++t) {
      const hc_kernel_pair w = {inner[t], inner[t]};
      for (size_t e = 0; e < K; ++e) {
        const double* row = data + offsets[e * k_inner + t];
        for (size_t h = 0; h < pairs; ++h) {
          hc_kernel_pair value;
          __builtin_memcpy(&value, row + 2 * h, sizeof value);
          part[e][h] += w * value;
        }
      }
    }
    hc_kernel_pair total[3] = {zero, zero, zero};
    for (size_t e = 0; e < K; ++e) {
      const hc_kernel_pair weight = {last[e], last[e]};
      for (size_t h = 0; h < pairs; ++h) total[h] += weight * part[e][h];
    }
    for (size_t h = 0; h < pairs; ++h) {
      out[2 * h * out_stride] = total[h][0];
      out[(2 * h + 1) * out_stride] = total[h][1];
    }
    return;
  }
#endif
  if (m == 1) {
    double part1[4] = {0.0, 0.0, 0.0, 0.0};
    for (size_t t = 0; t < k_inner; ++t) {
      const double w = inner[t];
      for (size_t e = 0; e < K; ++e) part1[e] += w * data[offsets[e * k_inner + t]];
    }
    double total1 = 0.0;
    for (size_t e = 0; e < K; ++e) total1 += last[e] * part1[e];
    out[0] = total1;
    return;
  }
  double part[4][6] = {{0.0}, {0.0}, {0.0}, {0.0}};
  for (size_t t = 0; t < k_inner; ++t) {
    const double w = inner[t];
    for (size_t e = 0; e < K; ++e) {
      const double* row = data + offsets[e * k_inner + t];
      for (size_t j = 0; j < m; ++j) part[e][j] += w * row[j];
    }
  }
  double total[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (size_t e = 0; e < K; ++e) {
    for (size_t j = 0; j < m; ++j) total[j] += last[e] * part[e][j];
  }
  for (size_t j = 0; j < m; ++j) out[j * out_stride] = total[j];
}

/* The local sum over `count` outputs, six at a time, then four, two, one:
 * out[k * out_stride] = sum over the K^n terms of the product of per-axis
 * weights times data[offsets[t] + k]. inner: scratch of K^(n-1) doubles. */
HC_KERNEL_INLINE void hc_kernel_sum(size_t n, size_t K, const double* axis_weights, size_t replaced,
                                    const double* replacement, const size_t* offsets, const double* data, size_t count,
                                    double* out, size_t out_stride, double* inner) {
  const size_t k_inner = hc_kernel_power(K, n - 1);
  hc_kernel_inner_weights(n, K, axis_weights, replaced, replacement, inner);
  const double* last = n - 1 == replaced ? replacement : axis_weights + 4 * (n - 1);
  size_t k = 0;
  for (; k + 6 <= count; k += 6)
    hc_kernel_accumulate(6, k_inner, K, inner, last, offsets, data + k, out + k * out_stride, out_stride);
  if (count - k >= 4) {
    hc_kernel_accumulate(4, k_inner, K, inner, last, offsets, data + k, out + k * out_stride, out_stride);
    k += 4;
  }
  if (count - k >= 2) {
    hc_kernel_accumulate(2, k_inner, K, inner, last, offsets, data + k, out + k * out_stride, out_stride);
    k += 2;
  }
  if (k < count) hc_kernel_accumulate(1, k_inner, K, inner, last, offsets, data + k, out + k * out_stride, out_stride);
}

#ifdef __cplusplus
}
#endif

#endif
