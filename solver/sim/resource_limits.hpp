// What a scene will cost before anything is allocated: the particle count (from the bodies' and
// walls' lattices), the memory it needs, and the cell list's size. A spacing that would create 10^12
// particles, or a domain of 10^11 cells around a small body, is refused with a message naming the
// field instead of running into std::bad_alloc or the swap for minutes.
#pragma once
#include "io/scene.hpp"

namespace geosph {

struct ResourceEstimate {
  double particles = 0;  // about; walls counted as full layers
  double bytes = 0;      // particles x bytes per particle of the scene's physics
  double cells = 0;      // cell-list cells of the domain
};

ResourceEstimate estimate_resources(const Scene& scene);
// Throws InputError naming the file and field (dx, domain) when the estimate exceeds scene.limits or
// the memory this machine has available (MemAvailable of /proc/meminfo, where it exists).
void check_resources(const Scene& scene);

}  // namespace geosph
