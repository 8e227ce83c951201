// A thin owner of an HDF5 file for the snapshots and checkpoints: datasets of doubles and integers
// (1D, or rows x 3), scalar attributes (double, integer, string) and groups, every failure an
// exception naming the file and the object. The C API is wrapped here once so that the writers
// hold no handle bookkeeping.
#pragma once
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace geosph {

struct Hdf5Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Hdf5File {
 public:
  static Hdf5File create(const std::filesystem::path& path);  // truncates
  static Hdf5File open(const std::filesystem::path& path);    // read only
  Hdf5File(Hdf5File&& o) noexcept : id_(o.id_), path_(std::move(o.path_)) { o.id_ = -1; }
  Hdf5File(const Hdf5File&) = delete;
  ~Hdf5File();
  void close();  // flushes; throws on failure (the destructor only closes)

  void group(const std::string& name);
  // rows x cols values (cols 1: a 1D dataset)
  void write(const std::string& name, const std::vector<double>& v, std::size_t cols = 1);
  void write(const std::string& name, const std::vector<std::int64_t>& v);
  void write(const std::string& name, const std::vector<std::int32_t>& v);
  void write(const std::string& name, const std::vector<std::uint16_t>& v);
  void write(const std::string& name, const std::vector<std::uint8_t>& v);
  void attribute(const std::string& name, double v);
  void attribute(const std::string& name, long v);
  void attribute(const std::string& name, const std::string& v);

  bool exists(const std::string& name) const;
  std::vector<std::string> members(const std::string& group) const;  // names in a group
  std::vector<double> read_doubles(const std::string& name) const;
  std::vector<std::int64_t> read_int64(const std::string& name) const;
  std::vector<std::int32_t> read_int32(const std::string& name) const;
  std::vector<std::uint16_t> read_uint16(const std::string& name) const;
  std::vector<std::uint8_t> read_uint8(const std::string& name) const;
  double attribute_double(const std::string& name) const;
  long attribute_long(const std::string& name) const;
  std::string attribute_string(const std::string& name) const;
  const std::filesystem::path& path() const { return path_; }

 private:
  Hdf5File(long long id, std::filesystem::path p) : id_(id), path_(std::move(p)) {}
  long long id_;
  std::filesystem::path path_;
};

}  // namespace geosph
