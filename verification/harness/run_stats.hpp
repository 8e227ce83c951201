// Runs a case's simulation, timing it, and records speed and stability in the result record.
#pragma once
#include <functional>

#include "harness/case_config.hpp"
#include "harness/record.hpp"
#include "sim/simulation.hpp"

namespace geosph::verify {

// Runs to the scene's end time calling `observe` after every step. Fills steps, wall_s,
// particle_steps_per_s (fluid particles x steps / wall time), resolution and options; on a blow-up
// sets stable = false with the diagnosis and returns false.
bool run_timed(Simulation& sim, Record& rec, const std::function<void(const Simulation&)>& observe,
               bool progress, double until = -1);

// Runs `run_at` once per spacing of the requested level of case `name` (coarse to fine) and
// annotates the records with the observed order (and case.json's expected_order, if any).
std::vector<Record> run_each_spacing(const CaseContext& ctx, const std::string& name,
                                     const std::function<Record(const CaseConfig&, const CaseContext&, double)>& run_at);

// Runs `run_variant` for each entry of case.json's "variants" (in key order) at each spacing of the
// requested level (coarse to fine), or of the variant's own "levels" entry for it (CaseConfig::use_variant_level).
std::vector<Record> run_each_variant(
    const CaseContext& ctx, const std::string& name,
    const std::function<Record(const CaseConfig&, const CaseContext&, const std::string&, double)>& run_variant);

// Final particle snapshot (fluid only, at most max_points) coloured by pressure.
nlohmann::json pressure_snapshot(const Simulation& sim, std::size_t max_points = 6000);
// Snapshot of any moving-particle field ("pressure", "speed" or an optional field such as
// "plastic_strain"), of a simulation or of a particle set kept from one.
nlohmann::json field_snapshot(const Simulation& sim, const std::string& field, const std::string& units,
                              std::size_t max_points = 6000);
nlohmann::json field_snapshot(const Particles& P, const std::string& field, const std::string& units,
                              std::size_t max_points = 6000);

}  // namespace geosph::verify
