#include "core/particles.hpp"

#include <algorithm>
#include <iterator>

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
  for (auto& [name, f] : ints_) f.push_back(0);
}

void Particles::claim(std::string_view name, std::string_view owner) {
  auto [it, fresh] = owners_.emplace(std::string(name), std::string(owner));
  if (!fresh && it->second != owner)
    throw FieldError("particle field '" + std::string(name) + "' is owned by " + it->second + "; " +
                     std::string(owner) + " cannot create it too");
}

std::vector<double>& Particles::add_field(std::string_view name, std::string_view owner) {
  if (has_int_field(name)) throw FieldError("particle field '" + std::string(name) + "' exists as an integer field");
  claim(name, owner);
  auto it = extra_.find(std::string(name));
  if (it == extra_.end()) it = extra_.emplace(std::string(name), std::vector<double>(size(), 0.0)).first;
  return it->second;
}

std::vector<std::int32_t>& Particles::add_int_field(std::string_view name, std::string_view owner) {
  if (has_field(name)) throw FieldError("particle field '" + std::string(name) + "' exists as a real field");
  claim(name, owner);
  auto it = ints_.find(std::string(name));
  if (it == ints_.end()) it = ints_.emplace(std::string(name), std::vector<std::int32_t>(size(), 0)).first;
  return it->second;
}

void Particles::missing(std::string_view name) const {
  std::string known;
  for (const auto& [n, f] : extra_) known += " " + n;
  for (const auto& [n, f] : ints_) known += " " + n;
  throw FieldError("no particle field '" + std::string(name) + "' (this scene has:" + known + ")");
}

std::vector<double>& Particles::field(std::string_view name) {
  auto it = extra_.find(std::string(name));
  if (it == extra_.end()) missing(name);
  return it->second;
}
const std::vector<double>& Particles::field(std::string_view name) const {
  auto it = extra_.find(std::string(name));
  if (it == extra_.end()) missing(name);
  return it->second;
}
std::vector<std::int32_t>& Particles::int_field(std::string_view name) {
  auto it = ints_.find(std::string(name));
  if (it == ints_.end()) missing(name);
  return it->second;
}
const std::vector<std::int32_t>& Particles::int_field(std::string_view name) const {
  auto it = ints_.find(std::string(name));
  if (it == ints_.end()) missing(name);
  return it->second;
}
const double* Particles::find(std::string_view name) const {
  auto it = extra_.find(std::string(name));
  return it == extra_.end() ? nullptr : it->second.data();
}
const std::int32_t* Particles::find_int(std::string_view name) const {
  auto it = ints_.find(std::string(name));
  return it == ints_.end() ? nullptr : it->second.data();
}
const std::string& Particles::owner(std::string_view name) const {
  auto it = owners_.find(std::string(name));
  if (it == owners_.end()) missing(name);
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
  std::vector<std::int32_t> t32;
  for (auto& [name, f] : ints_) apply(f, order, t32);
  std::vector<Kind> tk; apply(kind, order, tk);
  std::vector<std::int64_t> ti; apply(id, order, ti);
  std::vector<std::uint16_t> tm; apply(material, order, tm);
}

namespace {
template <class T>
void compact(std::vector<T>& v, const std::vector<char>& remove) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!remove[i]) v[k++] = v[i];
  v.resize(k);
}
template <class T>
void extend(std::vector<T>& v, const std::vector<T>* from, std::size_t n) {
  if (from) v.insert(v.end(), from->begin(), from->end());
  else v.resize(v.size() + n, T{});
}
}  // namespace

std::size_t Particles::remove(const std::vector<char>& remove) {
  const std::size_t before = size();
  for (auto* f : {&x, &y, &z, &vx, &vy, &vz, &ax, &ay, &az, &rho, &drho, &p, &m}) compact(*f, remove);
  for (auto& [name, f] : extra_) compact(f, remove);
  for (auto& [name, f] : ints_) compact(f, remove);
  compact(kind, remove);
  compact(id, remove);
  compact(material, remove);
  return before - size();
}

void Particles::append(const Particles& o) {
  const std::size_t n = o.size();
  std::int64_t next = 0;
  for (const auto v : id) next = std::max(next, v + 1);
  for (const auto& [name, f] : o.extra_)
    if (!has_field(name)) add_field(name, o.owner(name));
  for (const auto& [name, f] : o.ints_)
    if (!has_int_field(name)) add_int_field(name, o.owner(name));
  const std::vector<double>* core[] = {&o.x, &o.y, &o.z, &o.vx, &o.vy, &o.vz, &o.ax, &o.ay, &o.az, &o.rho, &o.drho, &o.p, &o.m};
  std::vector<double>* mine[] = {&x, &y, &z, &vx, &vy, &vz, &ax, &ay, &az, &rho, &drho, &p, &m};
  for (std::size_t c = 0; c < std::size(mine); ++c) extend(*mine[c], core[c], n);
  for (auto& [name, f] : extra_) {
    const auto it = o.extra_.find(name);
    extend(f, it == o.extra_.end() ? nullptr : &it->second, n);
  }
  for (auto& [name, f] : ints_) {
    const auto it = o.ints_.find(name);
    extend(f, it == o.ints_.end() ? nullptr : &it->second, n);
  }
  extend(kind, &o.kind, n);
  extend(material, &o.material, n);
  for (std::size_t i = 0; i < n; ++i) id.push_back(next + static_cast<std::int64_t>(i));
}

void Particles::resize(std::size_t n) {
  for (auto* f : {&x, &y, &z, &vx, &vy, &vz, &ax, &ay, &az, &rho, &drho, &p, &m}) f->resize(n);
  for (auto& [name, f] : extra_) f.resize(n);
  for (auto& [name, f] : ints_) f.resize(n);
  kind.resize(n);
  id.resize(n);
  material.resize(n);
}

std::size_t Particles::count(Kind k) const { return static_cast<std::size_t>(std::count(kind.begin(), kind.end(), k)); }

}  // namespace geosph
