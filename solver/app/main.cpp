// The `geosph` command:
//   geosph run SCENE.json --out DIR      simulate a scene, HDF5 + XDMF output, checkpoints
//   geosph run SCENE.json --out DIR --restart DIR|CHECKPOINT   continue an interrupted run
//   geosph verify [--case NAME] [--level quick|full] [--walls T|all] --out DIR   run catalogue cases, write result records
//   geosph info                          version, threads, catalogue
//   geosph scene-reference [--format markdown|json-schema]   the scene format (docs/scene-reference.md)
//   geosph stages SCENE.json             the time step's stages for that scene (sim/stages.hpp)
// Global options (--threads N) go before or after the subcommand. (the case folders found)
#include <CLI/CLI.hpp>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "analysis/strength_reduction.hpp"
#include "boundary/wall_input.hpp"
#include "harness/catalogue.hpp"
#include "io/hdf5_output.hpp"
#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "io/scene_reference.hpp"
#include "sim/checkpoint.hpp"
#include "sim/progress.hpp"
#include "sim/simulation.hpp"

namespace fs = std::filesystem;
using namespace geosph;

namespace {

// The files a run writes into its output directory (io/hdf5_output.hpp, this file).
bool is_run_output(const fs::path& p) {
  const std::string f = p.filename().string();
  return f == "particles.xdmf" || f == "summary.json" || f == "diagnosis.txt" || f == "checkpoints" ||
         (f.rfind("particles_", 0) == 0 && (p.extension() == ".h5" || p.extension() == ".tmp"));
}

// An output directory that holds anything is refused (an earlier run's snapshots would mix with this
// run's); with --overwrite the files an earlier run wrote are removed first, other files are kept.
void prepare_output_dir(const fs::path& dir, bool overwrite) {
  if (!fs::exists(dir)) return;
  if (!fs::is_directory(dir)) throw InputError("--out " + dir.string() + ": exists and is not a directory");
  std::vector<fs::path> ours, others;
  for (const auto& e : fs::directory_iterator(dir)) (is_run_output(e.path()) ? ours : others).push_back(e.path());
  if (ours.empty() && others.empty()) return;
  if (!overwrite)
    throw InputError("--out " + dir.string() + ": the directory exists and is not empty (" +
                     std::to_string(ours.size() + others.size()) +
                     " entries); choose a new directory, or pass --overwrite to replace an earlier run's output");
  if (!others.empty() && ours.empty())
    throw InputError("--out " + dir.string() + ": --overwrite replaces an earlier run's output, but this directory "
                     "holds no GeoSPH output (first entry: " + others.front().filename().string() + ")");
  for (const auto& p : ours) fs::remove_all(p);
}

// SIGINT/SIGTERM: the run stops after the current step, writes a checkpoint and exits with
// kExitInterrupted; a second signal ends the process at once (the default action).
volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_signal(int sig) {
  g_signal = sig;
  std::signal(sig, SIG_DFL);
}

// Exit codes of `geosph run` (README): 0 done, 2 bad input, 3 unstable (diagnosis.txt), 4 interrupted
// with a checkpoint to restart from.
constexpr int kExitInterrupted = 4;

struct RunOptions {
  std::string scene, out, restart;
  bool quiet = false, overwrite = false;
  RunLimits limits;
  long checkpoint_every = 0;        // steps; 0: off
  double checkpoint_wall = 1800;    // wall seconds between checkpoints; 0: off
  int checkpoint_keep = 2;
  long stop_after = 0;              // stop (as interrupted) after this step; 0: off
};

int cmd_run(const RunOptions& o) {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  // Everything that can be wrong with the input is found before the output directory is touched.
  Scene scene = load_scene(o.scene);
  scene.limits = o.limits;
  Simulation sim(scene);
  const Provenance prov = provenance(scene.hash);
  double next_out = scene.output_interval > 0 ? scene.output_interval : 1e300;
  nlohmann::json stored_output;
  fs::path restarted_from;
  if (!o.restart.empty()) {
    restarted_from = find_checkpoint(o.restart);
    stored_output = restore_checkpoint(restarted_from, sim);
    for (const auto& e : stored_output.at("index"))
      if (!fs::exists(fs::path(o.out) / e.at("file").get<std::string>()))
        throw InputError("--out " + o.out + ": snapshot " + e.at("file").get<std::string>() + " of the run being restarted is "
                         "not there; --out must be the directory of the run that wrote " + restarted_from.string());
    next_out = stored_output.at("next_out").get<double>();
  } else {
    const GravityLoadingResult& gl = sim.settle_under_gravity();  // before anything is written
    if (gl.ran)
      std::fprintf(stderr, "gravity loading: settled in %.4g s (%ld steps), kinetic energy %.3g of its peak, unbalanced force %.3g of the weight\n",
                   gl.time, gl.steps, gl.peak_kinetic_energy > 0 ? gl.final_kinetic_energy / gl.peak_kinetic_energy : 0.0,
                   gl.final_force_ratio);
    prepare_output_dir(o.out, o.overwrite);
  }
  Hdf5Output out(o.out, prov);
  std::fprintf(stderr, "geosph run: %s, %zu fluid + %zu soil + %zu structure + %zu wall particles, %s kernel, %d thread(s)\n",
               scene.name.c_str(), sim.fluid_count(), sim.soil_count(), sim.structure_count(),
               sim.particles().size() - sim.moving_count(), kernel_name(scene.kernel).c_str(), omp_get_max_threads());
  for (std::size_t k = 0; k < sim.fills().size(); ++k) {  // the fill against the shape's own measure
    const BodyFill& f = sim.fills()[k];
    std::fprintf(stderr, "  bodies[%zu]: %zu particles, mass %.6g kg%s (density x %s %.6g: %+.2f%%)\n", k, f.particles, f.mass,
                 scene.dim == 2 ? "/m" : "", scene.dim == 2 ? "area" : "volume", f.shape_mass,
                 f.shape_mass > 0 ? 100.0 * (f.mass / f.shape_mass - 1.0) : 0.0);
    if (f.relaxation.iterations > 0)
      std::fprintf(stderr, "  bodies[%zu]: relaxed against the mirror walls in %d iterations, kernel-sum gradient h|sum V grad W| "
                   "mean %.3g -> %.3g, max %.3g -> %.3g\n", k, f.relaxation.iterations, f.relaxation.initial_mean,
                   f.relaxation.final_mean, f.relaxation.initial_residual, f.relaxation.final_residual);
  }
  if (restarted_from.empty()) {
    out.write(sim.particles(), sim.time(), sim.steps());
  } else {
    out.resume(stored_output.at("index"));
    std::fprintf(stderr, "restarted from %s at step %ld, t = %.9g s\n", restarted_from.c_str(), sim.steps(), sim.time());
  }
  const long first_step = sim.steps();
  fs::path last_checkpoint;
  const auto checkpoint = [&](const Simulation& s) {
    last_checkpoint = checkpoint_path(o.out, s.steps());
    write_checkpoint(last_checkpoint, s, prov, {{"index", out.index()}, {"next_out", next_out}});
    prune_checkpoints(o.out, o.checkpoint_keep);
  };
  Progress bar(scene.t_end, !o.quiet);
  const auto t0 = std::chrono::steady_clock::now();
  auto last_wall_checkpoint = t0;
  int rc = 0;
  bool interrupted = false;
  std::size_t events_logged = 0;
  try {
    sim.run([&](const Simulation& s) {
      for (; events_logged < s.construction_log().size(); ++events_logged) {  // construction stages as they happen
        const ConstructionEvent& e = s.construction_log()[events_logged];
        std::fprintf(stderr, "\nconstruction at t = %.6g s: %s: %zu particles removed, %zu added", e.time, e.what.c_str(),
                     e.removed, e.added);
        if (e.settle_steps > 0)
          std::fprintf(stderr, "; %s in %ld damped steps", e.settled ? "settled" : "NOT settled within gravity_loading.max_time",
                       e.settle_steps);
        std::fprintf(stderr, "\n");
      }
      if (s.time() >= next_out * (1 - 1e-9)) {
        out.write(s.particles(), s.time(), s.steps());
        next_out += scene.output_interval;
      }
      bar.update(s.steps(), s.time());
      const auto now = std::chrono::steady_clock::now();
      if (g_signal != 0 || (o.stop_after > 0 && s.steps() >= o.stop_after)) {
        interrupted = true;
        sim.request_stop();
      } else if ((o.checkpoint_every > 0 && s.steps() % o.checkpoint_every == 0) ||
                 (o.checkpoint_wall > 0 && std::chrono::duration<double>(now - last_wall_checkpoint).count() >= o.checkpoint_wall)) {
        checkpoint(s);
        last_wall_checkpoint = now;
      }
    });
    if (interrupted) {
      checkpoint(sim);
      rc = kExitInterrupted;
    } else if (scene.output_interval <= 0 || sim.time() > next_out - scene.output_interval + 1e-12) {
      out.write(sim.particles(), sim.time(), sim.steps());
    }
  } catch (const InstabilityError& e) {
    bar.finish(sim.steps(), sim.time());
    std::ofstream(fs::path(o.out) / "diagnosis.txt") << e.what() << "\nprovenance: " << prov.to_json().dump() << "\n";
    std::fprintf(stderr, "error: %s\n(diagnosis written to %s/diagnosis.txt; snapshots before the failure are kept)\n",
                 e.what(), o.out.c_str());
    rc = 3;
  }
  bar.finish(sim.steps(), sim.time());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const long steps = sim.steps() - first_step;
  const double rate = wall > 0 ? sim.moving_count() * static_cast<double>(steps) / wall : 0;
  nlohmann::json summary = {{"scene", scene.name}, {"steps", sim.steps()}, {"steps_this_run", steps}, {"time", sim.time()},
                            {"wall_s", wall}, {"material_particles", sim.moving_count()}, {"particles", sim.particles().size()},
                            {"particle_steps_per_s", rate}, {"threads", omp_get_max_threads()},
                            {"snapshots", out.snapshots()}, {"stable", rc != 3}, {"finished", rc == 0},
                            {"provenance", prov.to_json()}};
  if (!restarted_from.empty()) summary["restarted_from"] = restarted_from.string();
  if (!last_checkpoint.empty()) summary["last_checkpoint"] = last_checkpoint.string();
  {
    const auto tmp = fs::path(o.out) / "summary.json.tmp";
    std::ofstream(tmp) << summary.dump(2) << "\n";
    fs::rename(tmp, fs::path(o.out) / "summary.json");
  }
  if (rc == kExitInterrupted)
    std::fprintf(stderr, "interrupted at step %ld, t = %.9g s: checkpoint %s\n(continue with: geosph run %s --out %s --restart %s)\n",
                 sim.steps(), sim.time(), last_checkpoint.c_str(), o.scene.c_str(), o.out.c_str(), o.out.c_str());
  std::fprintf(stderr, "%s: %ld steps to t = %.6g s in %.2f s wall, %.3g particle-steps/s, %zu snapshots in %s\n",
               rc == 0 ? "done" : "stopped", steps, sim.time(), wall, rate, out.snapshots(), o.out.c_str());
  return rc;
}

// Strength reduction (analysis/strength_reduction.hpp): the factor of safety, every trial and the failure
// surface, written to OUT/strength_reduction.json (complete or not at all).
int cmd_ssr(const std::string& scene_file, const std::string& out_dir, const StrengthReductionOptions& o, bool snapshots) {
  if (!fs::exists(scene_file)) throw InputError(scene_file + ": cannot open scene file");
  const nlohmann::json scene = read_json_file(scene_file);
  const auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<Hdf5Output> trial_states;  // with --snapshots: each trial's end state, in the order run
  if (snapshots) {
    prepare_output_dir((fs::path(out_dir) / "trials").string(), true);
    trial_states = std::make_unique<Hdf5Output>(fs::path(out_dir) / "trials", provenance(content_hash(scene.dump())));
  }
  const StrengthReductionResult r = strength_reduction(scene, scene_file, o, [&](const StrengthReductionTrial& t, const Particles& P) {
    std::fprintf(stderr, "  F = %.4f: %s (%s), u95 %.3g m, %.3g s in %ld steps\n", t.factor, t.stable ? "stable" : "FAILED",
                 t.reason.c_str(), t.displacement, t.time, t.steps);
    if (trial_states) trial_states->write(P, t.factor, static_cast<long>(trial_states->snapshots()));
  });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  nlohmann::json trials = nlohmann::json::array(), surface = nlohmann::json::array();
  for (const auto& t : r.trials)
    trials.push_back({{"factor", t.factor}, {"stable", t.stable}, {"reason", t.reason}, {"time_s", t.time},
                      {"steps", t.steps}, {"u95_m", t.displacement}, {"kinetic_energy_ratio", t.kinetic_energy_ratio}});
  nlohmann::json band = nlohmann::json::array();
  for (const auto& p : r.failure_surface) surface.push_back({p[0], p[1]});
  for (const auto& p : r.plastic_band) band.push_back({p[0], p[1]});
  const nlohmann::json out = {{"scene", scene_file}, {"factor_of_safety", r.factor_of_safety}, {"f_stable", r.f_stable},
                              {"f_failed", r.f_failed}, {"tolerance", o.tolerance},
                              {"displacement_limit_m", o.displacement_limit}, {"trials", trials},
                              {"failure_surface", surface}, {"plastic_band", band}, {"wall_s", wall},
                              {"provenance", provenance(content_hash(scene.dump())).to_json()}};
  fs::create_directories(out_dir);
  const auto tmp = fs::path(out_dir) / "strength_reduction.json.tmp";
  std::ofstream(tmp) << out.dump(2) << "\n";
  fs::rename(tmp, fs::path(out_dir) / "strength_reduction.json");
  std::fprintf(stderr, "factor of safety %.4f (stable at %.4f, failed at %.4f), %zu trials in %.1f s; %s\n",
               r.factor_of_safety, r.f_stable, r.f_failed, r.trials.size(), wall,
               (fs::path(out_dir) / "strength_reduction.json").c_str());
  return 0;
}

// The wall treatments a case runs with under --walls: "" is the scene's own; "all" adds every other
// treatment its case.json "wall_treatments" lists (the boundary comparison); a single treatment runs
// the cases that list it.
std::vector<std::string> wall_runs(const verify::CaseEntry& c, const std::string& walls, bool named) {
  if (walls.empty()) return {""};
  const auto& listed = c.wall_treatments;
  if (walls == "all") {
    std::vector<std::string> runs = {""};
    for (const auto& t : listed)
      if (t != c.own_walls) runs.push_back(t);
    return runs;
  }
  if (std::find(listed.begin(), listed.end(), walls) == listed.end()) {
    if (!named) return {};
    std::string all;
    for (const auto& t : listed) all += (all.empty() ? "" : ", ") + t;
    throw InputError("--walls " + walls + ": case '" + c.name + "' is not compared with " + walls +
                     " walls (its case.json wall_treatments: " + (all.empty() ? "none" : all) + ")");
  }
  return {walls == c.own_walls ? "" : walls};
}

int cmd_verify(const std::vector<std::string>& names, const std::string& level, const std::string& out_dir,
               bool progress, const std::string& walls) {
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
  int failed = 0, passed = 0, studies = 0, known = 0;
  for (const auto* c : todo)
    for (const auto& treatment : wall_runs(*c, walls, !names.empty())) {
      ctx.walls = treatment;
      std::fprintf(stderr, "== %s (%s%s)\n", c->name.c_str(), level.c_str(),
                   treatment.empty() ? "" : (", " + treatment + " walls").c_str());
      const auto records = verify::run_case(*c, ctx);
      for (std::size_t k = 0; k < records.size(); ++k) {
        const auto& r = records[k];
        std::string file = c->name + "__" + level + (treatment.empty() ? "" : "__walls-" + treatment) +
                           (records.size() > 1 ? "__" + std::to_string(k) : "") + ".json";
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
        // --walls all: a treatment its case.json lists in open_wall_treatments is a known miss of the
        // comparison, reported but not a failure of the catalogue (ctest walls.<case>.<T> still fails)
        else if (!r.passed() && walls == "all" && r.extra.contains("wall_treatment_open")) ++known;
        else (r.passed() ? passed : failed)++;
      }
    }
  std::printf("verify: %d passed, %d failed, %d unscored studies", passed, failed, studies);
  if (known > 0) std::printf(", %d known misses of the wall comparison (case.json open_wall_treatments)", known);
  std::printf("\n");
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
  RunOptions ro;
  run->add_option("scene", ro.scene, "scene file (JSON)")->required();
  run->add_option("--out", ro.out, "output directory (HDF5 snapshots + XDMF index, checkpoints/)")->required();
  run->add_flag("--quiet", ro.quiet, "no progress display");
  run->add_flag("--overwrite", ro.overwrite, "replace an earlier run's output in --out (otherwise a non-empty --out is refused)");
  run->add_option("--max-particles", ro.limits.max_particles, "refuse scenes with more particles (estimated before allocating)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  run->add_option("--max-cells", ro.limits.max_cells, "refuse domains with more neighbour-search cells")
      ->capture_default_str()->check(CLI::PositiveNumber);
  run->add_option("--restart", ro.restart, "continue from a checkpoint file, or the newest in a run directory's checkpoints/")
      ->excludes("--overwrite");
  run->add_option("--checkpoint-every", ro.checkpoint_every, "write a checkpoint every N steps (0: off)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  run->add_option("--checkpoint-wall", ro.checkpoint_wall, "write a checkpoint every T seconds of wall time (0: off)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  run->add_option("--checkpoint-keep", ro.checkpoint_keep, "checkpoints kept (the newest)")
      ->capture_default_str()->check(CLI::Range(1, 1000));
  run->add_option("--stop-after-steps", ro.stop_after,
                  "stop after step N as if interrupted: checkpoint, exit code 4 (0: off)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);

  auto* ver = app.add_subcommand("verify", "run verification cases and write result records");
  std::vector<std::string> cases;
  std::string level = "quick", vout;
  bool vprogress = false;
  ver->add_option("--case", cases, "case name (repeatable; default: all)");
  ver->add_option("--level", level, "resolution level")->check(CLI::IsMember({"quick", "full", "convergence"}));
  ver->add_option("--out", vout, "directory for the result records")->required();
  ver->add_flag("--progress", vprogress, "show progress of each run");
  std::string vwalls;
  std::vector<std::string> wall_choices = wall_types();
  wall_choices.push_back("all");
  ver->add_option("--walls", vwalls,
                  "run the cases with this wall treatment instead of their own (those whose case.json lists it in "
                  "wall_treatments), or 'all': each case with its own and every treatment it lists")
      ->check(CLI::IsMember(wall_choices));

  auto* ssr = app.add_subcommand("ssr", "slope stability: factor of safety by shear strength reduction");
  std::string ssr_scene, ssr_out;
  StrengthReductionOptions so;
  ssr->add_option("scene", ssr_scene, "scene file (JSON) with a gravity_loading stage (model \"material\")")->required();
  ssr->add_option("--out", ssr_out, "directory for strength_reduction.json")->required();
  ssr->add_option("--f-low", so.f_low, "lower end of the bracket (must be stable)")->capture_default_str();
  ssr->add_option("--f-high", so.f_high, "upper end of the bracket (must fail)")->capture_default_str();
  ssr->add_option("--tolerance", so.tolerance, "bisection stops at this width of the bracket")->capture_default_str();
  bool ssr_snapshots = false;
  ssr->add_flag("--snapshots", ssr_snapshots, "write each trial's end state under OUT/trials/ (HDF5; its 'time' is the trial's F)");
  ssr->add_option("--displacement-limit", so.displacement_limit,
                  "m: a trial whose u95 (displacement passed by 5% of the soil) exceeds this has failed")
      ->capture_default_str();

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
    if (*run) return cmd_run(ro);
    if (*ver) return cmd_verify(cases, level, vout, vprogress, vwalls);
    if (*ssr) return cmd_ssr(ssr_scene, ssr_out, so, ssr_snapshots);
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
