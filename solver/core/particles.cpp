#include "core/particles.hpp"

#include <algorithm>

namespace geosph {

void Particles::add(double px, double py, double pz, double mass, double density, Kind k, std::uint16_t mat) {
  x.push_back(px); y.push_back(py); z.push_back(pz);
  vx.push_back(0); vy.push_back(0); vz.push_back(0);
  ax.push_back(0); ay.push_back(0); az.push_back(0);
  rho.push_back(density); drho.push_back(0); p.push_back(0);
  m.push_back(mass);
  kind.push_back(k);
  id.push_back(static_cast<std::int64_t>(id.size()));
  material.push_back(mat);
  for (auto& [name, f] : extra_) f.push_back(0.0);
}

std::vector<double>& Particles::field(const std::string& name) {
  auto it = extra_.find(name);
  if (it == extra_.end()) it = extra_.emplace(name, std::vector<double>(size(), 0.0)).first;
  return it->second;
}

namespace {
template <class T>
void apply(std::vector<T>& v, const std::vector<std::uint32_t>& order, std::vector<T>& tmp) {
  tmp.resize(v.size());
  const std::size_t n = v.size();
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) tmp[k] = v[order[k]];
  v.swap(tmp);
}
}  // namespace

void Particles::permute(const std::vector<std::uint32_t>& order) {
  for (auto* f : {&x, &y, &z, &vx, &vy, &vz, &ax, &ay, &az, &rho, &drho, &p, &m}) apply(*f, order, scratch_);
  for (auto& [name, f] : extra_) apply(f, order, scratch_);
  std::vector<Kind> tk; apply(kind, order, tk);
  std::vector<std::int64_t> ti; apply(id, order, ti);
  std::vector<std::uint16_t> tm; apply(material, order, tm);
}

std::size_t Particles::count(Kind k) const { return static_cast<std::size_t>(std::count(kind.begin(), kind.end(), k)); }

}  // namespace geosph
