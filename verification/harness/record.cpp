#include "harness/record.hpp"

#include <cmath>

namespace geosph::verify {

void Record::add_metric(const std::string& name, double value, double tolerance, const std::string& why) {
  metrics.push_back({name, value, tolerance, std::isfinite(value) && value <= tolerance, why});
}

bool Record::passed() const {
  if (!stable || metrics.empty()) return false;
  for (const auto& m : metrics)
    if (!m.passed) return false;
  return true;
}

nlohmann::json Record::to_json() const {
  nlohmann::json j;
  j["case"] = case_name;
  j["title"] = title;
  j["level"] = level;
  if (!variant.empty()) j["variant"] = variant;
  if (!scored) j["scored"] = false;
  j["reference"] = reference;
  j["resolution"] = {{"dx", dx}, {"particles", particles}, {"wall_particles", wall_particles}, {"dimension", dimension}};
  j["metrics"] = nlohmann::json::array();
  for (const auto& m : metrics) {
    nlohmann::json mj = {{"name", m.name}, {"tolerance", m.tolerance}, {"passed", m.passed}, {"why_tolerance", m.why_tolerance}};
    mj["value"] = std::isfinite(m.value) ? nlohmann::json(m.value) : nlohmann::json(nullptr);
    j["metrics"].push_back(mj);
  }
  j["steps"] = steps;
  j["wall_s"] = wall_s;
  j["particle_steps_per_s"] = particle_steps_per_s;
  j["threads"] = threads;
  j["stable"] = stable;
  if (!stable) j["failure"] = failure;
  j["options"] = options;
  j["series"] = nlohmann::json::array();
  for (const auto& s : series)
    j["series"].push_back({{"name", s.name}, {"role", s.role}, {"plot", s.plot}, {"xlabel", s.xlabel},
                           {"ylabel", s.ylabel}, {"x", s.x}, {"y", s.y}});
  if (!snapshot.is_null()) j["snapshot"] = snapshot;
  if (!provenance.is_null()) j["provenance"] = provenance;
  for (auto it = extra.begin(); it != extra.end(); ++it) j[it.key()] = it.value();
  return j;
}

}  // namespace geosph::verify
