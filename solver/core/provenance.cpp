#include "core/provenance.hpp"

#include <omp.h>

#include <cstdint>
#include <cstdio>

#include "git_version.hpp"  // generated at build time (cmake/git_version.cmake)

namespace geosph {

nlohmann::json Provenance::to_json() const {
  return {{"solver_version", solver_version}, {"compiler", compiler}, {"build_flags", build_flags},
          {"threads", threads}, {"scene_hash", scene_hash}};
}

std::string solver_version() { return std::string(GEOSPH_RELEASE) + " (git " + GEOSPH_GIT_VERSION + ")"; }

std::string content_hash(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a offset basis and prime (Fowler, Noll, Vo)
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

Provenance provenance(const std::string& scene_hash) {
  return {solver_version(), GEOSPH_COMPILER, GEOSPH_BUILD_FLAGS, omp_get_max_threads(), scene_hash};
}

}  // namespace geosph
