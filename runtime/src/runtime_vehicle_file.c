/* Reading a runtime file's vehicle section (docs/runtime.md, "Vehicle
 * section"): every count, code, index and number checked before use, every
 * surface index against the file's surfaces. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "runtime_reader.h"

enum { MATRIX_NUMBERS = 36, THRUSTER_NUMBERS = 8 };

static const char* const kDofNames[6] = {"X", "Y", "Z", "K", "M", "N"};
static const char* const kVelocityNames[6] = {"u", "v", "w", "p", "q", "r"};

void hc_free_vehicle(hc_runtime_vehicle* vehicle) {
  if (vehicle == NULL) return;
  for (size_t dof = 0; dof < 6; ++dof) {
    free(vehicle->dofs[dof].begin);
    free(vehicle->dofs[dof].factors);
  }
  free(vehicle->metadata);
  free((void*)vehicle->disturbance_names);
  free((void*)vehicle->thruster_names);
  free(vehicle->thrusters);
  free(vehicle);
}

/* 36 numbers row by row at the cursor into `column` column by column. */
static int read_matrix(reader* r, const char* what, double* column) {
  const size_t at = r->pos;
  const double* row = NULL;
  int status = hc_read_doubles(r, what, MATRIX_NUMBERS, &row);
  if (status == HC_RUNTIME_OK) status = hc_check_finite(r, what, row, MATRIX_NUMBERS, at);
  if (status != HC_RUNTIME_OK) return status;
  for (size_t i = 0; i < 6; ++i)
    for (size_t j = 0; j < 6; ++j) column[i + 6 * j] = row[6 * i + j];
  return HC_RUNTIME_OK;
}

/* count u32 at the cursor, then a zero u32 when count is odd (to 8 bytes). */
static int read_words(reader* r, const char* what, size_t count, uint32_t* words) {
  for (size_t i = 0; i < count; ++i) {
    const int status = hc_read_u32(r, what, &words[i]);
    if (status != HC_RUNTIME_OK) return status;
  }
  return count % 2 == 1 ? hc_read_reserved(r, "the padding word after a list of codes") : HC_RUNTIME_OK;
}

static int check_source(reader* r, size_t at, const char* dof, uint32_t source, size_t disturbances) {
  if ((size_t)source >= 6 + disturbances)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at,
                      "damping of %s: source %u; expected 0 to 5 (u, v, w, p, q, r) or 6 + a disturbance index "
                      "(%zu disturbances)",
                      dof, (unsigned)source, disturbances);
  return HC_RUNTIME_OK;
}

static int read_law(reader* r, hc_runtime_dof* d, const char* dof, uint32_t count, uint32_t variable,
                    size_t record_at) {
  if (count < 1 || count > 6)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, record_at + 4, "damping of %s: a law of %u terms; expected 1 to 6", dof,
                      (unsigned)count);
  if (variable > 5)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, record_at + 8,
                      "damping of %s: law variable %u; expected 0 to 5 (u, v, w, p, q, r)", dof, (unsigned)variable);
  uint32_t codes[6];
  const size_t codes_at = r->pos;
  int status = read_words(r, "a law's term codes", count, codes);
  if (status != HC_RUNTIME_OK) return status;
  for (size_t k = 0; k < count; ++k) {
    if (codes[k] >= HC_DAMPING_TERM_CODES)
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, codes_at + 4 * k,
                        "damping of %s: term code %u; expected 0 (1), 1 (x), 2 (x|x|), 3 (x^2), 4 (x^3) or 5 (|x|)",
                        dof, (unsigned)codes[k]);
    d->codes[k] = (int)codes[k];
  }
  const size_t at = r->pos;
  status = hc_read_doubles(r, "a law's coefficients", count, &d->coefficients);
  if (status == HC_RUNTIME_OK) status = hc_check_finite(r, "a law's coefficient", d->coefficients, count, at);
  d->kind = HC_DOF_LAW;
  d->count = count;
  d->variable = variable;
  return status;
}

static int read_derivatives(reader* r, hc_runtime_dof* d, const char* dof, uint32_t terms, uint32_t factor_count,
                            size_t disturbances, size_t record_at) {
  if (terms < 1 || terms > HC_VEHICLE_MAX_TERMS)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, record_at + 4, "damping of %s: %u derivative terms; expected 1 to %d",
                      dof, (unsigned)terms, HC_VEHICLE_MAX_TERMS);
  if (factor_count > (uint32_t)terms * HC_VEHICLE_MAX_FACTORS)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, record_at + 8, "damping of %s: %u factors; expected at most %u", dof,
                      (unsigned)factor_count, (unsigned)terms * HC_VEHICLE_MAX_FACTORS);
  d->kind = HC_DOF_DERIVATIVES;
  d->count = terms;
  d->begin = (size_t*)calloc((size_t)terms + 1, sizeof(size_t));
  d->factors = (hc_damping_factor*)calloc(factor_count > 0 ? factor_count : 1, sizeof(hc_damping_factor));
  if (d->begin == NULL || d->factors == NULL)
    return hc_fail_at(r, HC_RUNTIME_E_MEMORY, record_at, "out of memory for %u terms", (unsigned)terms);
  uint32_t per_term[HC_VEHICLE_MAX_TERMS];
  const size_t counts_at = r->pos;
  int status = read_words(r, "a term's factor count", terms, per_term);
  if (status != HC_RUNTIME_OK) return status;
  size_t total = 0;
  for (size_t k = 0; k < terms; ++k) {
    if (per_term[k] > HC_VEHICLE_MAX_FACTORS)
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, counts_at + 4 * k,
                        "damping of %s: term %zu has %u factors; expected at most %d", dof, k, (unsigned)per_term[k],
                        HC_VEHICLE_MAX_FACTORS);
    d->begin[k] = total;
    total += per_term[k];
  }
  d->begin[terms] = total;
  if (total != factor_count)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, record_at + 8,
                      "damping of %s: %u factors; the terms' factor counts add up to %zu", dof, (unsigned)factor_count,
                      total);
  for (size_t i = 0; i < total; ++i) {
    const size_t at = r->pos;
    uint32_t source = 0, power = 0, odd = 0;
    status = hc_read_u32(r, "a factor's source", &source);
    if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "a factor's power", &power);
    if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "a factor's odd flag", &odd);
    if (status == HC_RUNTIME_OK) status = hc_read_reserved(r, "the reserved word after a factor");
    if (status == HC_RUNTIME_OK) status = check_source(r, at, dof, source, disturbances);
    if (status != HC_RUNTIME_OK) return status;
    if (power < 1 || power > 4)
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at + 4, "damping of %s: factor power %u; expected 1 to 4", dof,
                        (unsigned)power);
    if (odd > 1)
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at + 8, "damping of %s: factor odd flag %u; expected 0 or 1", dof,
                        (unsigned)odd);
    d->factors[i].source = source;
    d->factors[i].power = (int)power;
    d->factors[i].odd = (int)odd;
  }
  const size_t at = r->pos;
  status = hc_read_doubles(r, "a derivative model's coefficients", terms, &d->coefficients);
  if (status == HC_RUNTIME_OK)
    status = hc_check_finite(r, "a derivative model's coefficient", d->coefficients, terms, at);
  return status;
}

static int read_surface_binding(reader* r, const hc_runtime_model* model, hc_runtime_dof* d, const char* dof,
                                uint32_t surface, uint32_t output, uint32_t axes, size_t disturbances,
                                size_t record_at) {
  if ((size_t)surface >= model->surface_count)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, record_at + 4,
                      "damping of %s: surface index %u; the file has %zu surfaces", dof, (unsigned)surface,
                      model->surface_count);
  const hc_runtime_surface* s = &model->surfaces[surface];
  if (s->output_count > HC_VEHICLE_MAX_OUTPUTS)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, record_at + 4,
                      "damping of %s: surface '%s' has %zu outputs; a vehicle's damping reads surfaces of at most %d",
                      dof, s->name, s->output_count, HC_VEHICLE_MAX_OUTPUTS);
  if ((size_t)output >= s->output_count)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, record_at + 8, "damping of %s: output %u of surface '%s', which has %zu",
                      dof, (unsigned)output, s->name, s->output_count);
  if ((size_t)axes != s->axis_count)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, record_at + 12,
                      "damping of %s: %u axis sources for surface '%s'; expected %zu (one per axis)", dof,
                      (unsigned)axes, s->name, s->axis_count);
  const size_t sign_at = r->pos;
  const double* sign = NULL;
  int status = hc_read_doubles(r, "a surface's sign", 1, &sign);
  if (status != HC_RUNTIME_OK) return status;
  if (!(*sign == 1.0 || *sign == -1.0))
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, sign_at, "damping of %s: sign %.17g; expected 1 or -1", dof, *sign);
  uint32_t sources[HC_KERNEL_MAX_AXES];
  const size_t sources_at = r->pos;
  status = read_words(r, "an axis source", axes, sources);
  if (status != HC_RUNTIME_OK) return status;
  for (size_t a = 0; a < axes; ++a) {
    status = check_source(r, sources_at + 4 * a, dof, sources[a], disturbances);
    if (status != HC_RUNTIME_OK) return status;
    d->sources[a] = sources[a];
  }
  d->kind = HC_DOF_SURFACE;
  d->surface = surface;
  d->output = output;
  d->axis_count = axes;
  d->sign = *sign;
  return HC_RUNTIME_OK;
}

/* The surface DOFs grouped by (surface, sources): one evaluation each. */
static void group_lookups(hc_runtime_vehicle* v) {
  for (size_t dof = 0; dof < 6; ++dof) {
    const hc_runtime_dof* d = &v->dofs[dof];
    if (d->kind != HC_DOF_SURFACE) continue;
    hc_runtime_lookup* l = NULL;
    for (size_t i = 0; i < v->lookup_count && l == NULL; ++i) {
      hc_runtime_lookup* c = &v->lookups[i];
      if (c->surface == d->surface && memcmp(c->sources, d->sources, d->axis_count * sizeof(size_t)) == 0) l = c;
    }
    if (l == NULL) {
      l = &v->lookups[v->lookup_count++];
      l->surface = d->surface;
      l->axis_count = d->axis_count;
      memcpy(l->sources, d->sources, sizeof l->sources);
    }
    l->dof[l->used] = dof;
    l->output[l->used] = d->output;
    l->sign[l->used] = d->sign;
    ++l->used;
  }
}

int hc_read_vehicle(reader* r, hc_runtime_model* model) {
  hc_runtime_vehicle* v = (hc_runtime_vehicle*)calloc(1, sizeof(hc_runtime_vehicle));
  if (v == NULL) return hc_fail_at(r, HC_RUNTIME_E_MEMORY, r->pos, "out of memory for the vehicle");
  model->vehicle = v; /* freed by hc_runtime_close, also when reading fails */
  int status = hc_read_pairs(r, "vehicle metadata", &v->metadata, &v->metadata_count);
  const size_t counts_at = r->pos;
  uint32_t disturbances = 0, thrusters = 0;
  if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "the disturbance count", &disturbances);
  if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "the thruster count", &thrusters);
  if (status != HC_RUNTIME_OK) return status;
  if (disturbances > HC_VEHICLE_MAX_DISTURBANCES || disturbances > (r->end - r->pos) / 8)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, counts_at, "%u disturbances; expected at most %d that fit in the section",
                      (unsigned)disturbances, HC_VEHICLE_MAX_DISTURBANCES);
  if (thrusters > HC_VEHICLE_MAX_THRUSTERS || thrusters > (r->end - r->pos) / 72)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, counts_at + 4,
                      "%u thrusters; expected at most %d that fit in the section", (unsigned)thrusters,
                      HC_VEHICLE_MAX_THRUSTERS);
  status = read_matrix(r, "M_RB", v->m_rb);
  if (status == HC_RUNTIME_OK) status = read_matrix(r, "M_A", v->m_a);
  const size_t m_at = r->pos;
  if (status == HC_RUNTIME_OK) status = read_matrix(r, "M", v->m);
  if (status == HC_RUNTIME_OK) status = read_matrix(r, "M^-1", v->m_inv);
  if (status != HC_RUNTIME_OK) return status;
  for (size_t i = 0; i < MATRIX_NUMBERS; ++i) {
    if (v->m[i] != v->m_rb[i] + v->m_a[i])
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, m_at + 8 * (6 * (i % 6) + i / 6),
                        "M (%zu, %zu) is %.17g; expected M_RB + M_A = %.17g", i % 6, i / 6, v->m[i],
                        v->m_rb[i] + v->m_a[i]);
  }
  const size_t scalars_at = r->pos;
  const double* scalars = NULL;
  status = hc_read_doubles(r, "the weight, buoyancy, CG, CB and norm gain", 9, &scalars);
  if (status == HC_RUNTIME_OK)
    status = hc_check_finite(r, "the weight, buoyancy, CG, CB and norm gain", scalars, 9, scalars_at);
  if (status != HC_RUNTIME_OK) return status;
  v->weight_N = scalars[0];
  v->buoyancy_N = scalars[1];
  for (size_t i = 0; i < 3; ++i) {
    v->r_g[i] = scalars[2 + i];
    v->r_b[i] = scalars[5 + i];
  }
  v->gain = scalars[8];

  v->disturbance_count = disturbances;
  v->disturbance_names = (const char**)calloc(disturbances > 0 ? disturbances : 1, sizeof(const char*));
  v->thruster_count = thrusters;
  v->thruster_names = (const char**)calloc(thrusters > 0 ? thrusters : 1, sizeof(const char*));
  v->thrusters = (double*)calloc(thrusters > 0 ? (size_t)thrusters * THRUSTER_NUMBERS : 1, sizeof(double));
  if (v->disturbance_names == NULL || v->thruster_names == NULL || v->thrusters == NULL)
    return hc_fail_at(r, HC_RUNTIME_E_MEMORY, counts_at, "out of memory for the disturbances and thrusters");
  for (size_t i = 0; i < disturbances; ++i) {
    const size_t at = r->pos;
    status = hc_read_text(r, "a disturbance name", &v->disturbance_names[i]);
    if (status != HC_RUNTIME_OK) return status;
    const char* name = v->disturbance_names[i];
    if (name[0] == '\0') return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at, "disturbance %zu's name is empty", i);
    for (size_t c = 0; c < 6; ++c)
      if (strcmp(name, kVelocityNames[c]) == 0)
        return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at,
                          "disturbance %zu is named '%s', a velocity component; expected another name", i, name);
    /* Sorted and unique, as the library orders them. */
    if (i > 0 && !(strcmp(v->disturbance_names[i - 1], name) < 0))
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at,
                        "disturbance '%s' after '%s'; expected unique names in increasing byte order", name,
                        v->disturbance_names[i - 1]);
  }
  for (size_t i = 0; i < thrusters; ++i) {
    status = hc_read_text(r, "a thruster name", &v->thruster_names[i]);
    if (status != HC_RUNTIME_OK) return status;
    const size_t at = r->pos;
    const double* numbers = NULL;
    status = hc_read_doubles(r, "a thruster's numbers", THRUSTER_NUMBERS, &numbers);
    if (status == HC_RUNTIME_OK) status = hc_check_finite(r, "a thruster's", numbers, THRUSTER_NUMBERS, at);
    if (status != HC_RUNTIME_OK) return status;
    memcpy(v->thrusters + THRUSTER_NUMBERS * i, numbers, THRUSTER_NUMBERS * sizeof(double));
    if (!(numbers[6] <= numbers[7]))
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at + 48, "thruster '%s': min thrust %.17g above max %.17g",
                        v->thruster_names[i], numbers[6], numbers[7]);
  }

  for (size_t dof = 0; dof < 6; ++dof) {
    const size_t at = r->pos;
    uint32_t kind = 0, a = 0, b = 0, c = 0;
    status = hc_read_u32(r, "a DOF's damping kind", &kind);
    if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "a DOF's first count", &a);
    if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "a DOF's second count", &b);
    if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "a DOF's third count", &c);
    if (status != HC_RUNTIME_OK) return status;
    hc_runtime_dof* d = &v->dofs[dof];
    switch (kind) {
      case HC_DOF_NONE:
        if (a != 0 || b != 0 || c != 0)
          return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at + 4, "damping of %s: none, with non-zero counts; expected 0",
                            kDofNames[dof]);
        break;
      case HC_DOF_LAW:
        if (c != 0)
          return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at + 12, "damping of %s: reserved word %u; expected 0",
                            kDofNames[dof], (unsigned)c);
        status = read_law(r, d, kDofNames[dof], a, b, at);
        break;
      case HC_DOF_DERIVATIVES:
        if (c != 0)
          return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at + 12, "damping of %s: reserved word %u; expected 0",
                            kDofNames[dof], (unsigned)c);
        status = read_derivatives(r, d, kDofNames[dof], a, b, disturbances, at);
        break;
      case HC_DOF_SURFACE: status = read_surface_binding(r, model, d, kDofNames[dof], a, b, c, disturbances, at); break;
      default:
        return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at,
                          "damping of %s: kind %u; expected 0 (none), 1 (law), 2 (derivatives) or 3 (surface)",
                          kDofNames[dof], (unsigned)kind);
    }
    if (status != HC_RUNTIME_OK) return status;
  }
  if (r->pos != r->end)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos, "%zu bytes after the vehicle's last DOF; expected none",
                      r->end - r->pos);
  group_lookups(v);
  return HC_RUNTIME_OK;
}
