/* XXH64 (Yann Collet's xxHash, 64-bit variant), the runtime file's content
 * hash: shared by the writer (src/export/runtime_export.cpp) and the reader
 * (runtime/src/runtime_file.c). Reads bytes one at a time into little-endian
 * words, so it gives the same hash on every host. C11 and C++20. */
#ifndef HYDROCOEF_RUNTIME_XXH64_H
#define HYDROCOEF_RUNTIME_XXH64_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define HC_XXH_PRIME64_1 0x9E3779B185EBCA87ull
#define HC_XXH_PRIME64_2 0xC2B2AE3D27D4EB4Full
#define HC_XXH_PRIME64_3 0x165667B19E3779F9ull
#define HC_XXH_PRIME64_4 0x85EBCA77C2B2AE63ull
#define HC_XXH_PRIME64_5 0x27D4EB2F165667C5ull

static inline uint64_t hc_xxh64_rotl(uint64_t x, unsigned r) { return (x << r) | (x >> (64u - r)); }

static inline uint64_t hc_xxh64_read64(const unsigned char* p) {
  return (uint64_t)p[0] | (uint64_t)p[1] << 8 | (uint64_t)p[2] << 16 | (uint64_t)p[3] << 24 | (uint64_t)p[4] << 32 |
         (uint64_t)p[5] << 40 | (uint64_t)p[6] << 48 | (uint64_t)p[7] << 56;
}

static inline uint64_t hc_xxh64_round(uint64_t acc, uint64_t input) {
  acc += input * HC_XXH_PRIME64_2;
  acc = hc_xxh64_rotl(acc, 31);
  return acc * HC_XXH_PRIME64_1;
}

static inline uint64_t hc_xxh64_merge(uint64_t acc, uint64_t value) {
  acc ^= hc_xxh64_round(0, value);
  return acc * HC_XXH_PRIME64_1 + HC_XXH_PRIME64_4;
}

/* XXH64 of size bytes at data with the given seed. */
static inline uint64_t hc_xxh64(const void* data, size_t size, uint64_t seed) {
  const unsigned char* p = (const unsigned char*)data;
  const unsigned char* const end = p + size;
  uint64_t h;
  if (size >= 32) {
    uint64_t v1 = seed + HC_XXH_PRIME64_1 + HC_XXH_PRIME64_2, v2 = seed + HC_XXH_PRIME64_2, v3 = seed,
             v4 = seed - HC_XXH_PRIME64_1;
    const unsigned char* const limit = end - 32;
    do {
      v1 = hc_xxh64_round(v1, hc_xxh64_read64(p));
      v2 = hc_xxh64_round(v2, hc_xxh64_read64(p + 8));
      v3 = hc_xxh64_round(v3, hc_xxh64_read64(p + 16));
      v4 = hc_xxh64_round(v4, hc_xxh64_read64(p + 24));
      p += 32;
    } while (p <= limit);
    h = hc_xxh64_rotl(v1, 1) + hc_xxh64_rotl(v2, 7) + hc_xxh64_rotl(v3, 12) + hc_xxh64_rotl(v4, 18);
    h = hc_xxh64_merge(h, v1);
    h = hc_xxh64_merge(h, v2);
    h = hc_xxh64_merge(h, v3);
    h = hc_xxh64_merge(h, v4);
  } else {
    h = seed + HC_XXH_PRIME64_5;
  }
  h += (uint64_t)size;
  while (end - p >= 8) {
    h ^= hc_xxh64_round(0, hc_xxh64_read64(p));
    h = hc_xxh64_rotl(h, 27) * HC_XXH_PRIME64_1 + HC_XXH_PRIME64_4;
    p += 8;
  }
  if (end - p >= 4) {
    const uint64_t word = (uint64_t)p[0] | (uint64_t)p[1] << 8 | (uint64_t)p[2] << 16 | (uint64_t)p[3] << 24;
    h ^= word * HC_XXH_PRIME64_1;
    h = hc_xxh64_rotl(h, 23) * HC_XXH_PRIME64_2 + HC_XXH_PRIME64_3;
    p += 4;
  }
  while (p < end) {
    h ^= (uint64_t)(*p) * HC_XXH_PRIME64_5;
    h = hc_xxh64_rotl(h, 11) * HC_XXH_PRIME64_1;
    ++p;
  }
  h ^= h >> 33;
  h *= HC_XXH_PRIME64_2;
  h ^= h >> 29;
  h *= HC_XXH_PRIME64_3;
  h ^= h >> 32;
  return h;
}

#ifdef __cplusplus
}
#endif

#endif
