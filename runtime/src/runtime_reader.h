/* The checked reading of a runtime file's sections (runtime_file.c), shared
 * by the surface and vehicle sections' readers. Not installed; the
 * functions are hidden in the shared library. */
#ifndef HYDROCOEF_RUNTIME_READER_H
#define HYDROCOEF_RUNTIME_READER_H

#include <stddef.h>
#include <stdint.h>

#include "runtime_internal.h"

/* A cursor over one section (or the header) of the file. */
typedef struct reader {
  unsigned char* base;
  size_t pos;
  size_t end;
  const char* section; /* e.g. "header", "surface section 2" */
  char section_text[48];
  char* err;
  size_t errlen;
} reader;

/* Writes "runtime file, SECTION, byte OFFSET: MESSAGE" into the reader's
 * err; returns status. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((format(printf, 4, 5)))
#endif
int hc_fail_at(reader* r, int status, size_t offset, const char* format, ...);
uint32_t hc_get_u32(const unsigned char* p);
uint64_t hc_get_u64(const unsigned char* p);
/* Each reads at the cursor and advances it, or fails naming `what`. */
int hc_read_u32(reader* r, const char* what, uint32_t* value);
int hc_read_u64(reader* r, const char* what, uint64_t* value);
int hc_read_reserved(reader* r, const char* what);
int hc_read_text(reader* r, const char* what, const char** text);
int hc_read_doubles(reader* r, const char* what, uint64_t count, const double** values);
int hc_check_finite(reader* r, const char* what, const double* values, size_t count, size_t first_byte);
int hc_read_pairs(reader* r, const char* what, hc_text_pair** pairs, size_t* count);

/* The vehicle section (runtime_vehicle_file.c): reads it into
 * model->vehicle, checking its indices against the model's surfaces. */
int hc_read_vehicle(reader* r, hc_runtime_model* model);
void hc_free_vehicle(hc_runtime_vehicle* vehicle);

#endif
