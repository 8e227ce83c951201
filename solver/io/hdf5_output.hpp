// Particle snapshots as HDF5 files (one per output time) plus an XDMF index that ParaView opens as
// a time series (Polyvertex topology). Files are written under a temporary name and renamed, so a
// reader never sees a half-written snapshot.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "core/particles.hpp"

namespace geosph {

class Hdf5Output {
 public:
  explicit Hdf5Output(std::filesystem::path dir);
  void write(const Particles& P, double time, long step);
  const std::filesystem::path& dir() const { return dir_; }
  std::size_t snapshots() const { return entries_.size(); }

 private:
  void write_index() const;
  struct Entry { std::string file; double time; std::size_t n; std::vector<std::string> extra, ints; };
  std::filesystem::path dir_;
  std::vector<Entry> entries_;
};

}  // namespace geosph
