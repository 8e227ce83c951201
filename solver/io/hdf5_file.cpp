#include "io/hdf5_file.hpp"

#include <hdf5.h>

namespace geosph {

namespace {

template <class T> hid_t native();
template <> hid_t native<double>() { return H5T_NATIVE_DOUBLE; }
template <> hid_t native<std::int64_t>() { return H5T_NATIVE_INT64; }
template <> hid_t native<std::int32_t>() { return H5T_NATIVE_INT32; }
template <> hid_t native<std::uint16_t>() { return H5T_NATIVE_UINT16; }
template <> hid_t native<std::uint8_t>() { return H5T_NATIVE_UINT8; }

template <class T>
void write_set(hid_t file, const std::filesystem::path& path, const std::string& name, const std::vector<T>& v,
               std::size_t cols) {
  hsize_t dims[2] = {v.size() / cols, cols};
  const hid_t space = H5Screate_simple(cols > 1 ? 2 : 1, dims, nullptr);
  const hid_t set = H5Dcreate2(file, name.c_str(), native<T>(), space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t st = set < 0 ? -1 : H5Dwrite(set, native<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  if (st < 0) throw Hdf5Error(path.string() + ": cannot write dataset " + name);
}

template <class T>
std::vector<T> read_set(hid_t file, const std::filesystem::path& path, const std::string& name) {
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (set < 0) throw Hdf5Error(path.string() + ": no dataset " + name);
  const hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  H5Sclose(space);
  std::vector<T> v(static_cast<std::size_t>(n < 0 ? 0 : n));
  const herr_t st = H5Dread(set, native<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Dclose(set);
  if (st < 0) throw Hdf5Error(path.string() + ": cannot read dataset " + name);
  return v;
}

void write_attr(hid_t file, const std::filesystem::path& path, const std::string& name, hid_t type, const void* v) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t st = a < 0 ? -1 : H5Awrite(a, type, v);
  if (a >= 0) H5Aclose(a);
  H5Sclose(space);
  if (st < 0) throw Hdf5Error(path.string() + ": cannot write attribute " + name);
}

void read_attr(hid_t file, const std::filesystem::path& path, const std::string& name, hid_t type, void* v) {
  const hid_t a = H5Aopen(file, name.c_str(), H5P_DEFAULT);
  const herr_t st = a < 0 ? -1 : H5Aread(a, type, v);
  if (a >= 0) H5Aclose(a);
  if (st < 0) throw Hdf5Error(path.string() + ": no attribute " + name);
}

herr_t collect(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->emplace_back(name);
  return 0;
}

}  // namespace

Hdf5File Hdf5File::create(const std::filesystem::path& path) {
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) throw Hdf5Error("cannot create " + path.string());
  return Hdf5File(id, path);
}

Hdf5File Hdf5File::open(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw Hdf5Error(path.string() + ": no such file");
  // Quietly: a file that is not HDF5 is reported by the exception, not by HDF5's error stack dump.
  H5E_auto2_t func = nullptr;
  void* data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  H5Eset_auto2(H5E_DEFAULT, func, data);
  if (id < 0) throw Hdf5Error(path.string() + ": not an HDF5 file (or unreadable)");
  return Hdf5File(id, path);
}

Hdf5File::~Hdf5File() {
  if (id_ >= 0) H5Fclose(id_);
}

void Hdf5File::close() {
  if (id_ < 0) return;
  const herr_t st = H5Fclose(id_);
  id_ = -1;
  if (st < 0) throw Hdf5Error("cannot close " + path_.string());
}

void Hdf5File::group(const std::string& name) {
  const hid_t g = H5Gcreate2(id_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) throw Hdf5Error(path_.string() + ": cannot create group " + name);
  H5Gclose(g);
}

void Hdf5File::write(const std::string& n, const std::vector<double>& v, std::size_t cols) { write_set(id_, path_, n, v, cols); }
void Hdf5File::write(const std::string& n, const std::vector<std::int64_t>& v) { write_set(id_, path_, n, v, 1); }
void Hdf5File::write(const std::string& n, const std::vector<std::int32_t>& v) { write_set(id_, path_, n, v, 1); }
void Hdf5File::write(const std::string& n, const std::vector<std::uint16_t>& v) { write_set(id_, path_, n, v, 1); }
void Hdf5File::write(const std::string& n, const std::vector<std::uint8_t>& v) { write_set(id_, path_, n, v, 1); }

void Hdf5File::attribute(const std::string& name, double v) { write_attr(id_, path_, name, H5T_NATIVE_DOUBLE, &v); }
void Hdf5File::attribute(const std::string& name, long v) { write_attr(id_, path_, name, H5T_NATIVE_LONG, &v); }
void Hdf5File::attribute(const std::string& name, const std::string& v) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, v.size() + 1);
  write_attr(id_, path_, name, type, v.c_str());
  H5Tclose(type);
}

bool Hdf5File::exists(const std::string& name) const { return H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0; }

std::vector<std::string> Hdf5File::members(const std::string& group) const {
  std::vector<std::string> names;
  if (H5Literate_by_name(id_, group.c_str(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names, H5P_DEFAULT) < 0)
    throw Hdf5Error(path_.string() + ": no group " + group);
  return names;
}

std::vector<double> Hdf5File::read_doubles(const std::string& n) const { return read_set<double>(id_, path_, n); }
std::vector<std::int64_t> Hdf5File::read_int64(const std::string& n) const { return read_set<std::int64_t>(id_, path_, n); }
std::vector<std::int32_t> Hdf5File::read_int32(const std::string& n) const { return read_set<std::int32_t>(id_, path_, n); }
std::vector<std::uint16_t> Hdf5File::read_uint16(const std::string& n) const { return read_set<std::uint16_t>(id_, path_, n); }
std::vector<std::uint8_t> Hdf5File::read_uint8(const std::string& n) const { return read_set<std::uint8_t>(id_, path_, n); }

double Hdf5File::attribute_double(const std::string& name) const {
  double v = 0;
  read_attr(id_, path_, name, H5T_NATIVE_DOUBLE, &v);
  return v;
}
long Hdf5File::attribute_long(const std::string& name) const {
  long v = 0;
  read_attr(id_, path_, name, H5T_NATIVE_LONG, &v);
  return v;
}
std::string Hdf5File::attribute_string(const std::string& name) const {
  const hid_t a = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
  if (a < 0) throw Hdf5Error(path_.string() + ": no attribute " + name);
  const hid_t type = H5Aget_type(a);
  std::string s(H5Tget_size(type), '\0');
  const herr_t st = H5Aread(a, type, s.data());
  H5Tclose(type);
  H5Aclose(a);
  if (st < 0) throw Hdf5Error(path_.string() + ": cannot read attribute " + name);
  s.resize(s.find('\0') == std::string::npos ? s.size() : s.find('\0'));
  return s;
}

}  // namespace geosph
