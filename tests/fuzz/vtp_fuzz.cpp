// libFuzzer target: the direct .vtp reader (importers/vtk_xml_polydata): its
// XML header parser, base64 and zlib decoding and the checks on the decoded
// arrays. For any bytes it may leave the file to VTK's reader (no mesh),
// refuse it with a one-line InputError, or return a mesh the integration can
// trust.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "importers/vtk_xml_polydata.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const auto mesh = parse_vtp_surface(bytes, "fuzz.vtp", "fuzz");
    if (!mesh) return 0;
    fuzz::check_mesh(*mesh);
    if (mesh->face_count() == 0) fuzz::finding("a mesh without faces");
    if (mesh->location_names.size() != 1 || mesh->face_location.size() != mesh->face_count())
      fuzz::finding("not one location for every face");
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
