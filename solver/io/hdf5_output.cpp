#include "io/hdf5_output.hpp"

#include <cstdio>
#include <fstream>

#include "io/hdf5_file.hpp"

namespace geosph {

namespace {

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string snapshot_name(std::size_t k) {
  char name[64];
  std::snprintf(name, sizeof name, "particles_%06zu.h5", k);
  return name;
}

}  // namespace

void write_provenance(Hdf5File& f, const Provenance& p) {
  f.attribute("solver_version", p.solver_version);
  f.attribute("compiler", p.compiler);
  f.attribute("build_flags", p.build_flags);
  f.attribute("threads", static_cast<long>(p.threads));
  f.attribute("scene_hash", p.scene_hash);
}

Hdf5Output::Hdf5Output(std::filesystem::path dir, Provenance provenance)
    : dir_(std::move(dir)), provenance_(std::move(provenance)) {
  std::filesystem::create_directories(dir_);
}

void Hdf5Output::write(const Particles& P, double time, long step) {
  const std::string name = snapshot_name(entries_.size());
  const auto final_path = dir_ / name, tmp_path = dir_ / (name + ".tmp");
  const std::size_t n = P.size();
  std::vector<double> xyz(3 * n), v(3 * n);
  std::vector<std::int32_t> kind(n);
  for (std::size_t i = 0; i < n; ++i) {
    xyz[3 * i] = P.x[i]; xyz[3 * i + 1] = P.y[i]; xyz[3 * i + 2] = P.z[i];
    v[3 * i] = P.vx[i]; v[3 * i + 1] = P.vy[i]; v[3 * i + 2] = P.vz[i];
    kind[i] = static_cast<std::int32_t>(P.kind[i]);
  }
  Entry e{name, time, n, {}, {}};
  {
    Hdf5File f = Hdf5File::create(tmp_path);
    f.write("position", xyz, 3);
    f.write("velocity", v, 3);
    f.write("density", P.rho);
    f.write("pressure", P.p);
    f.write("mass", P.m);
    f.write("kind", kind);
    f.write("id", P.id);
    for (const auto& [fname, field] : P.extra_fields()) {
      f.write(fname, field);
      e.extra.push_back(fname);
    }
    for (const auto& [fname, field] : P.int_fields()) {
      f.write(fname, field);
      e.ints.push_back(fname);
    }
    f.attribute("time", time);
    f.attribute("step", step);
    write_provenance(f, provenance_);
    f.close();
  }
  std::filesystem::rename(tmp_path, final_path);
  entries_.push_back(std::move(e));
  write_index();
}

nlohmann::json Hdf5Output::index() const {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& e : entries_) j.push_back({{"file", e.file}, {"time", e.time}, {"n", e.n}, {"extra", e.extra}, {"ints", e.ints}});
  return j;
}

void Hdf5Output::resume(const nlohmann::json& index) {
  entries_.clear();
  for (const auto& e : index)
    entries_.push_back({e.at("file").get<std::string>(), e.at("time").get<double>(), e.at("n").get<std::size_t>(),
                        e.at("extra").get<std::vector<std::string>>(), e.at("ints").get<std::vector<std::string>>()});
  for (std::size_t k = entries_.size();; ++k) {  // snapshots the interrupted run wrote after its checkpoint
    const auto p = dir_ / snapshot_name(k);
    std::filesystem::remove(dir_ / (snapshot_name(k) + ".tmp"));
    if (!std::filesystem::remove(p)) break;
  }
  write_index();
}

void Hdf5Output::write_index() const {
  const auto tmp = dir_ / "particles.xdmf.tmp";
  {
    std::ofstream x(tmp);
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n";
    const nlohmann::json prov = provenance_.to_json();
    for (const auto& [key, value] : prov.items())
      x << "  <Information Name=\"" << key << "\" Value=\""
        << xml_escape(value.is_string() ? value.get<std::string>() : value.dump()) << "\"/>\n";
    x << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
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
    if (!x) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, dir_ / "particles.xdmf");
}

}  // namespace geosph
