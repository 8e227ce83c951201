// The `geosph` command:
//   geosph run SCENE.json --out DIR      simulate a scene, HDF5 + XDMF output
//   geosph verify [--case NAME] [--level quick|full] --out DIR   run catalogue cases, write result records
//   geosph info                          version, threads, catalogue
//   geosph scene-reference [--format markdown|json-schema]   the scene format (docs/scene-reference.md)
//   geosph stages SCENE.json             the time step's stages for that scene (sim/stages.hpp)
// Global options (--threads N) go before or after the subcommand. (the case folders found)
#include <CLI/CLI.hpp>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "harness/catalogue.hpp"
#include "io/hdf5_output.hpp"
#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "io/scene_reference.hpp"
#include "sim/progress.hpp"
#include "sim/simulation.hpp"

namespace fs = std::filesystem;
using namespace geosph;

namespace {

int cmd_run(const std::string& scene_path, const std::string& out_dir, bool quiet) {
  // Everything that can be wrong with the input is found before the output directory exists.
  Scene scene = load_scene(scene_path);
  Simulation sim(scene);
  Hdf5Output out(out_dir);
  std::fprintf(stderr, "geosph run: %s, %zu fluid + %zu soil + %zu structure + %zu wall particles, %s kernel, %d thread(s)\n",
               scene.name.c_str(), sim.fluid_count(), sim.soil_count(), sim.structure_count(),
               sim.particles().size() - sim.moving_count(), kernel_name(scene.kernel).c_str(), omp_get_max_threads());
  out.write(sim.particles(), sim.time(), sim.steps());
  double next_out = scene.output_interval > 0 ? scene.output_interval : 1e300;
  Progress bar(scene.t_end, !quiet);
  const auto t0 = std::chrono::steady_clock::now();
  int rc = 0;
  try {
    sim.run([&](const Simulation& s) {
      if (s.time() >= next_out * (1 - 1e-9)) {
        out.write(s.particles(), s.time(), s.steps());
        next_out += scene.output_interval;
      }
      bar.update(s.steps(), s.time());
    });
    if (scene.output_interval <= 0 || sim.time() > next_out - scene.output_interval + 1e-12)
      out.write(sim.particles(), sim.time(), sim.steps());
  } catch (const InstabilityError& e) {
    bar.finish(sim.steps(), sim.time());
    std::ofstream(fs::path(out_dir) / "diagnosis.txt") << e.what() << "\n";
    std::fprintf(stderr, "error: %s\n(diagnosis written to %s/diagnosis.txt; snapshots before the failure are kept)\n",
                 e.what(), out_dir.c_str());
    rc = 3;
  }
  bar.finish(sim.steps(), sim.time());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double rate = wall > 0 ? sim.moving_count() * static_cast<double>(sim.steps()) / wall : 0;
  nlohmann::json summary = {{"scene", scene.name}, {"steps", sim.steps()}, {"time", sim.time()}, {"wall_s", wall},
                            {"material_particles", sim.moving_count()}, {"particles", sim.particles().size()},
                            {"particle_steps_per_s", rate}, {"threads", omp_get_max_threads()},
                            {"snapshots", out.snapshots()}, {"stable", rc == 0}};
  std::ofstream(fs::path(out_dir) / "summary.json") << summary.dump(2) << "\n";
  std::fprintf(stderr, "%s: %ld steps to t = %.6g s in %.2f s wall, %.3g particle-steps/s, %zu snapshots in %s\n",
               rc == 0 ? "done" : "stopped", sim.steps(), sim.time(), wall, rate, out.snapshots(), out_dir.c_str());
  return rc;
}

int cmd_verify(const std::vector<std::string>& names, const std::string& level, const std::string& out_dir,
               bool progress) {
  verify::CaseContext ctx;
  ctx.data_dir = verify::default_data_dir();
  ctx.level = level;
  ctx.threads = omp_get_max_threads();
  ctx.progress = progress;
  // the catalogue: the case folders under the data dir (verification/cases/*/case.json)
  const auto catalogue = verify::discover_cases(ctx.data_dir);
  for (const auto& n : names) {
    if (std::none_of(catalogue.begin(), catalogue.end(), [&](const auto& c) { return c.name == n; })) {
      std::string all;
      for (const auto& c : catalogue) all += " " + c.name;
      throw InputError("--case: unknown case '" + n + "' (catalogue in " + (ctx.data_dir / "verification" / "cases").string() +
                       ":" + all + ")");
    }
  }
  std::vector<const verify::CaseEntry*> todo;
  for (const auto& c : catalogue) {
    if (!names.empty() && std::find(names.begin(), names.end(), c.name) == names.end()) continue;
    // without --case, a level that only some cases define (convergence) runs those cases
    if (names.empty() && !c.has_level(level)) {
      std::fprintf(stderr, "(%s has no '%s' level, skipped)\n", c.name.c_str(), level.c_str());
      continue;
    }
    todo.push_back(&c);
  }
  fs::create_directories(out_dir);
  int failed = 0, passed = 0, studies = 0;
  for (const auto* c : todo) {
    std::fprintf(stderr, "== %s (%s)\n", c->name.c_str(), level.c_str());
    const auto records = verify::run_case(*c, ctx);
    for (std::size_t k = 0; k < records.size(); ++k) {
      const auto& r = records[k];
      std::string file = c->name + "__" + level + (records.size() > 1 ? "__" + std::to_string(k) : "") + ".json";
      const auto tmp = fs::path(out_dir) / (file + ".tmp");
      std::ofstream(tmp) << r.to_json().dump(1) << "\n";
      fs::rename(tmp, fs::path(out_dir) / file);
      for (const auto& m : r.metrics)
        std::printf("%-18s dx=%-9.4g %-32s %-12.5g tol %-10.4g %s\n", c->name.c_str(), r.dx, m.name.c_str(), m.value,
                    m.tolerance, r.scored ? (m.passed ? "PASS" : "FAIL") : (m.passed ? "study: pass" : "study: fail"));
      std::printf("%-18s dx=%-9.4g %ld particles, %ld steps, %.2f s wall, %.3g particle-steps/s, %s%s\n",
                  c->name.c_str(), r.dx, r.particles, r.steps, r.wall_s, r.particle_steps_per_s,
                  r.stable ? "stable" : "UNSTABLE", r.scored ? "" : " (study, not scored)");
      if (!r.scored) ++studies;
      else (r.passed() ? passed : failed)++;
    }
  }
  std::printf("verify: %d passed, %d failed, %d unscored studies\n", passed, failed, studies);
  return failed == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"GeoSPH: SPH for geomaterials with a verification catalogue"};
  app.require_subcommand(1);
  app.fallthrough();  // the app's options (--threads) are accepted after the subcommand too
  int threads = 0;
  app.add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::NonNegativeNumber);

  auto* run = app.add_subcommand("run", "run a scene");
  std::string scene_path, out_dir;
  bool quiet = false;
  run->add_option("scene", scene_path, "scene file (JSON)")->required();
  run->add_option("--out", out_dir, "output directory (HDF5 snapshots + XDMF index)")->required();
  run->add_flag("--quiet", quiet, "no progress display");

  auto* ver = app.add_subcommand("verify", "run verification cases and write result records");
  std::vector<std::string> cases;
  std::string level = "quick", vout;
  bool vprogress = false;
  ver->add_option("--case", cases, "case name (repeatable; default: all)");
  ver->add_option("--level", level, "resolution level")->check(CLI::IsMember({"quick", "full", "convergence"}));
  ver->add_option("--out", vout, "directory for the result records")->required();
  ver->add_flag("--progress", vprogress, "show progress of each run");

  auto* info = app.add_subcommand("info", "version, threads and the verification catalogue");

  auto* ref = app.add_subcommand("scene-reference", "the scene format, from the modules' own declarations");
  std::string ref_format = "markdown";
  ref->add_option("--format", ref_format, "markdown or json-schema")->check(CLI::IsMember({"markdown", "json-schema"}));

  auto* stages = app.add_subcommand("stages", "the time step's stages for a scene, in order, with the fields each reads and writes");
  std::string stages_scene;
  stages->add_option("scene", stages_scene, "scene file (JSON)")->required();

  CLI11_PARSE(app, argc, argv);
  if (threads > 0) omp_set_num_threads(threads);
  try {
    if (*run) return cmd_run(scene_path, out_dir, quiet);
    if (*ver) return cmd_verify(cases, level, vout, vprogress);
    if (*ref) {
      if (ref_format == "markdown") std::printf("%s", scene_reference_markdown().c_str());
      else std::printf("%s\n", scene_reference_schema().dump(2).c_str());
      return 0;
    }
    if (*stages) {
      Simulation sim(load_scene(stages_scene));
      std::printf("%s", describe_stages(sim.stages()).c_str());
      return 0;
    }
    if (*info) {
      std::printf("GeoSPH 0.1.0\nOpenMP threads: %d\ndata dir: %s\ncatalogue:\n", omp_get_max_threads(),
                  verify::default_data_dir().c_str());
      for (const auto& c : verify::discover_cases(verify::default_data_dir()))
        std::printf("  %-28s driver %s\n", c.name.c_str(), c.driver.c_str());
      return 0;
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
