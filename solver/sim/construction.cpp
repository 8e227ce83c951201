#include "sim/construction.hpp"

#include <cmath>
#include <unordered_map>

#include "geometry/shape_input.hpp"
#include "io/scene_reference.hpp"

namespace geosph {

namespace {

const bool documented = register_section(
    {"excavations", "excavations[k]",
     "An excavation stage: at its time the soil and fluid particles inside its shape are removed (walls and "
     "structures stay). With gravity_loading.after_construction the solids then settle again.",
     {number_doc("time", Range::positive(), "required", "s", "when the region is removed (at most time.end)"),
      {"shape", FieldType::Object, "a shape object (see shape)", "required", "-", "the region removed"}}});

}  // namespace

ExcavationSpec parse_excavation(const JsonFields& f, int dim) {
  f.section("excavations");
  ExcavationSpec e;
  e.time = f.number("time", Range::positive());
  e.shape = parse_shape(f.object("shape"), dim);
  const geometry::Bounds bb = e.shape->bounds();
  e.lo = bb.lo;
  e.hi = bb.hi;
  f.reject_unknown();
  return e;
}

std::vector<char> inside_excavation(const Particles& P, const geometry::Shape& shape, double dx) {
  std::vector<char> out(P.size(), 0);
  const geometry::Bounds bb = shape.bounds();
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil && P.kind[i] != Kind::Fluid) continue;
    const geometry::Point p{P.x[i], P.y[i], P.z[i]};
    bool in_box = true;
    for (int a = 0; a < P.dim; ++a) in_box = in_box && p[a] >= bb.lo[a] - dx && p[a] <= bb.hi[a] + dx;
    out[i] = in_box && shape.contains(p, dx);
  }
  return out;
}

long first_overlap(const Particles& P, const Particles& added, double dx) {
  // the added particles by cell of size dx/2: a particle closer than dx/2 lies in a neighbouring cell
  const double c = 0.5 * dx;
  const auto key = [c](double x, double y, double z) {
    const auto q = [c](double v) { return static_cast<std::int64_t>(std::floor(v / c)) & 0x1fffff; };
    return (q(x) << 42) | (q(y) << 21) | q(z);
  };
  std::unordered_multimap<std::int64_t, std::size_t> cells;
  for (std::size_t k = 0; k < added.size(); ++k) cells.emplace(key(added.x[k], added.y[k], added.z[k]), k);
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int d = -1; d <= 1; ++d) {
          const auto range = cells.equal_range(key(P.x[i] + a * c, P.y[i] + b * c, P.z[i] + d * c));
          for (auto it = range.first; it != range.second; ++it) {
            const std::size_t k = it->second;
            const double rx = P.x[i] - added.x[k], ry = P.y[i] - added.y[k], rz = P.z[i] - added.z[k];
            if (rx * rx + ry * ry + rz * rz < 0.25 * dx * dx * (1 - 1e-9)) return static_cast<long>(i);
          }
        }
  return -1;
}

}  // namespace geosph
