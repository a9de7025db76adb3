// The FMU binary (fmu/src, built as hydrocoef_fmu), embedded into the library
// at build time (fmu/embed_binary.cmake): `hydrocoef export-fmu` writes these
// bytes as binaries/linux64/<modelIdentifier>.so of every FMU.
#pragma once

#include <cstddef>

namespace hydrocoef {

const unsigned char* fmu_binary_bytes();
std::size_t fmu_binary_size();

}  // namespace hydrocoef
