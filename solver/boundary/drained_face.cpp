#include "boundary/drained_face.hpp"

#include <algorithm>

namespace geosph {

std::vector<DrainedFace> drained_faces(const Scene& s) {
  std::vector<DrainedFace> out;
  for (std::size_t k = 0; k < s.walls.containers.size(); ++k)
    for (int a = 0; a < s.dim; ++a)
      for (bool upper : {false, true}) {
        const auto& c = s.walls.containers[k];
        if (std::find(c.drained.begin(), c.drained.end(), container_side(s.dim, a, upper)) == c.drained.end()) continue;
        DrainedFace f;
        f.container = k;
        f.axis = a;
        f.upper = upper;
        f.plane = upper ? c.hi[a] : c.lo[a];
        f.lo = c.lo;
        f.hi = c.hi;
        f.pressure = c.drained_pressure;
        out.push_back(f);
      }
  return out;
}

std::int32_t drained_face_of(const Scene& s, const std::vector<DrainedFace>& faces, std::size_t container,
                             const double x[3]) {
  const auto& c = s.walls.containers[container];
  int outside = 0, axis = -1;
  bool upper = false;
  for (int a = 0; a < s.dim; ++a)
    if (x[a] < c.lo[a] || x[a] > c.hi[a]) {
      ++outside;
      axis = a;
      upper = x[a] > c.hi[a];
    }
  if (outside != 1) return 0;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (faces[f].axis == axis && faces[f].upper == upper && faces[f].container == container)
      return static_cast<std::int32_t>(f + 1);
  return 0;
}

std::vector<char> crossed_drained_faces(const Scene& s, const std::vector<DrainedFace>& faces, const Particles& P) {
  std::vector<char> out(P.size(), 0);
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    const double x[3] = {P.x[i], P.y[i], P.z[i]};
    for (const auto& f : faces)
      if (f.depth(x) > 0 && f.spans(x, s.dim)) { out[i] = 1; break; }
  }
  return out;
}

}  // namespace geosph
