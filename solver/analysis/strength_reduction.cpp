#include "analysis/strength_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"
#include "sim/stability.hpp"
#include "soil/soil_fields.hpp"

namespace geosph {

namespace {

constexpr double kPi = 3.14159265358979323846;

bool reducible(const nlohmann::json& m) {
  const std::string model = m.value("model", "");
  return model == "drucker_prager" || model == "mohr_coulomb";
}

// u95: the displacement from the start exceeded by 5% of the soil particles.
double displacement_95(const Particles& P, const std::vector<std::array<double, 3>>& start) {
  std::vector<double> u;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const auto& s = start[static_cast<std::size_t>(P.id[i])];
    u.push_back(std::sqrt((P.x[i] - s[0]) * (P.x[i] - s[0]) + (P.y[i] - s[1]) * (P.y[i] - s[1]) +
                          (P.z[i] - s[2]) * (P.z[i] - s[2])));
  }
  if (u.empty()) return 0;
  const std::size_t k = static_cast<std::size_t>(0.95 * static_cast<double>(u.size() - 1));
  std::nth_element(u.begin(), u.begin() + static_cast<long>(k), u.end());
  return u[k];
}

StrengthReductionTrial run_trial(const nlohmann::json& scene, const std::string& file, double factor,
                                 const StrengthReductionOptions& o, Particles* state) {
  StrengthReductionTrial t;
  t.factor = factor;
  Simulation sim(parse_scene(reduce_strength(scene, factor), file));
  const Particles& P = sim.particles();
  std::vector<std::array<double, 3>> start(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) start[static_cast<std::size_t>(P.id[i])] = {P.x[i], P.y[i], P.z[i]};
  bool moved = false;
  try {
    const GravityLoadingResult& r = sim.try_settle_under_gravity([&](const Simulation& s) {
      if (s.steps() % 50 != 0) return false;
      moved = displacement_95(s.particles(), start) > o.displacement_limit;
      return moved;
    });
    t.time = r.time;
    t.steps = r.steps;
    t.kinetic_energy_ratio = r.peak_kinetic_energy > 0 ? r.final_kinetic_energy / r.peak_kinetic_energy : 0;
    t.displacement = displacement_95(P, start);
    if (moved || t.displacement > o.displacement_limit) {
      t.reason = "u95 passed the displacement limit";
    } else if (!r.settled) {
      t.reason = "kinetic energy not settled within gravity_loading.max_time";
    } else {
      t.stable = true;
      t.reason = "settled";
    }
  } catch (const InstabilityError& e) {
    t.time = sim.time();
    t.steps = sim.steps();
    t.displacement = displacement_95(P, start);
    t.reason = std::string("unstable: ") + e.what();
  }
  if (state) *state = P;
  return t;
}

}  // namespace

nlohmann::json reduce_strength(const nlohmann::json& scene, double factor) {
  nlohmann::json j = scene;
  if (!j.contains("materials") || !j["materials"].is_object()) return j;
  for (auto& [name, m] : j["materials"].items()) {
    if (!m.is_object() || !reducible(m)) continue;
    if (m.contains("cohesion") && m["cohesion"].is_number()) m["cohesion"] = m["cohesion"].get<double>() / factor;
    if (m.contains("friction_angle") && m["friction_angle"].is_number()) {
      const double phi = m["friction_angle"].get<double>() * kPi / 180;
      const double phi_f = std::atan(std::tan(phi) / factor) * 180 / kPi;
      m["friction_angle"] = phi_f;
      if (m.contains("dilatancy_angle") && m["dilatancy_angle"].is_number())
        m["dilatancy_angle"] = std::min(m["dilatancy_angle"].get<double>(), phi_f);
    }
  }
  return j;
}

StrengthReductionResult strength_reduction(const nlohmann::json& scene, const std::string& file,
                                           const StrengthReductionOptions& o,
                                           const std::function<void(const StrengthReductionTrial&, const Particles&)>& report) {
  if (!(o.f_low > 0) || !(o.f_high > o.f_low))
    throw InputError("--f-low/--f-high: need 0 < f_low < f_high, got " + std::to_string(o.f_low) + ", " + std::to_string(o.f_high));
  if (!(o.tolerance > 0)) throw InputError("--tolerance: must be > 0");
  if (!(o.displacement_limit > 0)) throw InputError("--displacement-limit: must be > 0 m");
  double dx = 0;
  {
    const Scene s = parse_scene(scene, file);  // the scene itself must be valid
    if (!s.gravity_loading.active)
      throw InputError(file + ": field 'gravity_loading': strength reduction loads each trial with the scene's "
                              "gravity-loading stage; the scene has none");
    if (s.gravity_loading.model != "material")
      throw InputError(file + ": field 'gravity_loading.model': strength reduction needs \"material\" (the trial's "
                              "reduced strength must act during loading)");
    bool any = false;
    for (const auto& [name, m] : scene.at("materials").items()) any = any || (m.is_object() && reducible(m));
    if (!any) throw InputError(file + ": field 'materials': no drucker_prager or mohr_coulomb material to reduce");
    dx = s.dx;
  }
  StrengthReductionResult res;
  Particles state;
  const auto trial = [&](double f) {
    Particles st;
    const StrengthReductionTrial t = run_trial(scene, file, f, o, &st);
    res.trials.push_back(t);
    if (report) report(t, st);
    if (!t.stable) state = std::move(st);
    return t.stable;
  };
  double lo = o.f_low, hi = o.f_high;
  if (!trial(lo))
    throw InputError("--f-low: the slope fails already at F = " + std::to_string(lo) + " (" + res.trials.back().reason +
                     "); lower --f-low");
  Particles failed;
  if (trial(hi))
    throw InputError("--f-high: the slope holds at F = " + std::to_string(hi) + "; raise --f-high");
  failed = std::move(state);
  while (hi - lo > o.tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (trial(mid)) {
      lo = mid;
    } else {
      hi = mid;
      failed = std::move(state);
    }
  }
  res.f_stable = lo;
  res.f_failed = hi;
  res.factor_of_safety = 0.5 * (lo + hi);
  res.failure_surface = slip_surface(failed, dx);
  res.plastic_band = plastic_band(failed, dx);
  res.failed_state = std::move(failed);
  return res;
}

std::vector<std::array<double, 2>> plastic_band(const Particles& P, double dx, double fraction) {
  const double* eps = P.find(SoilFields::plastic_strain);
  std::vector<std::array<double, 2>> band;
  if (!eps) return band;
  double top = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) top = std::max(top, eps[i]);
  if (!(top > 0)) return band;
  std::map<long, std::size_t> best;  // column -> particle of largest plastic strain
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const long c = std::lround(std::floor(P.x[i] / (2 * dx)));
    auto [it, fresh] = best.try_emplace(c, i);
    if (!fresh && eps[i] > eps[it->second]) it->second = i;
  }
  for (const auto& [c, i] : best)
    if (eps[i] >= fraction * top) band.push_back({P.x[i], P.y[i]});
  return band;
}

}  // namespace geosph

namespace geosph {

std::vector<std::array<double, 2>> slip_surface(const Particles& P, double dx, double fraction) {
  std::map<long, std::vector<std::pair<double, double>>> columns;  // column -> (y, speed), soil only
  double fastest = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const double v = std::sqrt(P.vx[i] * P.vx[i] + P.vy[i] * P.vy[i] + P.vz[i] * P.vz[i]);
    columns[std::lround(std::floor(P.x[i] / (2 * dx)))].push_back({P.y[i], v});
    fastest = std::max(fastest, v);
  }
  std::vector<std::array<double, 2>> line;
  if (!(fastest > 0)) return line;
  for (auto& [c, col] : columns) {
    double top = 0;
    for (const auto& [y, v] : col) top = std::max(top, v);
    if (top < fraction * fastest) continue;
    std::sort(col.begin(), col.end());
    // from the top down, the first particle slower than half the column's fastest
    for (std::size_t k = col.size(); k-- > 1;) {
      if (col[k].second >= 0.5 * top && col[k - 1].second < 0.5 * top) {
        line.push_back({(c + 0.5) * 2 * dx, 0.5 * (col[k].first + col[k - 1].first)});
        break;
      }
    }
  }
  return line;
}

}  // namespace geosph
