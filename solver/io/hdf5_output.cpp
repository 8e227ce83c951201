#include "io/hdf5_output.hpp"

#include <hdf5.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace geosph {

namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5 error while writing " + what);
}

void write_dataset(hid_t file, const std::string& name, hid_t type, const void* data, hsize_t rows, hsize_t cols) {
  hsize_t dims[2] = {rows, cols};
  hid_t space = H5Screate_simple(cols > 1 ? 2 : 1, dims, nullptr);
  hid_t set = H5Dcreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) { H5Sclose(space); throw std::runtime_error("HDF5: cannot create dataset " + name); }
  check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
  H5Dclose(set);
  H5Sclose(space);
}

}  // namespace

Hdf5Output::Hdf5Output(std::filesystem::path dir) : dir_(std::move(dir)) { std::filesystem::create_directories(dir_); }

void Hdf5Output::write(const Particles& P, double time, long step) {
  char name[64];
  std::snprintf(name, sizeof name, "particles_%06zu.h5", entries_.size());
  const auto final_path = dir_ / name, tmp_path = dir_ / (std::string(name) + ".tmp");
  const std::size_t n = P.size();
  std::vector<double> xyz(3 * n), v(3 * n);
  std::vector<int> kind(n);
  for (std::size_t i = 0; i < n; ++i) {
    xyz[3 * i] = P.x[i]; xyz[3 * i + 1] = P.y[i]; xyz[3 * i + 2] = P.z[i];
    v[3 * i] = P.vx[i]; v[3 * i + 1] = P.vy[i]; v[3 * i + 2] = P.vz[i];
    kind[i] = static_cast<int>(P.kind[i]);
  }
  hid_t file = H5Fcreate(tmp_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("cannot create " + tmp_path.string());
  write_dataset(file, "position", H5T_NATIVE_DOUBLE, xyz.data(), n, 3);
  write_dataset(file, "velocity", H5T_NATIVE_DOUBLE, v.data(), n, 3);
  write_dataset(file, "density", H5T_NATIVE_DOUBLE, P.rho.data(), n, 1);
  write_dataset(file, "pressure", H5T_NATIVE_DOUBLE, P.p.data(), n, 1);
  write_dataset(file, "mass", H5T_NATIVE_DOUBLE, P.m.data(), n, 1);
  write_dataset(file, "kind", H5T_NATIVE_INT, kind.data(), n, 1);
  write_dataset(file, "id", H5T_NATIVE_INT64, P.id.data(), n, 1);
  std::vector<std::string> extra;
  for (const auto& [fname, f] : P.extra_fields()) {
    write_dataset(file, fname, H5T_NATIVE_DOUBLE, f.data(), n, 1);
    extra.push_back(fname);
  }
  std::vector<std::string> ints;
  for (const auto& [fname, f] : P.int_fields()) {
    write_dataset(file, fname, H5T_NATIVE_INT32, f.data(), n, 1);
    ints.push_back(fname);
  }
  hid_t aspace = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(file, "time", H5T_NATIVE_DOUBLE, aspace, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, H5T_NATIVE_DOUBLE, &time);
  H5Aclose(attr);
  hid_t sattr = H5Acreate2(file, "step", H5T_NATIVE_LONG, aspace, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(sattr, H5T_NATIVE_LONG, &step);
  H5Aclose(sattr);
  H5Sclose(aspace);
  check(H5Fclose(file), tmp_path.string());
  std::filesystem::rename(tmp_path, final_path);
  entries_.push_back({name, time, n, extra, ints});
  write_index();
}

void Hdf5Output::write_index() const {
  const auto tmp = dir_ / "particles.xdmf.tmp";
  {
    std::ofstream x(tmp);
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& e : entries_) {
      auto item = [&](const std::string& ds, int cols, const char* type, int prec) {
        x << "     <DataItem Dimensions=\"" << e.n << (cols > 1 ? " 3" : "") << "\" NumberType=\"" << type
          << "\" Precision=\"" << prec << "\" Format=\"HDF\">" << e.file << ":/" << ds << "</DataItem>\n";
      };
      x << "   <Grid Name=\"step\" GridType=\"Uniform\">\n    <Time Value=\"" << e.time << "\"/>\n"
        << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << e.n << "\"/>\n"
        << "    <Geometry GeometryType=\"XYZ\">\n";
      item("position", 3, "Float", 8);
      x << "    </Geometry>\n";
      auto attr = [&](const std::string& name, int cols, const char* type, int prec) {
        x << "    <Attribute Name=\"" << name << "\" AttributeType=\"" << (cols > 1 ? "Vector" : "Scalar")
          << "\" Center=\"Node\">\n";
        item(name, cols, type, prec);
        x << "    </Attribute>\n";
      };
      attr("velocity", 3, "Float", 8);
      attr("density", 1, "Float", 8);
      attr("pressure", 1, "Float", 8);
      attr("kind", 1, "Int", 4);
      attr("id", 1, "Int", 8);
      for (const auto& f : e.extra) attr(f, 1, "Float", 8);
      for (const auto& f : e.ints) attr(f, 1, "Int", 4);
      x << "   </Grid>\n";
    }
    x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  }
  std::filesystem::rename(tmp, dir_ / "particles.xdmf");
}

}  // namespace geosph
