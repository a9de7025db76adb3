/* The FMU's resource directory: fmuResourceLocation, a file URI given by the
 * host (RFC 8089 forms: file:///dir, file:/dir, file://localhost/dir), read
 * without trusting it; and the GUID of a runtime file. */
#include <stdio.h>
#include <string.h>

#include "fmu_internal.h"

static int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

static int lower_equal(const char* text, const char* lower, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    char c = text[i];
    if (c >= 'A' && c <= 'Z') c = (char)(c - 'A' + 'a');
    if (c != lower[i]) return 0;
  }
  return 1;
}

int fmu_resource_path(const char* uri, const char* file, char* out, size_t outlen, char* err, size_t errlen) {
  if (uri == NULL) {
    snprintf(err, errlen, "fmuResourceLocation is NULL; expected a file URI of the FMU's resources directory");
    return -1;
  }
  size_t length = 0;
  while (length < FMU_MAX_PATH * 3 + 64 && uri[length] != '\0') ++length;
  if (length > FMU_MAX_PATH * 3 + 32) {
    snprintf(err, errlen, "fmuResourceLocation is longer than %d bytes; expected a shorter file URI",
             FMU_MAX_PATH * 3 + 32);
    return -1;
  }
  if (length < 5 || !lower_equal(uri, "file:", 5)) {
    snprintf(err, errlen, "fmuResourceLocation '%.200s' is not a file URI; expected file:///path/to/resources", uri);
    return -1;
  }
  const char* path = uri + 5;
  if (path[0] == '/' && path[1] == '/') {
    const char* host = path + 2;
    const char* end = strchr(host, '/');
    if (end == NULL) {
      snprintf(err, errlen, "fmuResourceLocation '%.200s' has no path after its host; expected file:///path", uri);
      return -1;
    }
    const size_t host_length = (size_t)(end - host);
    if (host_length != 0 && !(host_length == 9 && lower_equal(host, "localhost", 9))) {
      snprintf(err, errlen,
               "fmuResourceLocation '%.200s' names host '%.*s'; expected a local file URI (file:///path or "
               "file://localhost/path)",
               uri, (int)(host_length > 64 ? 64 : host_length), host);
      return -1;
    }
    path = end;
  }
  if (path[0] != '/') {
    snprintf(err, errlen, "fmuResourceLocation '%.200s' has a relative path; expected an absolute one (file:///...)",
             uri);
    return -1;
  }
  size_t written = 0;
  const size_t file_length = strlen(file);
  for (const char* p = path; *p != '\0'; ++p) {
    char c = *p;
    if (c == '?' || c == '#') {
      snprintf(err, errlen, "fmuResourceLocation '%.200s' has a query or fragment; expected a plain file URI", uri);
      return -1;
    }
    if (c == '%') {
      const int high = hex_digit(p[1]);
      const int low = high < 0 ? -1 : hex_digit(p[2]);
      if (high < 0 || low < 0) {
        snprintf(err, errlen,
                 "fmuResourceLocation '%.200s' has a malformed percent escape at byte %zu; expected %%XX with two "
                 "hexadecimal digits",
                 uri, (size_t)(p - uri));
        return -1;
      }
      c = (char)(high * 16 + low);
      if (c == '\0') {
        snprintf(err, errlen, "fmuResourceLocation '%.200s' encodes a NUL byte (%%00) at byte %zu; expected none", uri,
                 (size_t)(p - uri));
        return -1;
      }
      p += 2;
    }
    if (written + 1 >= FMU_MAX_PATH || written + 1 >= outlen) {
      snprintf(err, errlen, "fmuResourceLocation's path is longer than %d bytes; expected a shorter one", FMU_MAX_PATH);
      return -1;
    }
    out[written++] = c;
  }
  if (written == 0 || out[written - 1] != '/') out[written++] = '/';
  if (written + file_length + 1 > outlen || written + file_length + 1 > FMU_MAX_PATH) {
    snprintf(err, errlen, "fmuResourceLocation's path is longer than %d bytes; expected a shorter one", FMU_MAX_PATH);
    return -1;
  }
  memcpy(out + written, file, file_length + 1);
  return 0;
}

void fmu_guid_of(unsigned long long hash, char* out, size_t outlen) {
  snprintf(out, outlen, "%s%016llx", FMU_GUID_PREFIX, hash);
}
