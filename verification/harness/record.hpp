// A case's result record (schema in shared/design.md and reports/geosph_report/records.py): the
// only thing reports and convergence studies read.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace geosph::verify {

struct Metric {
  std::string name;
  double value = 0;
  double tolerance = 0;
  bool passed = false;
  std::string why_tolerance;
};

struct Series {
  std::string name, role, plot, xlabel, ylabel;  // role: simulation | experiment | analytical | dem
  std::vector<double> x, y;
};

struct Record {
  std::string case_name, title, level, variant;
  nlohmann::json reference = nlohmann::json::object();
  double dx = 0;
  long particles = 0, wall_particles = 0;
  int dimension = 2;
  std::vector<Metric> metrics;
  long steps = 0;
  double wall_s = 0, particle_steps_per_s = 0;
  int threads = 1;
  bool stable = true;
  // false for a study run whose outcome is reported but not judged (e.g. a hard case with its
  // stabilisation switched off, for the stability table): it neither passes nor fails the catalogue
  bool scored = true;
  nlohmann::json failure;  // {step, time, message} when unstable
  nlohmann::json options = nlohmann::json::object();
  nlohmann::json extra = nlohmann::json::object();  // merged into the record (e.g. expected_order)
  std::vector<Series> series;
  nlohmann::json snapshot;  // {x, y, field, values, units}
  // solver version, compiler and flags, threads, hash of the case's input files (core/provenance.hpp)
  nlohmann::json provenance;

  // value <= tolerance passes; a metric of an unstable run is recorded as failing
  void add_metric(const std::string& name, double value, double tolerance, const std::string& why);
  bool passed() const;
  nlohmann::json to_json() const;
};

}  // namespace geosph::verify
