// Particle storage as structure of arrays. Every particle has the core fields below; a module
// that needs more (soil stress, wall ghost values, pore-water porosity...) creates a named optional
// field that it owns, so a scene only pays for the physics it declares. Optional fields are a typed
// registry: add_field/add_int_field create a field and record its owner (a module's name), field/
// int_field look one up and throw FieldError naming a missing one (a misspelt name never becomes a
// new zero field). Flags and indices are integer fields. Every field name is a constant of the
// module that owns it (e.g. SoilFields, SeepageFields, BodyFields).
#pragma once
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
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

// A field looked up that no module created, or created twice by different owners.
struct FieldError : std::logic_error {
  using std::logic_error::logic_error;
};

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

  // Creates the field (zero for every particle) owned by `owner`, or returns it if `owner` created it
  // already; throws FieldError if another module owns that name.
  std::vector<double>& add_field(std::string_view name, std::string_view owner);
  std::vector<std::int32_t>& add_int_field(std::string_view name, std::string_view owner);
  // Existing fields; FieldError naming the field (and the fields there are) if it was never created.
  std::vector<double>& field(std::string_view name);
  const std::vector<double>& field(std::string_view name) const;
  std::vector<std::int32_t>& int_field(std::string_view name);
  const std::vector<std::int32_t>& int_field(std::string_view name) const;
  // The field's data, or null when the scene has no such field (optional physics).
  const double* find(std::string_view name) const;
  const std::int32_t* find_int(std::string_view name) const;
  bool has_field(std::string_view name) const { return extra_.count(std::string(name)) != 0; }
  bool has_int_field(std::string_view name) const { return ints_.count(std::string(name)) != 0; }
  const std::map<std::string, std::vector<double>>& extra_fields() const { return extra_; }
  const std::map<std::string, std::vector<std::int32_t>>& int_fields() const { return ints_; }
  const std::string& owner(std::string_view name) const;

  // Reorder every field so that particle k becomes old particle order[k].
  void permute(const std::vector<std::uint32_t>& order);
  // Removes the particles whose `remove` flag is set (every field; order of the rest kept). Returns the count.
  std::size_t remove(const std::vector<char>& remove);
  // Appends the particles of `other` (same dimension): core fields, and every optional field of either
  // set (zero where a set lacks it; fields only `other` has keep its owner). Ids continue after the
  // largest id here, so they stay unique after removals.
  void append(const Particles& other);
  // Every field to n particles (new ones zero): a checkpoint of a run whose construction changed the count.
  void resize(std::size_t n);

  std::size_t count(Kind k) const;

 private:
  [[noreturn]] void missing(std::string_view name) const;
  void claim(std::string_view name, std::string_view owner);
  std::map<std::string, std::vector<double>> extra_;
  std::map<std::string, std::vector<std::int32_t>> ints_;
  std::map<std::string, std::string> owners_;
  std::vector<double> scratch_;
};

}  // namespace geosph
