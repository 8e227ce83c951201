#include "sim/checkpoint.hpp"

#include <algorithm>
#include <cstdio>

#include "io/hdf5_file.hpp"
#include "io/hdf5_output.hpp"
#include "io/json_fields.hpp"

namespace geosph {

namespace {

// The core particle arrays of Particles, by name (every one is saved; none is derived on restore).
template <class P, class F>
void for_each_core_array(P& p, F&& f) {
  f("x", p.x); f("y", p.y); f("z", p.z);
  f("vx", p.vx); f("vy", p.vy); f("vz", p.vz);
  f("ax", p.ax); f("ay", p.ay); f("az", p.az);
  f("rho", p.rho); f("drho", p.drho); f("p", p.p); f("m", p.m);
}

std::vector<std::uint8_t> bytes(const std::string& s) { return {s.begin(), s.end()}; }
std::string text(const std::vector<std::uint8_t>& b) { return {b.begin(), b.end()}; }

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& why) {
  throw InputError(file.string() + ": cannot restart from this checkpoint: " + why);
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const Provenance& provenance,
                      const nlohmann::json& output) {
  std::filesystem::create_directories(file.parent_path());
  const auto tmp = std::filesystem::path(file.string() + ".tmp");
  {
    Hdf5File f = Hdf5File::create(tmp);
    f.attribute("format", kCheckpointFormat);
    write_provenance(f, provenance);  // its scene_hash is the scene's (provenance(scene.hash))
    f.attribute("scene_name", sim.scene().name);
    f.attribute("time", sim.time());
    f.attribute("step", sim.steps());
    f.write("scene_file", bytes(sim.scene().file));
    f.write("scene", bytes(sim.scene().source));
    f.write("output", bytes(output.dump()));
    const Particles& P = sim.particles();
    f.group("particles");
    for_each_core_array(P, [&](const char* name, const std::vector<double>& v) { f.write(std::string("particles/") + name, v); });
    std::vector<std::uint8_t> kind(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) kind[i] = static_cast<std::uint8_t>(P.kind[i]);
    f.write("particles/kind", kind);
    f.write("particles/id", P.id);
    f.write("particles/material", P.material);
    f.group("fields");
    for (const auto& [name, v] : P.extra_fields()) f.write("fields/" + name, v);
    f.group("int_fields");
    for (const auto& [name, v] : P.int_fields()) f.write("int_fields/" + name, v);
    f.group("run_state");
    for (const auto& [name, v] : sim.run_state()) f.write("run_state/" + name, v);
    f.close();
  }
  std::filesystem::rename(tmp, file);
}

CheckpointHeader read_checkpoint_header(const std::filesystem::path& file) {
  try {
    const Hdf5File f = Hdf5File::open(file);
    CheckpointHeader h;
    h.format = f.attribute_long("format");
    h.solver_version = f.attribute_string("solver_version");
    h.scene_hash = f.attribute_string("scene_hash");
    h.scene_name = f.attribute_string("scene_name");
    h.time = f.attribute_double("time");
    h.step = f.attribute_long("step");
    return h;
  } catch (const Hdf5Error& e) {
    throw InputError(file.string() + ": not a GeoSPH checkpoint (" + e.what() + ")");
  }
}

nlohmann::json restore_checkpoint(const std::filesystem::path& file, Simulation& sim) {
  const CheckpointHeader h = read_checkpoint_header(file);
  if (h.format != kCheckpointFormat)
    refuse(file, "its format is " + std::to_string(h.format) + ", this solver (" + solver_version() + ") reads format " +
                     std::to_string(kCheckpointFormat));
  if (h.scene_hash != sim.scene().hash)
    refuse(file, "it was written for another scene (\"" + h.scene_name + "\", hash " + h.scene_hash + "), not " +
                     sim.scene().file + " (hash " + sim.scene().hash + "); restart with the scene file the run began with");
  if (h.solver_version != solver_version())
    std::fprintf(stderr, "warning: %s was written by GeoSPH %s, this is %s: the continuation may differ in the last "
                 "digits from an uninterrupted run\n", file.c_str(), h.solver_version.c_str(), solver_version().c_str());
  try {
    const Hdf5File f = Hdf5File::open(file);
    Particles& P = sim.particles();
    std::size_t n = P.size();
    const auto sized = [&](auto v, const std::string& name) {
      if (v.size() != n)
        refuse(file, "'" + name + "' holds " + std::to_string(v.size()) + " particles, the scene " + std::to_string(n));
      return v;
    };
    // the same optional fields as the scene creates: a different set means another solver layout
    const auto names = [](const auto& fields) {
      std::vector<std::string> v;
      for (const auto& [name, _] : fields) v.push_back(name);
      return v;
    };
    const auto same_fields = [&](const std::string& group, const std::vector<std::string>& expected) {
      auto stored = f.members(group);
      std::sort(stored.begin(), stored.end());
      if (stored == expected) return;
      std::string missing, extra;
      for (const auto& e : expected)
        if (!std::binary_search(stored.begin(), stored.end(), e)) missing += " " + e;
      for (const auto& s : stored)
        if (!std::binary_search(expected.begin(), expected.end(), s)) extra += " " + s;
      refuse(file, group + " differ from what this solver creates for the scene (missing:" + (missing.empty() ? " none" : missing) +
                       "; not known:" + (extra.empty() ? " none" : extra) + ")");
    };
    same_fields("fields", names(P.extra_fields()));  // checked before anything of `sim` is overwritten
    same_fields("int_fields", names(P.int_fields()));
    if (sim.scene().has_construction()) {  // excavations and placed bodies change the count during the run
      n = f.read_uint8("particles/kind").size();
      P.resize(n);
    }
    for_each_core_array(P, [&](const char* name, std::vector<double>& v) {
      v = sized(f.read_doubles(std::string("particles/") + name), name);
    });
    const auto kind = sized(f.read_uint8("particles/kind"), "kind");
    for (std::size_t i = 0; i < n; ++i) P.kind[i] = static_cast<Kind>(kind[i]);
    P.id = sized(f.read_int64("particles/id"), "id");
    P.material = sized(f.read_uint16("particles/material"), "material");
    for (const auto& name : names(P.extra_fields())) P.field(name) = sized(f.read_doubles("fields/" + name), name);
    for (const auto& name : names(P.int_fields())) P.int_field(name) = sized(f.read_int32("int_fields/" + name), name);
    Simulation::RunState rs;
    for (const auto& name : f.members("run_state")) rs[name] = f.read_doubles("run_state/" + name);
    try {
      sim.restore_run_state(rs);
    } catch (const std::invalid_argument& e) {
      refuse(file, e.what());
    }
    return nlohmann::json::parse(text(f.read_uint8("output")));
  } catch (const Hdf5Error& e) {
    refuse(file, e.what());
  }
}

std::filesystem::path checkpoint_path(const std::filesystem::path& out_dir, long step) {
  char name[64];
  std::snprintf(name, sizeof name, "checkpoint_%010ld.h5", step);
  return out_dir / "checkpoints" / name;
}

namespace {
std::vector<std::filesystem::path> checkpoints_in(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> v;
  if (!std::filesystem::is_directory(dir)) return v;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (f.rfind("checkpoint_", 0) == 0 && e.path().extension() == ".h5") v.push_back(e.path());
  }
  std::sort(v.begin(), v.end());  // zero-padded step: name order is step order
  return v;
}
}  // namespace

std::filesystem::path find_checkpoint(const std::filesystem::path& path) {
  if (std::filesystem::is_regular_file(path)) return path;
  auto v = checkpoints_in(path / "checkpoints");
  if (v.empty()) v = checkpoints_in(path);
  if (v.empty()) throw InputError("--restart " + path.string() + ": no checkpoint file there (checkpoints/checkpoint_*.h5)");
  return v.back();
}

void prune_checkpoints(const std::filesystem::path& out_dir, int keep) {
  const auto v = checkpoints_in(out_dir / "checkpoints");
  for (std::size_t k = 0; k + static_cast<std::size_t>(keep) < v.size(); ++k) std::filesystem::remove(v[k]);
}

}  // namespace geosph
