// A one-run ImportBatch as an importer would deliver it, for tests that fill a
// database without files: the source is a made-up file whose hash comes from
// `id`, so that each id is a distinct import.
#pragma once

#include <cstdio>
#include <string>

#include "src/core/run.hpp"

namespace hydrocoef::test {

inline ImportBatch one_run_batch(int id, const ImportedRun& run) {
  ImportBatch batch;
  char hash[65];
  std::snprintf(hash, sizeof hash, "%064x", id);
  batch.source.path = "case-" + std::to_string(id) + ".csv";
  batch.source.sha256 = hash;
  batch.source.size_bytes = 1;
  batch.source.importer = "test";
  batch.source.importer_version = "1";
  batch.source.settings_key = "id=" + std::to_string(id);
  batch.runs = {run};
  return batch;
}

}  // namespace hydrocoef::test
