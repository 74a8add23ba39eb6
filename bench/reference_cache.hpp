// A converged bounce run kept in a file, so that repeated comparisons against it do not recompute it.
#pragma once

#include <optional>
#include <string>

#include "bounce_run.hpp"

namespace bench {

// The record stored in `path` (written by save_record), or nothing if the file is missing or not one.
std::optional<BounceRecord> load_record(const std::string& path);
// Writes `record`'s samples, step and times to `path` (raw doubles: the same machine reads them back).
void save_record(const BounceRecord& record, const std::string& path);
// The run of `setup` over duration_s: read from `path` if it holds one, else recorded and written there (an empty
// path: recorded, nothing kept). Same setup and duration as the stored run are the caller's business.
BounceRecord load_or_record(const BounceSetup& setup, double duration_s, const std::string& path);

}  // namespace bench
