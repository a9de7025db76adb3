// Shared checks for the libFuzzer targets in tests/fuzz: what every parser
// must guarantee for any bytes. A parser may accept the input or throw
// InputError with a one-line message; anything else (another exception, a
// crash, a sanitizer report, a broken invariant of the result) is a finding.
// A finding aborts, so libFuzzer saves the input as crash-<sha1>.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "src/core/error.hpp"
#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef::fuzz {

[[noreturn]] inline void finding(const char* what, std::string_view detail = {}) {
  std::fprintf(stderr, "fuzz finding: %s: %.*s\n", what, static_cast<int>(detail.size()), detail.data());
  std::abort();
}

/// The CLI prints an InputError as one line: its message must hold no line
/// break.
inline void check_error(const InputError& error) {
  const std::string_view message = error.what();
  if (message.empty()) finding("empty InputError message");
  if (message.find('\n') != std::string_view::npos) finding("InputError message spans lines", message);
}

/// A mesh the integration may trust: offsets ascending from 0, indices in
/// range, one location per face, arrays of the right length.
inline void check_mesh(const SurfaceMesh& mesh) {
  if (mesh.points_xyz.size() % 3 != 0) finding("points_xyz not a multiple of 3");
  if (mesh.face_offsets.empty() || mesh.face_offsets.front() != 0) finding("face_offsets must start with 0");
  for (std::size_t f = 0; f + 1 < mesh.face_offsets.size(); ++f)
    if (mesh.face_offsets[f + 1] < mesh.face_offsets[f] + 3) finding("face with fewer than 3 points");
  if (mesh.face_offsets.back() != mesh.face_indices.size()) finding("face_offsets do not end at face_indices");
  for (const auto index : mesh.face_indices)
    if (index >= mesh.point_count()) finding("face index out of range");
  if (!mesh.face_location.empty() && mesh.face_location.size() != mesh.face_count())
    finding("face_location size differs from the face count");
  for (const auto location : mesh.face_location)
    if (location >= mesh.location_names.size()) finding("face_location out of range");
  for (const auto& field : mesh.fields) {
    const std::size_t expected = field.association == FieldAssociation::Point ? mesh.point_count() : mesh.face_count();
    if (field.components < 1 || field.size() != expected ||
        field.values.size() != expected * static_cast<std::size_t>(field.components))
      finding("field array of the wrong length", field.name);
  }
}

}  // namespace hydrocoef::fuzz
