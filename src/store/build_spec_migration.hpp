// Migration 7's data step (schema/0007_surface_build_spec.sql): every stored
// surface's command-line build options ("build" in its definition JSON)
// become its serialized build specification ("build_spec",
// src/surface/surface_build_spec.hpp).
#pragma once

#include "src/store/connection.hpp"

namespace hydrocoef::store {

/// The schema version whose migration this step completes.
inline constexpr int kBuildSpecMigration = 7;

/// Converts every surface's definition in place, inside the caller's
/// transaction. InputError naming the database and surface when a
/// definition is not JSON or its options cannot be converted.
void convert_surface_build_options(Connection& connection, const std::string& database);

}  // namespace hydrocoef::store
