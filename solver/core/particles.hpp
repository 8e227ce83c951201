// Particle storage as structure of arrays. Every particle has the core fields below; a module
// that needs more (e.g. extrapolated wall velocity, or later soil stress) adds a named optional
// field, so a scene only pays for the physics it declares.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace geosph {

// Structure: a deformable structure body (its own SPH solid, in contact with soil);
// RigidStructure: a structure body whose motion is prescribed (translated/rotated at a set rate).
enum class Kind : std::uint8_t { Fluid = 0, DummyWall = 1, RepulsiveWall = 2, Soil = 3, Structure = 4, RigidStructure = 5 };

inline bool is_wall(Kind k) { return k == Kind::DummyWall || k == Kind::RepulsiveWall; }
// particles the integrator moves (material particles); walls and rigid structures are moved kinematically
inline bool is_moving(Kind k) { return k == Kind::Fluid || k == Kind::Soil || k == Kind::Structure; }
// particles that carry a stress tensor integrated by the solid mechanics (soil/soil_forces.hpp)
inline bool is_solid(Kind k) { return k == Kind::Soil || k == Kind::Structure; }
inline bool is_structure(Kind k) { return k == Kind::Structure || k == Kind::RigidStructure; }

struct Particles {
  int dim = 2;
  // core fields
  std::vector<double> x, y, z;     // position [m]
  std::vector<double> vx, vy, vz;  // velocity [m/s]
  std::vector<double> ax, ay, az;  // acceleration [m/s^2]
  std::vector<double> rho, drho;   // density [kg/m^3] and its rate
  std::vector<double> p;           // pressure [Pa]
  std::vector<double> m;           // mass [kg]
  std::vector<Kind> kind;
  std::vector<std::int64_t> id;    // original index, kept through reordering
  std::vector<std::uint16_t> material;  // index into the scene's material list

  std::size_t size() const { return x.size(); }
  void add(double px, double py, double pz, double mass, double density, Kind k, std::uint16_t mat);

  // Optional fields, allocated on first request, permuted with the core fields.
  std::vector<double>& field(const std::string& name);
  bool has_field(const std::string& name) const { return extra_.count(name) != 0; }
  const std::map<std::string, std::vector<double>>& extra_fields() const { return extra_; }

  // Reorder every field so that particle k becomes old particle order[k].
  void permute(const std::vector<std::uint32_t>& order);

  std::size_t count(Kind k) const;

 private:
  std::map<std::string, std::vector<double>> extra_;
  std::vector<double> scratch_;
};

}  // namespace geosph
