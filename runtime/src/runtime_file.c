/* Opening a runtime file: every byte is checked before use (docs/runtime.md
 * has the format). The model keeps the file's bytes; its doubles and texts
 * point into them, so opening copies the file once and allocates a few
 * small index arrays. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime_internal.h"
#include "runtime_reader.h"
#include "xxh64.h"

enum {
  HEADER_SIZE = 64,
  SECTION_ENTRY_SIZE = 24,
  SECTION_MODEL = 1,
  SECTION_SURFACE = 2,
  SECTION_VEHICLE = 3,
  SURFACE_FLAG_SIGMA = 1
};

static const unsigned char kMagic[8] = {0x89, 'H', 'C', 'R', 'T', '\r', '\n', 0x1a};

int hc_fail_at(reader* r, int status, size_t offset, const char* format, ...) {
  if (r->err == NULL || r->errlen == 0) return status;
  int used = snprintf(r->err, r->errlen, "runtime file, %s, byte %zu: ", r->section, offset);
  if (used < 0) used = 0;
  if ((size_t)used < r->errlen) {
    va_list args;
    va_start(args, format);
    vsnprintf(r->err + used, r->errlen - (size_t)used, format, args);
    va_end(args);
  }
  return status;
}

static int host_is_little_endian(void) {
  const uint16_t one = 1;
  unsigned char first;
  memcpy(&first, &one, 1);
  return first == 1;
}

uint32_t hc_get_u32(const unsigned char* p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

uint64_t hc_get_u64(const unsigned char* p) { return (uint64_t)hc_get_u32(p) | (uint64_t)hc_get_u32(p + 4) << 32; }

int hc_read_u32(reader* r, const char* what, uint32_t* value) {
  if (r->end - r->pos < 4)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos, "%s: the section ends; expected 4 bytes", what);
  *value = hc_get_u32(r->base + r->pos);
  r->pos += 4;
  return HC_RUNTIME_OK;
}

int hc_read_u64(reader* r, const char* what, uint64_t* value) {
  if (r->end - r->pos < 8)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos, "%s: the section ends; expected 8 bytes", what);
  *value = hc_get_u64(r->base + r->pos);
  r->pos += 8;
  return HC_RUNTIME_OK;
}

int hc_read_reserved(reader* r, const char* what) {
  uint32_t reserved = 0;
  const size_t at = r->pos;
  int status = hc_read_u32(r, what, &reserved);
  if (status != HC_RUNTIME_OK) return status;
  if (reserved != 0) return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at, "%s is %u; expected 0", what, (unsigned)reserved);
  return HC_RUNTIME_OK;
}

/* A text: u32 length, its bytes (no NUL among them), then 1 to 8 zero bytes
 * up to the next multiple of 8 from the section's start. *text points at the
 * bytes, NUL-terminated by the padding. */
int hc_read_text(reader* r, const char* what, const char** text) {
  const size_t at = r->pos;
  uint32_t length = 0;
  int status = hc_read_u32(r, what, &length);
  if (status != HC_RUNTIME_OK) return status;
  const size_t available = r->end - r->pos;
  if (length >= available)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at, "%s has length %u; expected at most %zu (the rest of the section)",
                      what, (unsigned)length, available == 0 ? (size_t)0 : available - 1);
  const unsigned char* bytes = r->base + r->pos;
  if (memchr(bytes, 0, length) != NULL)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at, "%s holds a NUL byte; expected text", what);
  const size_t padded = (4 + (size_t)length + 1 + 7) / 8 * 8 - 4; /* bytes after the length */
  if (padded > available)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at, "%s's padding runs past the section's end", what);
  for (size_t i = length; i < padded; ++i) {
    if (bytes[i] != 0)
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos + i, "%s's padding byte is %u; expected 0", what,
                        (unsigned)bytes[i]);
  }
  *text = (const char*)bytes;
  r->pos += padded;
  return HC_RUNTIME_OK;
}

/* count doubles at the cursor (8-byte aligned: every field before them is),
 * swapped in place on a big-endian host. */
int hc_read_doubles(reader* r, const char* what, uint64_t count, const double** values) {
  const size_t available = (r->end - r->pos) / 8;
  if (count > available)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos, "%s: %llu numbers; only %zu fit in the rest of the section", what,
                      (unsigned long long)count, available);
  unsigned char* bytes = r->base + r->pos;
  if (!host_is_little_endian()) {
    for (size_t i = 0; i < (size_t)count; ++i) {
      unsigned char* p = bytes + 8 * i;
      for (size_t j = 0; j < 4; ++j) {
        const unsigned char swap = p[j];
        p[j] = p[7 - j];
        p[7 - j] = swap;
      }
    }
  }
  *values = (const double*)(void*)bytes;
  r->pos += (size_t)count * 8;
  return HC_RUNTIME_OK;
}

int hc_check_finite(reader* r, const char* what, const double* values, size_t count, size_t first_byte) {
  for (size_t i = 0; i < count; ++i) {
    if (!isfinite(values[i]))
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, first_byte + 8 * i,
                        "%s number %zu is not finite; expected a finite number", what, i);
  }
  return HC_RUNTIME_OK;
}

/* u32 count, u32 0, then count (key, value) texts. */
int hc_read_pairs(reader* r, const char* what, hc_text_pair** pairs, size_t* count) {
  const size_t at = r->pos;
  uint32_t n = 0;
  int status = hc_read_u32(r, what, &n);
  if (status == HC_RUNTIME_OK) status = hc_read_reserved(r, "the reserved word after the metadata count");
  if (status != HC_RUNTIME_OK) return status;
  if ((size_t)n > (r->end - r->pos) / 16)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at, "%s count %u does not fit in the rest of the section", what,
                      (unsigned)n);
  *pairs = NULL;
  *count = 0;
  if (n == 0) return HC_RUNTIME_OK;
  *pairs = (hc_text_pair*)calloc(n, sizeof(hc_text_pair));
  if (*pairs == NULL)
    return hc_fail_at(r, HC_RUNTIME_E_MEMORY, at, "out of memory for %u metadata entries", (unsigned)n);
  *count = n;
  for (size_t i = 0; i < n; ++i) {
    status = hc_read_text(r, "a metadata key", &(*pairs)[i].key);
    if (status == HC_RUNTIME_OK) status = hc_read_text(r, "a metadata value", &(*pairs)[i].value);
    if (status != HC_RUNTIME_OK) return status;
  }
  return HC_RUNTIME_OK;
}

static int read_surface(reader* r, hc_runtime_surface* s) {
  const size_t start = r->pos;
  uint32_t axes = 0, outputs = 0, method = 0, flags = 0;
  uint64_t nodes = 0, block = 0;
  int status = hc_read_u32(r, "the axis count", &axes);
  if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "the output count", &outputs);
  if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "the method code", &method);
  if (status == HC_RUNTIME_OK) status = hc_read_u32(r, "the flags", &flags);
  if (status == HC_RUNTIME_OK) status = hc_read_u64(r, "the node count", &nodes);
  if (status == HC_RUNTIME_OK) status = hc_read_u64(r, "the numbers per node", &block);
  if (status != HC_RUNTIME_OK) return status;
  if (axes < 1 || axes > HC_RUNTIME_MAX_AXES)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, start, "axis count %u; expected 1 to %d", (unsigned)axes,
                      HC_RUNTIME_MAX_AXES);
  if (outputs < 1 || outputs > HC_RUNTIME_MAX_OUTPUTS)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, start + 4, "output count %u; expected 1 to %d", (unsigned)outputs,
                      HC_RUNTIME_MAX_OUTPUTS);
  if (method > HC_KERNEL_NATURAL_SPLINE)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, start + 8,
                      "method code %u; expected 0 (nearest), 1 (linear), 2 (pchip), 3 (makima) or 4 (natural-spline)",
                      (unsigned)method);
  if ((flags & ~(uint32_t)SURFACE_FLAG_SIGMA) != 0)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, start + 12, "flags 0x%x; expected 0 or 1 (sigma)", (unsigned)flags);
  s->axis_count = axes;
  s->output_count = outputs;
  s->method = (int)method;
  s->has_sigma = (flags & SURFACE_FLAG_SIGMA) != 0;
  s->terms_per_axis = hc_kernel_terms_per_axis(s->method);
  const int cubic = s->terms_per_axis == 4;
  const size_t expected_block = (cubic ? (size_t)1 << axes : 1u) * outputs;
  if (block != expected_block)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, start + 24, "%llu numbers per node; expected %zu for %u axes, %u outputs",
                      (unsigned long long)block, expected_block, (unsigned)axes, (unsigned)outputs);
  s->node_block = expected_block;

  status = hc_read_text(r, "the surface name", &s->name);
  if (status != HC_RUNTIME_OK) return status;
  if (s->name[0] == '\0')
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos, "the surface name is empty; expected a name");
  status = hc_read_pairs(r, "surface metadata", &s->metadata, &s->metadata_count);
  if (status != HC_RUNTIME_OK) return status;

  /* Axes: the breakpoints of every axis are read in place; they are
   * contiguous only per axis, so each axis's offset is from s->breakpoints,
   * the first axis's, in doubles. */
  size_t product = 1;
  const double* axis_points[HC_KERNEL_MAX_AXES] = {NULL};
  for (size_t a = 0; a < axes; ++a) {
    hc_runtime_axis_info* info = &s->axis_info[a];
    status = hc_read_text(r, "an axis name", &info->name);
    if (status == HC_RUNTIME_OK) status = hc_read_text(r, "an axis unit", &info->unit);
    if (status != HC_RUNTIME_OK) return status;
    if (info->name[0] == '\0') return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos, "axis %zu's name is empty", a);
    for (size_t b = 0; b < a; ++b) {
      if (strcmp(s->axis_info[b].name, info->name) == 0)
        return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos, "axes %zu and %zu are both named '%s'; expected unique names",
                          b, a, info->name);
    }
    const size_t policy_at = r->pos;
    uint32_t policy = 0;
    uint64_t count = 0;
    status = hc_read_u32(r, "an extrapolation code", &policy);
    if (status == HC_RUNTIME_OK) status = hc_read_reserved(r, "the reserved word after an extrapolation code");
    if (status == HC_RUNTIME_OK) status = hc_read_u64(r, "a breakpoint count", &count);
    if (status != HC_RUNTIME_OK) return status;
    if (policy > HC_KERNEL_METHOD)
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, policy_at,
                        "axis '%s': extrapolation code %u; expected 0 (error), 1 (clamp), 2 (linear) or 3 (method)",
                        info->name, (unsigned)policy);
    const uint64_t least = cubic ? 3 : 2;
    if (count < least)
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, policy_at + 8, "axis '%s' has %llu breakpoints; expected at least %llu",
                        info->name, (unsigned long long)count, (unsigned long long)least);
    const size_t points_at = r->pos;
    status = hc_read_doubles(r, "breakpoints", count, &axis_points[a]);
    if (status != HC_RUNTIME_OK) return status;
    const double* x = axis_points[a];
    for (size_t i = 0; i < (size_t)count; ++i) {
      if (!isfinite(x[i]))
        return hc_fail_at(r, HC_RUNTIME_E_FORMAT, points_at + 8 * i,
                          "axis '%s' breakpoint %zu is not finite; expected a finite number", info->name, i);
      if (i > 0 && !(x[i] > x[i - 1]))
        return hc_fail_at(r, HC_RUNTIME_E_FORMAT, points_at + 8 * i,
                          "axis '%s' breakpoint %zu (%.17g) is not greater than breakpoint %zu (%.17g); expected "
                          "strictly increasing breakpoints",
                          info->name, i, x[i], i - 1, x[i - 1]);
    }
    hc_kernel_axis* axis = &s->axes[a];
    hc_kernel_axis_setup(x, (size_t)count, axis);
    axis->extrapolation = (int)policy;
    axis->node_stride = product;
    /* count fits in the section, so the product only overflows past SIZE_MAX / count. */
    if (product > SIZE_MAX / (size_t)count)
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, policy_at + 8, "the grid's node count overflows; expected fewer nodes");
    product *= (size_t)count;
  }
  if (nodes != product)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, start + 16,
                      "node count %llu; expected %zu (the product of the axes' "
                      "breakpoint counts)",
                      (unsigned long long)nodes, product);
  s->node_count = product;

  s->output_names = (const char**)calloc(outputs, sizeof(const char*));
  s->output_units = (const char**)calloc(outputs, sizeof(const char*));
  if (s->output_names == NULL || s->output_units == NULL)
    return hc_fail_at(r, HC_RUNTIME_E_MEMORY, r->pos, "out of memory for %u outputs", (unsigned)outputs);
  for (size_t k = 0; k < outputs; ++k) {
    status = hc_read_text(r, "an output name", &s->output_names[k]);
    if (status == HC_RUNTIME_OK) status = hc_read_text(r, "an output unit", &s->output_units[k]);
    if (status != HC_RUNTIME_OK) return status;
    if (s->output_names[k][0] == '\0')
      return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos, "output %zu's name is empty", k);
    for (size_t j = 0; j < k; ++j) {
      if (strcmp(s->output_names[j], s->output_names[k]) == 0)
        return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos,
                          "outputs %zu and %zu are both named '%s'; expected unique names", j, k, s->output_names[k]);
    }
  }

  /* Data: node_count * node_block numbers, the product checked against the
   * section's size by division first. */
  if (s->node_count > (r->end - r->pos) / 8 / s->node_block)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos,
                      "the table of %zu nodes x %zu numbers does not fit in the rest of the section (%zu bytes)",
                      s->node_count, s->node_block, r->end - r->pos);
  const size_t numbers = s->node_count * s->node_block;
  size_t at = r->pos;
  status = hc_read_doubles(r, "the table", numbers, &s->data);
  if (status == HC_RUNTIME_OK) status = hc_check_finite(r, "the table's", s->data, numbers, at);
  if (status != HC_RUNTIME_OK) return status;
  if (s->has_sigma) {
    at = r->pos;
    status = hc_read_doubles(r, "the leave-one-out standard deviations", outputs, &s->loo);
    if (status != HC_RUNTIME_OK) return status;
    for (size_t k = 0; k < outputs; ++k) {
      if (!isfinite(s->loo[k]) || s->loo[k] < 0.0)
        return hc_fail_at(r, HC_RUNTIME_E_FORMAT, at + 8 * k,
                          "output '%s' leave-one-out standard deviation %.17g; expected a finite number >= 0",
                          s->output_names[k], s->loo[k]);
    }
    at = r->pos;
    status = hc_read_doubles(r, "the runs' sigma table", numbers, &s->sigma_data);
    if (status == HC_RUNTIME_OK) status = hc_check_finite(r, "the runs' sigma table's", s->sigma_data, numbers, at);
    if (status != HC_RUNTIME_OK) return status;
  }
  if (r->pos != r->end)
    return hc_fail_at(r, HC_RUNTIME_E_FORMAT, r->pos, "%zu bytes after the surface's last table; expected none",
                      r->end - r->pos);

  /* Breakpoint offsets relative to the first axis's array (pointers into one file). */
  s->breakpoints = axis_points[0];
  for (size_t a = 0; a < axes; ++a) {
    s->axes[a].offset = (size_t)(axis_points[a] - axis_points[0]);
    s->sigma_axes[a] = s->axes[a];
    s->sigma_axes[a].extrapolation = HC_KERNEL_CLAMP;
  }
  const size_t terms = hc_kernel_power(s->terms_per_axis, axes);
  s->term_offsets = (size_t*)calloc(terms, sizeof(size_t));
  if (s->term_offsets == NULL) return hc_fail_at(r, HC_RUNTIME_E_MEMORY, start, "out of memory for %zu terms", terms);
  size_t strides[HC_KERNEL_MAX_AXES];
  for (size_t a = 0; a < axes; ++a) strides[a] = s->axes[a].node_stride;
  hc_kernel_term_offsets(axes, s->method, outputs, s->node_block, strides, s->term_offsets);
  return HC_RUNTIME_OK;
}

void hc_runtime_close(hc_runtime_model* model) {
  if (model == NULL) return;
  for (size_t i = 0; i < model->surface_count; ++i) {
    hc_runtime_surface* s = &model->surfaces[i];
    free(s->metadata);
    free((void*)s->output_names);
    free((void*)s->output_units);
    free(s->term_offsets);
  }
  free(model->surfaces);
  hc_free_vehicle(model->vehicle);
  free(model->metadata);
  free(model->bytes);
  free(model);
}

/* Parses the model's bytes (owned by it). */
static int parse(hc_runtime_model* model, char* err, size_t errlen) {
  reader r;
  memset(&r, 0, sizeof r);
  r.base = model->bytes;
  r.end = model->size;
  r.section = "header";
  r.err = err;
  r.errlen = errlen;
  if (model->size < HEADER_SIZE)
    return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, 0, "the file has %zu bytes; a runtime file has at least %d", model->size,
                      HEADER_SIZE);
  const unsigned char* h = model->bytes;
  if (memcmp(h, kMagic, sizeof kMagic) != 0)
    return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, 0,
                      "not a hydrocoef runtime file (its first 8 bytes are not the magic "
                      "number 89 48 43 52 54 0d 0a 1a)");
  /* Version 1: the model and surfaces; version 2: and a vehicle, the last section. */
  const uint32_t version = hc_get_u32(h + 8);
  if (version < 1 || version > HC_RUNTIME_FILE_VERSION)
    return hc_fail_at(&r, HC_RUNTIME_E_VERSION, 8, "format version %u; this library reads versions 1 to %d",
                      (unsigned)version, HC_RUNTIME_FILE_VERSION);
  const int has_vehicle = version == 2;
  if (hc_get_u32(h + 12) != HEADER_SIZE)
    return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, 12, "header size %u; expected %d", (unsigned)hc_get_u32(h + 12),
                      HEADER_SIZE);
  const uint64_t file_size = hc_get_u64(h + 16);
  if (file_size != (uint64_t)model->size)
    return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, 16,
                      "the header states %llu bytes; the file has %zu (truncated or "
                      "extended)",
                      (unsigned long long)file_size, model->size);
  const uint64_t stored_hash = hc_get_u64(h + 24);
  const uint32_t section_count = hc_get_u32(h + 32);
  const uint32_t flags = hc_get_u32(h + 36);
  const uint64_t table_offset = hc_get_u64(h + 40);
  if (flags != 0) return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, 36, "header flags 0x%x; expected 0", (unsigned)flags);
  for (size_t i = 48; i < HEADER_SIZE; ++i) {
    if (h[i] != 0)
      return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, i, "reserved header byte is %u; expected 0", (unsigned)h[i]);
  }
  const uint64_t hash = hc_xxh64(h + HEADER_SIZE, model->size - HEADER_SIZE, 0);
  if (hash != stored_hash)
    return hc_fail_at(&r, HC_RUNTIME_E_HASH, 24,
                      "content hash %016llx; the content hashes to %016llx (the file was "
                      "changed or damaged after it was written)",
                      (unsigned long long)stored_hash, (unsigned long long)hash);
  model->hash = hash;
  if (table_offset != HEADER_SIZE)
    return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, 40, "section table at byte %llu; expected %d (right after the header)",
                      (unsigned long long)table_offset, HEADER_SIZE);
  if (section_count < 1u + (unsigned)has_vehicle ||
      section_count > HC_RUNTIME_MAX_SURFACES + 1u + (unsigned)has_vehicle)
    return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, 32, "%u sections; expected %d to %d", (unsigned)section_count,
                      1 + has_vehicle, HC_RUNTIME_MAX_SURFACES + 1 + has_vehicle);
  if ((uint64_t)section_count > (model->size - HEADER_SIZE) / SECTION_ENTRY_SIZE)
    return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, 32, "%u sections do not fit in the file's %zu bytes",
                      (unsigned)section_count, model->size);
  const size_t sections_end = HEADER_SIZE + (size_t)section_count * SECTION_ENTRY_SIZE;
  model->surface_count = section_count - 1 - (size_t)has_vehicle;
  if (model->surface_count > 0) {
    model->surfaces = (hc_runtime_surface*)calloc(model->surface_count, sizeof(hc_runtime_surface));
    if (model->surfaces == NULL)
      return hc_fail_at(&r, HC_RUNTIME_E_MEMORY, 32, "out of memory for %zu surfaces", model->surface_count);
  }
  size_t previous_end = (sections_end + 7) / 8 * 8;
  r.section = "section table";
  for (size_t i = 0; i < section_count; ++i) {
    const size_t entry = HEADER_SIZE + i * SECTION_ENTRY_SIZE;
    const uint32_t kind = hc_get_u32(h + entry);
    const uint32_t reserved = hc_get_u32(h + entry + 4);
    const uint64_t offset = hc_get_u64(h + entry + 8);
    const uint64_t size = hc_get_u64(h + entry + 16);
    r.section = "section table";
    const int vehicle_section = has_vehicle && i + 1 == section_count;
    const uint32_t expected_kind = i == 0 ? SECTION_MODEL : vehicle_section ? SECTION_VEHICLE : SECTION_SURFACE;
    if (kind != expected_kind)
      return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, entry, "section %zu has kind %u; expected %u (%s)", i, (unsigned)kind,
                        (unsigned)expected_kind,
                        i == 0            ? "the model section comes first"
                        : vehicle_section ? "a version 2 file's vehicle section comes last"
                                          : "a surface");
    if (reserved != 0)
      return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, entry + 4, "section %zu's reserved word is %u; expected 0", i,
                        (unsigned)reserved);
    if (offset != previous_end || offset % 8 != 0)
      return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, entry + 8,
                        "section %zu starts at byte %llu; expected %zu (sections "
                        "follow one another, 8-byte aligned)",
                        i, (unsigned long long)offset, previous_end);
    if (size > (uint64_t)(model->size - (size_t)offset) || size % 8 != 0)
      return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, entry + 16,
                        "section %zu has %llu bytes from byte %llu; the file has "
                        "%zu bytes (and sections are multiples of 8 bytes)",
                        i, (unsigned long long)size, (unsigned long long)offset, model->size);
    r.pos = (size_t)offset;
    r.end = (size_t)(offset + size);
    previous_end = r.end;
    int status;
    if (i == 0) {
      r.section = "model section";
      status = hc_read_pairs(&r, "model metadata", &model->metadata, &model->metadata_count);
      if (status == HC_RUNTIME_OK && r.pos != r.end)
        status = hc_fail_at(&r, HC_RUNTIME_E_FORMAT, r.pos, "%zu bytes after the model's metadata; expected none",
                            r.end - r.pos);
    } else if (vehicle_section) {
      r.section = "vehicle section";
      status = hc_read_vehicle(&r, model);
    } else {
      snprintf(r.section_text, sizeof r.section_text, "surface section %zu", i);
      r.section = r.section_text;
      hc_runtime_surface* s = &model->surfaces[i - 1];
      status = read_surface(&r, s);
      for (size_t j = 0; status == HC_RUNTIME_OK && j + 1 < i; ++j) {
        if (strcmp(model->surfaces[j].name, s->name) == 0)
          status = hc_fail_at(&r, HC_RUNTIME_E_FORMAT, (size_t)offset,
                              "surface '%s' is also surface %zu; expected "
                              "unique surface names",
                              s->name, j + 1);
      }
    }
    if (status != HC_RUNTIME_OK) return status;
  }
  if (previous_end != model->size) {
    r.section = "file end";
    return hc_fail_at(&r, HC_RUNTIME_E_FORMAT, previous_end, "%zu bytes after the last section; expected none",
                      model->size - previous_end);
  }
  return HC_RUNTIME_OK;
}

static void set_message(char* err, size_t errlen, const char* format, const char* a, const char* b) {
  if (err != NULL && errlen > 0) snprintf(err, errlen, format, a, b);
}

/* Takes ownership of bytes (malloc'd, size bytes). */
static int open_owned(unsigned char* bytes, size_t size, hc_runtime_model** model, char* err, size_t errlen) {
  hc_runtime_model* m = (hc_runtime_model*)calloc(1, sizeof(hc_runtime_model));
  if (m == NULL) {
    free(bytes);
    set_message(err, errlen, "runtime file: out of memory%s%s", "", "");
    return HC_RUNTIME_E_MEMORY;
  }
  m->bytes = bytes;
  m->size = size;
  const int status = parse(m, err, errlen);
  if (status != HC_RUNTIME_OK) {
    hc_runtime_close(m);
    return status;
  }
  if (err != NULL && errlen > 0) err[0] = '\0';
  *model = m;
  return HC_RUNTIME_OK;
}

int hc_runtime_open_memory(const void* bytes, size_t size, hc_runtime_model** model, char* err, size_t errlen) {
  if (model == NULL || (bytes == NULL && size > 0)) {
    set_message(err, errlen, "hc_runtime_open_memory: %s%s", model == NULL ? "model is NULL" : "bytes is NULL", "");
    return HC_RUNTIME_E_ARGUMENT;
  }
  *model = NULL;
  unsigned char* copy = (unsigned char*)malloc(size > 0 ? size : 1);
  if (copy == NULL) {
    set_message(err, errlen, "runtime file: out of memory for %s%s bytes", "its", "");
    return HC_RUNTIME_E_MEMORY;
  }
  if (size > 0) memcpy(copy, bytes, size);
  return open_owned(copy, size, model, err, errlen);
}

int hc_runtime_open(const char* path, hc_runtime_model** model, char* err, size_t errlen) {
  if (model == NULL || path == NULL) {
    set_message(err, errlen, "hc_runtime_open: %s%s", model == NULL ? "model is NULL" : "path is NULL", "");
    return HC_RUNTIME_E_ARGUMENT;
  }
  *model = NULL;
  FILE* file = fopen(path, "rb");
  if (file == NULL) {
    set_message(err, errlen, "%s: cannot open: %s", path, strerror(errno));
    return HC_RUNTIME_E_IO;
  }
  /* One read of the whole file when its size is known (one byte more, to see its end). */
  size_t capacity = (size_t)1 << 16, size = 0;
  if (fseek(file, 0, SEEK_END) == 0) {
    const long length = ftell(file);
    if (length >= 0 && (unsigned long)length < SIZE_MAX) capacity = (size_t)length + 1;
    if (fseek(file, 0, SEEK_SET) != 0) {
      fclose(file);
      set_message(err, errlen, "%s: cannot read: %s", path, "seek failed");
      return HC_RUNTIME_E_IO;
    }
  }
  unsigned char* bytes = (unsigned char*)malloc(capacity);
  while (bytes != NULL) {
    size += fread(bytes + size, 1, capacity - size, file);
    if (size < capacity) break;
    if (capacity > SIZE_MAX / 2) {
      free(bytes);
      bytes = NULL;
      break;
    }
    unsigned char* grown = (unsigned char*)realloc(bytes, capacity * 2);
    if (grown == NULL) {
      free(bytes);
      bytes = NULL;
      break;
    }
    bytes = grown;
    capacity *= 2;
  }
  const int read_error = bytes != NULL && ferror(file);
  fclose(file);
  if (bytes == NULL) {
    set_message(err, errlen, "%s: out of memory reading it%s", path, "");
    return HC_RUNTIME_E_MEMORY;
  }
  if (read_error) {
    free(bytes);
    set_message(err, errlen, "%s: cannot read: %s", path, "read error");
    return HC_RUNTIME_E_IO;
  }
  const int status = open_owned(bytes, size, model, err, errlen);
  if (status != HC_RUNTIME_OK && err != NULL && errlen > 0) {
    /* Prefix the path: "PATH: runtime file, section ...". */
    char message[512];
    snprintf(message, sizeof message, "%s", err);
    snprintf(err, errlen, "%s: %s", path, message);
  }
  return status;
}
