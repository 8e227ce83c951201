// Particle snapshots as HDF5 files (one per output time) plus an XDMF index that ParaView opens as
// a time series (Polyvertex topology). Files are written under a temporary name and renamed, so a
// reader never sees a half-written snapshot, and the index is rewritten (also via rename) after each
// snapshot, so at every moment it names only complete files. Each snapshot and the index carry the
// run's provenance (core/provenance.hpp).
#pragma once
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "core/provenance.hpp"

namespace geosph {

class Hdf5File;
// The provenance as attributes of the file's root (solver_version, compiler, build_flags, threads,
// scene_hash); snapshots and checkpoints carry them.
void write_provenance(Hdf5File& f, const Provenance& p);

class Hdf5Output {
 public:
  Hdf5Output(std::filesystem::path dir, Provenance provenance);
  void write(const Particles& P, double time, long step);
  const std::filesystem::path& dir() const { return dir_; }
  std::size_t snapshots() const { return entries_.size(); }
  // The series so far (stored in a checkpoint), and its continuation after a restart: the entries of
  // `index` are kept, snapshot files written after them (by the run that was interrupted) removed.
  nlohmann::json index() const;
  void resume(const nlohmann::json& index);

 private:
  void write_index() const;
  struct Entry { std::string file; double time; std::size_t n; std::vector<std::string> extra, ints; };
  std::filesystem::path dir_;
  Provenance provenance_;
  std::vector<Entry> entries_;
};

}  // namespace geosph
