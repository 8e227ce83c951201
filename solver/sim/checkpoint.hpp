// Checkpoint and restart. A checkpoint is one HDF5 file holding every particle array and field, the
// run state (time, step, step length, the modules' running state: Simulation::run_state), the scene it
// came from (its text and hash), the output series written so far and the solver's provenance. It is
// written under a temporary name and renamed, so a crash while writing leaves the previous one intact.
// Restoring it into a Simulation built from the same scene continues the run bitwise as if it had not
// stopped (same build and thread count; verification/unit/test_restart.cpp).
#pragma once
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "core/provenance.hpp"
#include "sim/simulation.hpp"

namespace geosph {

// Bumped whenever the layout below changes; a checkpoint of another format is refused.
constexpr long kCheckpointFormat = 1;

struct CheckpointHeader {
  long format = 0;
  std::string solver_version, scene_hash, scene_name;
  double time = 0;
  long step = 0;
};

// `output`: what the run's output needs to continue (the series index and the next output time).
void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const Provenance& provenance,
                      const nlohmann::json& output);
// Throws InputError naming the file when it is not a GeoSPH checkpoint.
CheckpointHeader read_checkpoint_header(const std::filesystem::path& file);
// Restores particles and run state into `sim` (built from the same scene); returns the stored output
// data. Refused with an InputError naming the checkpoint when the format, the scene or the particle
// fields differ. A checkpoint of another solver commit is accepted with a warning on stderr (its
// continuation may differ in the last digits).
nlohmann::json restore_checkpoint(const std::filesystem::path& file, Simulation& sim);

// The newest checkpoint (highest step) in a run's output directory (DIR/checkpoints), or `path` itself
// when it is a file. Throws InputError when there is none.
std::filesystem::path find_checkpoint(const std::filesystem::path& path);
// DIR/checkpoints/checkpoint_<step>.h5, and removal of all but the newest `keep` there.
std::filesystem::path checkpoint_path(const std::filesystem::path& out_dir, long step);
void prune_checkpoints(const std::filesystem::path& out_dir, int keep);

}  // namespace geosph
