// Where a result came from: the solver version (release and git commit), the compiler and flags it
// was built with, the thread count and the hash of the input. Written into every snapshot, checkpoint,
// run summary and result record, so that a number in a report can be traced to the build and scene
// that produced it.
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace geosph {

struct Provenance {
  std::string solver_version;  // "0.1.0 (git 1234abcd5678[+dirty])"
  std::string compiler;        // e.g. "GNU 12.2.0"
  std::string build_flags;     // build type and compile flags
  int threads = 1;             // OpenMP threads of the run
  std::string scene_hash;      // content_hash of the input (canonical JSON)
  nlohmann::json to_json() const;
};

std::string solver_version();
// 64-bit FNV-1a of the text as 16 hex digits: an identity check of an input (a scene, a case's
// files), not a cryptographic digest; a few lines instead of a hashing library.
std::string content_hash(std::string_view text);
// This build's provenance with the current OpenMP thread count.
Provenance provenance(const std::string& scene_hash);

}  // namespace geosph
