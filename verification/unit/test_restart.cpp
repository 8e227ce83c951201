// Checkpoint/restart and reproducibility through the `geosph` command (issue 20): for a fluid, a
// soil, a two-phase and a soil-structure scene, a run stopped and restarted from a checkpoint writes
// the same snapshots, bit for bit, as the uninterrupted run (the series continues: no duplicated or
// missing snapshot), and a run with 2 threads the same as with 1. A run stopped by SIGTERM writes a
// checkpoint and exits with code 4; a checkpoint of another scene, or a file that is not one, is
// refused.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <hdf5.h>

#include "io/hdf5_file.hpp"
#include "io/scene.hpp"
#include "sim/checkpoint.hpp"
#include "test_scenes.hpp"

using nlohmann::json;
namespace fs = std::filesystem;
using geosph::Hdf5File;

namespace {

json fluid_scene() {  // a water column collapsing in a box
  return json::parse(R"({
    "name": "restart_fluid", "dimension": 2, "dx": 0.01,
    "domain": {"min": [-0.05, -0.05], "max": [0.45, 0.35]},
    "gravity": [0, -9.81], "time": {"end": 0.08}, "output": {"interval": 0.02},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20, "artificial_viscosity": 0.05,
                            "density_diffusion": 0.1}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0], "max": [0.1, 0.2], "initial": "hydrostatic"}],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [0.4, 0.3], "open": ["top"]}]}
  })");
}

json soil_scene() {  // a Drucker-Prager column collapsing
  json j = geosph::test::soil_column_scene(0.01);
  j["name"] = "restart_soil";
  j["time"]["end"] = 0.03;
  j["output"] = {{"interval", 0.01}};
  return j;
}

json two_phase_scene() {  // Terzaghi's column (verification/cases/terzaghi_consolidation), coarse and short
  return json::parse(R"({
    "name": "restart_two_phase", "dimension": 2, "dx": 0.05,
    "domain": {"min": [0, -0.25], "max": [0.5, 1.45], "periodic": ["x"]},
    "gravity": [0, 0], "time": {"end": 0.06}, "output": {"interval": 0.02},
    "materials": {
      "water": {"model": "tait_fluid", "density": 1000, "sound_speed": 50, "artificial_viscosity": 0.1,
                "density_diffusion": 0.1, "density_diffusion_hydrostatic": true},
      "clay": {"model": "linear_elastic", "density": 1590, "young_modulus": 185700.0, "poisson_ratio": 0.3,
               "porosity": 0.4, "hydraulic_conductivity": 0.01}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0], "max": [0.5, 1.0]},
               {"material": "clay", "shape": "box", "min": [0, 0], "max": [0.5, 1.0],
                "surcharge": {"pressure": 1250, "ramp": 0.02}}],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [0.5, 1.2], "open": ["top"]}]},
    "numerics": {"kernel_gradient_correction": true}
  })");
}

// A soil column under a deformable block, held by a retreating rigid plate whose foot reaches below
// the ground (as in rankine_active: a plate ending on the ground surface meets the soil's corner
// row at its own corner, where the contact has no single normal).
json structure_scene() {
  json j = geosph::test::soil_column_scene(0.01);
  j["name"] = "restart_structure";
  j["time"]["end"] = 0.03;
  j["output"] = {{"interval", 0.01}};
  j["materials"]["block"] = {{"model", "linear_elastic"}, {"density", 2000}, {"young_modulus", 2e6}, {"poisson_ratio", 0.3}};
  j["bodies"].push_back({{"material", "block"}, {"shape", "box"}, {"min", {0.05, 0.1}}, {"max", {0.15, 0.13}},
                         {"structure", true}, {"interface_friction_angle", 20}});
  j["bodies"].push_back({{"material", "block"}, {"shape", "box"}, {"min", {0.2, -0.05}}, {"max", {0.22, 0.12}},
                         {"structure", true}, {"interface_friction_angle", 10},
                         {"motion", {{"velocity", {0.05, 0.0}}, {"angular_velocity", -0.5}, {"ramp", 0.01}}}});
  return j;
}

struct CliRun {
  int code;
  std::string err;
};

CliRun run_geosph(const std::string& args, const fs::path& log) {
  const std::string cmd = std::string(GEOSPH_EXE) + " " + args + " --quiet 2> " + log.string();
  const int status = std::system(cmd.c_str());
  std::stringstream s;
  s << std::ifstream(log).rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, s.str()};
}

std::vector<std::string> snapshots(const fs::path& dir) {
  std::vector<std::string> v;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".h5") v.push_back(e.path().filename().string());
  std::sort(v.begin(), v.end());
  return v;
}

// Every dataset of every snapshot, and each snapshot's time and step, bit for bit.
void expect_same_series(const fs::path& a, const fs::path& b) {
  const auto sa = snapshots(a), sb = snapshots(b);
  ASSERT_EQ(sa, sb) << a << " vs " << b;
  ASSERT_GE(sa.size(), 3u);
  for (const auto& f : sa) {
    const Hdf5File A = Hdf5File::open(a / f), B = Hdf5File::open(b / f);
    EXPECT_EQ(A.attribute_long("step"), B.attribute_long("step")) << f;
    EXPECT_EQ(A.attribute_double("time"), B.attribute_double("time")) << f;
    const auto names = A.members("/");
    ASSERT_EQ(names, B.members("/")) << f;
    for (const auto& n : names) {
      const auto x = A.read_doubles(n), y = B.read_doubles(n);  // integer datasets convert exactly
      ASSERT_EQ(x.size(), y.size()) << f << ":" << n;
      EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << f << ":/" << n << " differs";
    }
  }
}

fs::path fresh(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("geosph_restart_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Uninterrupted (1 thread) vs stopped after `stop` steps and restarted from the periodic checkpoint
// at `every` steps (so the restarted run must also drop the snapshots written after it), vs 2 threads.
void check_restart_and_threads(const json& scene, long every, long stop) {
  const std::string name = scene["name"];
  const fs::path d = fresh(name);
  std::ofstream(d / "scene.json") << scene.dump(1);
  const std::string sc = (d / "scene.json").string();
  const CliRun whole = run_geosph("--threads 1 run " + sc + " --out " + (d / "whole").string(), d / "whole.log");
  ASSERT_EQ(whole.code, 0) << whole.err;
  const CliRun stopped = run_geosph("--threads 1 run " + sc + " --out " + (d / "restarted").string() + " --checkpoint-every " +
                                 std::to_string(every) + " --stop-after-steps " + std::to_string(stop),
                             d / "stopped.log");
  ASSERT_EQ(stopped.code, 4) << stopped.err;
  char ck[64];
  std::snprintf(ck, sizeof ck, "checkpoint_%010ld.h5", every);
  ASSERT_TRUE(fs::exists(d / "restarted" / "checkpoints" / ck)) << stopped.err;
  const CliRun restarted = run_geosph("--threads 1 run " + sc + " --out " + (d / "restarted").string() + " --restart " +
                                   (d / "restarted" / "checkpoints" / ck).string(),
                               d / "restart.log");
  ASSERT_EQ(restarted.code, 0) << restarted.err;
  expect_same_series(d / "whole", d / "restarted");
  const CliRun two = run_geosph("--threads 2 run " + sc + " --out " + (d / "two_threads").string(), d / "two.log");
  ASSERT_EQ(two.code, 0) << two.err;
  expect_same_series(d / "whole", d / "two_threads");
}

}  // namespace

TEST(Restart, FluidContinuesBitwiseAndThreadsAgree) { check_restart_and_threads(fluid_scene(), 100, 170); }
TEST(Restart, SoilContinuesBitwiseAndThreadsAgree) { check_restart_and_threads(soil_scene(), 100, 170); }
// The stress update recomputes the switch's f before each momentum pass reads it; the checkpoint's copy
// keeps the snapshots' field, which expect_same_series compares.
TEST(Restart, SoilWithViscositySwitchContinuesBitwise) {
  json j = soil_scene();
  j["name"] = "restart_soil_switch";
  j["materials"]["sand"]["artificial_viscosity_switch"] = "balsara";
  check_restart_and_threads(j, 100, 170);
}
TEST(Restart, TwoPhaseContinuesBitwiseAndThreadsAgree) { check_restart_and_threads(two_phase_scene(), 100, 170); }
TEST(Restart, StructureContinuesBitwiseAndThreadsAgree) { check_restart_and_threads(structure_scene(), 100, 170); }
// The total Lagrangian block's reference positions travel in the checkpoint; its bonds are rebuilt from them.
TEST(Restart, TotalLagrangianStructureContinuesBitwiseAndThreadsAgree) {
  json j = structure_scene();
  j["name"] = "restart_structure_tl";
  j["materials"]["tl_block"] = j["materials"]["block"];
  j["materials"]["tl_block"]["formulation"] = "total_lagrangian";
  j["bodies"][1]["material"] = "tl_block";
  check_restart_and_threads(j, 100, 170);
}

// SIGTERM mid-run: exit code 4, a checkpoint, an index naming only complete snapshots; the restart
// finishes the run with the uninterrupted run's last snapshot.
TEST(Restart, SigtermWritesACheckpointAndTheRunResumes) {
  const fs::path d = fresh("sigterm");
  json scene = fluid_scene();
  scene["dx"] = 0.005;
  scene["time"]["end"] = 0.3;
  scene["output"]["interval"] = 0.05;
  std::ofstream(d / "scene.json") << scene.dump(1);
  const std::string sc = (d / "scene.json").string();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string out = (d / "run").string(), log = (d / "run.log").string();
    std::freopen(log.c_str(), "w", stderr);
    execl(GEOSPH_EXE, GEOSPH_EXE, "--threads", "1", "run", sc.c_str(), "--out", out.c_str(), "--quiet", nullptr);
    _exit(127);
  }
  // the first snapshot is written after the signal handlers are installed: signal once it exists
  // (a signal during start-up, on a loaded machine, would meet the default action)
  for (int k = 0; k < 600 && !fs::exists(d / "run" / "particles_000000.h5"); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  std::stringstream log;
  log << std::ifstream(d / "run.log").rdbuf();
  ASSERT_TRUE(WIFEXITED(status)) << log.str();
  ASSERT_EQ(WEXITSTATUS(status), 4) << "the run ended before the signal, or not by it: " << log.str();
  ASSERT_TRUE(fs::exists(d / "run" / "checkpoints")) << log.str();
  std::stringstream xdmf;
  xdmf << std::ifstream(d / "run" / "particles.xdmf").rdbuf();
  for (const auto& f : snapshots(d / "run"))  // the index names every complete snapshot and nothing else
    EXPECT_NE(xdmf.str().find(f + ":/position"), std::string::npos) << f;
  const CliRun resumed = run_geosph("--threads 1 run " + sc + " --out " + (d / "run").string() + " --restart " + (d / "run").string(),
                             d / "resume.log");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const CliRun whole = run_geosph("--threads 1 run " + sc + " --out " + (d / "whole").string(), d / "whole.log");
  ASSERT_EQ(whole.code, 0) << whole.err;
  expect_same_series(d / "whole", d / "run");
}

TEST(Restart, CheckpointOfAnotherSceneOrNotACheckpointIsRefused) {
  const fs::path d = fresh("refused");
  json scene = fluid_scene();
  std::ofstream(d / "a.json") << scene.dump(1);
  scene["materials"]["water"]["sound_speed"] = 25;
  std::ofstream(d / "b.json") << scene.dump(1);
  const CliRun a = run_geosph("run " + (d / "a.json").string() + " --out " + (d / "run").string() + " --stop-after-steps 20",
                       d / "a.log");
  ASSERT_EQ(a.code, 4) << a.err;
  const CliRun b = run_geosph("run " + (d / "b.json").string() + " --out " + (d / "run").string() + " --restart " + (d / "run").string(),
                       d / "b.log");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("it was written for another scene"), std::string::npos) << b.err;
  std::ofstream(d / "fake.h5") << "not hdf5";
  const CliRun c = run_geosph("run " + (d / "a.json").string() + " --out " + (d / "run").string() + " --restart " +
                           (d / "fake.h5").string(), d / "c.log");
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("fake.h5: not a GeoSPH checkpoint"), std::string::npos) << c.err;
}

// In process: a checkpoint whose format number differs from this solver's is refused with a message
// naming the file and both formats (the attribute is rewritten here as an older solver would have
// left it).
TEST(Restart, CheckpointOfAnotherFormatIsRefused) {
  const fs::path d = fresh("format");
  geosph::Simulation sim(geosph::parse_scene(fluid_scene(), "fluid.json"));
  const fs::path file = d / "checkpoint.h5";
  geosph::write_checkpoint(file, sim, geosph::provenance(sim.scene().hash), {{"index", json::array()}, {"next_out", 0.02}});
  geosph::Simulation same(geosph::parse_scene(fluid_scene(), "fluid.json"));
  EXPECT_NO_THROW(geosph::restore_checkpoint(file, same));
  {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hid_t a = H5Aopen(f, "format", H5P_DEFAULT);
    const long other = geosph::kCheckpointFormat + 98;
    H5Awrite(a, H5T_NATIVE_LONG, &other);
    H5Aclose(a);
    H5Fclose(f);
  }
  try {
    geosph::restore_checkpoint(file, same);
    ADD_FAILURE() << "a checkpoint of another format was accepted";
  } catch (const geosph::InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("checkpoint.h5: cannot restart from this checkpoint: its format is " +
                       std::to_string(geosph::kCheckpointFormat + 98)), std::string::npos) << msg;
  }
}
