// libFuzzer target: a stored coefficient surface decoded from arbitrary bytes
// (src/surface/stored_surface: surface_from_record), as a received database
// could hold it, then evaluated at the corners and the middle of its range;
// and a stored fit's terms (parse_damping_terms). Input layout, so that
// seeds are readable: kind, method, definition JSON and quality JSON on the
// first four lines, then the data blob's bytes (float64, little-endian).
// The decoder may accept the record or throw InputError; a size near 2^63
// in the definition must be refused before anything is allocated for it.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "src/fit/damping_law.hpp"
#include "src/surface/stored_surface.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

std::string_view next_line(std::string_view& rest) {
  const auto end = rest.find('\n');
  const std::string_view line = rest.substr(0, end);
  rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
  return line;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  SurfaceRecord record;
  record.id = 1;
  record.name = "fuzz";
  record.body = "body";
  record.kind = std::string(next_line(rest));
  record.method = std::string(next_line(rest));
  record.definition = std::string(next_line(rest));
  record.quality = std::string(next_line(rest));
  record.data.resize(rest.size() / sizeof(double));
  if (!record.data.empty()) std::memcpy(record.data.data(), rest.data(), record.data.size() * sizeof(double));
  try {
    const CoefficientSurface surface = surface_from_record(record);
    std::vector<double> point(surface.axis_count()), out(surface.output_count());
    for (int corner = 0; corner < 3; ++corner) {
      for (std::size_t a = 0; a < surface.axis_count(); ++a) {
        const double lower = surface.lower(a), upper = surface.upper(a);
        point[a] = corner == 0 ? lower : corner == 1 ? upper : 0.5 * lower + 0.5 * upper;
      }
      try {
        surface.evaluate(point, out);
      } catch (const InputError& error) {
        fuzz::check_error(error);
      }
    }
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  try {
    (void)parse_damping_terms(record.method);
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
