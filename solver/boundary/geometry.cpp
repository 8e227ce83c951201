#include "boundary/geometry.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include <map>

#include "boundary/body_fields.hpp"
#include "boundary/drained_face.hpp"
#include "boundary/mirror_relaxation.hpp"
#include "boundary/wall_surface.hpp"
#include "geometry/lattice_fill.hpp"
#include "core/time_step.hpp"
#include "fluid/equation_of_state.hpp"
#include "soil/soil_fields.hpp"

namespace geosph {

int wall_layers(const Scene& s) {
  return s.walls.layers > 0 ? s.walls.layers : static_cast<int>(std::ceil(s.support() / s.dx - 1e-9));
}

namespace {

// A wall particle's depth behind the wall surface and the unit normal towards the fluid
// (boundary/wall_surface.hpp), on the particle just added.
void set_surface_geometry(Particles& P, double depth, const double n[3], bool corner = false) {
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  P.add_field(WallSurfaceFields::depth, WallSurfaceFields::owner).back() = depth;
  P.add_int_field(WallSurfaceFields::corner, WallSurfaceFields::owner).back() = corner ? 1 : 0;
  const char* names[3] = {BodyFields::wall_nx, BodyFields::wall_ny, BodyFields::wall_nz};
  for (int a = 0; a < 3; ++a) P.add_field(names[a], BodyFields::owner).back() = len > 0 ? n[a] / len : 0.0;
}

// Lattice points lo + (i + 1/2) dx covering [lo, hi) on every axis.
template <class F>
void lattice(int dim, std::array<double, 3> lo, std::array<double, 3> hi, double dx, F&& f) {
  std::array<long, 3> n{1, 1, 1};
  for (int a = 0; a < dim; ++a) n[a] = std::max(0L, std::lround((hi[a] - lo[a]) / dx));
  for (long k = 0; k < n[2]; ++k)
    for (long j = 0; j < n[1]; ++j)
      for (long i = 0; i < n[0]; ++i)
        f(lo[0] + (i + 0.5) * dx, lo[1] + (j + 0.5) * dx, dim == 3 ? lo[2] + (k + 0.5) * dx : 0.0);
}

// The body's particle positions: the box lattice, or the lattice points inside its shape.
std::vector<geometry::Point> body_points(const Scene& s, const BodySpec& b) {
  if (b.shape) return geometry::fill_lattice(*b.shape, s.dx);
  std::vector<geometry::Point> pts;
  lattice(s.dim, b.lo, b.hi, s.dx, [&](double x, double y, double z) { pts.push_back({x, y, z}); });
  return pts;
}

// Area (2D) or volume (3D) of the body.
double body_measure(const Scene& s, const BodySpec& b) {
  if (b.shape) return geometry::measure(*b.shape, s.dx);
  double v = 1;
  for (int a = 0; a < s.dim; ++a) v *= b.hi[a] - b.lo[a];
  return v;
}

// Height (y in 2D, z in 3D) of the body's top surface above each particle: the box's top, or for a
// shaped body the top particle of its lattice column plus dx/2 (the overburden of sloping ground).
std::vector<double> column_tops(const Scene& s, const BodySpec& b, const std::vector<geometry::Point>& pts) {
  const int up = s.dim - 1;
  std::vector<double> top(pts.size(), b.hi[up]);
  if (!b.shape) return top;
  std::map<std::pair<long, long>, double> highest;
  auto column = [&](const geometry::Point& p) {
    return std::make_pair(std::lround(p[0] / s.dx - 0.5), up == 2 ? std::lround(p[1] / s.dx - 0.5) : 0L);
  };
  for (const auto& p : pts) {
    auto [it, fresh] = highest.try_emplace(column(p), p[up]);
    if (!fresh) it->second = std::max(it->second, p[up]);
  }
  for (std::size_t i = 0; i < pts.size(); ++i) top[i] = highest[column(pts[i])] + 0.5 * s.dx;
  return top;
}

// Soil body on the lattice. "geostatic": vertical stress -rho g depth and horizontal K0 times it
// (tension positive), K0 = nu/(1 - nu) unless given (elastic lateral confinement); "isotropic":
// sigma = -pressure I (saturated soil: effective stresses, from the buoyant weight). A model with state
// fields initialises them from this stress (materials/solid_model.hpp: initialise).
// Structure bodies are built the same way (at rest) as Kind::Structure, or Kind::RigidStructure when
// their motion is prescribed, and carry their body number + 1 in the field "structure_body".
BodyFill add_soil_body(Particles& P, const Scene& s, const BodySpec& b, std::size_t body_index) {
  std::uint16_t mat = 0;
  while (s.soils[mat].name != b.material) ++mat;
  const SoilMaterial& m = s.soils[mat];
  const double vol = std::pow(s.dx, s.dim);
  const int up = s.dim - 1;  // gravity acts along -y (2D) or -z (3D); checked in validate_scene
  const double g = -s.gravity[up] * s.initial_gravity_factor();  // geostatic state at the gravity of t = 0
  const double k0 = b.k0 > 0 ? b.k0 : m.poisson_ratio() / (1.0 - m.poisson_ratio());
  const bool geostatic = b.initial == "geostatic", isotropic = b.initial == "isotropic";
  // saturated soil: the effective stress carries the buoyant weight (rho_d - (1 - n0) rho_w) g
  const double rho_geo = m.saturated() && s.has_fluid() ? m.density - (1.0 - m.porosity) * s.materials.front().density
                                                        : m.density;
  const auto pts = body_points(s, b);
  const auto tops = column_tops(s, b, pts);
  for (std::size_t q = 0; q < pts.size(); ++q) {
    const double x = pts[q][0], y = pts[q][1], z = pts[q][2];
    const Kind kind = !b.structure ? Kind::Soil : b.motion.active ? Kind::RigidStructure : Kind::Structure;
    P.add(x, y, z, m.density * vol, m.density, kind, mat);
    if (b.structure) P.add_int_field(BodyFields::structure_body, BodyFields::owner).back() = static_cast<std::int32_t>(body_index + 1);
    if (b.fixed) P.add_int_field(BodyFields::fixed, BodyFields::owner).back() = 1;
    else { P.vx.back() = b.velocity[0]; P.vy.back() = b.velocity[1]; P.vz.back() = b.velocity[2]; }
    if (b.surcharge.pressure > 0 && (up == 1 ? y : z) > tops[q] - s.dx) {  // top row carries the surcharge
      P.add_field(BodyFields::surcharge, BodyFields::owner).back() = b.surcharge.pressure;
      P.add_field(BodyFields::surcharge_ramp, BodyFields::owner).back() = b.surcharge.ramp;
    }
    const std::size_t i = P.size() - 1;
    if (geostatic) {
      const double depth = tops[q] - (up == 1 ? y : z);
      const double sv = -rho_geo * g * depth;
      P.add_field(SoilFields::xx, SoilFields::owner)[i] = k0 * sv;
      P.add_field(up == 1 ? SoilFields::yy : SoilFields::zz, SoilFields::owner)[i] = sv;
      P.add_field(up == 1 ? SoilFields::zz : SoilFields::yy, SoilFields::owner)[i] = k0 * sv;
      P.p[i] = -(1.0 + 2.0 * k0) * sv / 3.0;
    } else if (isotropic) {
      for (const char* f : {SoilFields::xx, SoilFields::yy, SoilFields::zz}) P.add_field(f, SoilFields::owner)[i] = -b.pressure;
      P.p[i] = b.pressure;
    }
    std::visit([&](const auto& model) {  // the model's own state (e.g. Modified Cam Clay's p_c)
      if (model.state_fields.empty()) return;
      const materials::SolidState st = m.bind_state(P);
      const auto stress = [&](const char* f) { const double* s = P.find(f); return s ? s[i] : 0.0; };
      const Eigen::Matrix3d sigma =
          Eigen::Vector3d(stress(SoilFields::xx), stress(SoilFields::yy), stress(SoilFields::zz)).asDiagonal();
      model.initialise(sigma, b, st, i);
    }, m.model);
  }
  return {pts.size(), m.density * vol * static_cast<double>(pts.size()), m.density * body_measure(s, b), {}};
}

std::uint16_t fluid_material_index(const Scene& s, const BodySpec& b) {
  std::uint16_t mat = 0;
  while (s.materials[mat].name != b.material) ++mat;
  return mat;
}

// Fluid body on the lattice: at rest (rho0) or in the Tait hydrostatic state below its highest point.
BodyFill add_fluid_body(Particles& P, const Scene& s, const BodySpec& b) {
  const double vol = std::pow(s.dx, s.dim);
  const std::uint16_t mat = fluid_material_index(s, b);
  const TaitEos eos(s.materials[mat]);
  const auto pts = body_points(s, b);
  double mass = 0;
  for (const auto& pt : pts) {
    const double x = pt[0], y = pt[1], z = pt[2];
    const double rho = fluid_initial_density(s, b, x, y, z);
    P.add(x, y, z, rho * vol, rho, Kind::Fluid, mat);
    mass += rho * vol;
    P.vx.back() = b.velocity[0]; P.vy.back() = b.velocity[1]; P.vz.back() = b.velocity[2];
    P.p.back() = eos.pressure(rho);
  }
  return {pts.size(), mass, eos.rho0 * body_measure(s, b), {}};
}

}  // namespace

double fluid_initial_density(const Scene& s, const BodySpec& b, double x, double y, double z) {
  const TaitEos eos(s.materials[fluid_material_index(s, b)]);
  const double gmag = std::sqrt(s.gravity[0] * s.gravity[0] + s.gravity[1] * s.gravity[1] + s.gravity[2] * s.gravity[2]);
  if (b.initial != "hydrostatic" || !(gmag > 0)) return eos.rho0;
  // depth below the body's highest point, measured along gravity
  double top = 1e300;
  for (int c = 0; c < (1 << s.dim); ++c) {
    double proj = 0;
    for (int a = 0; a < s.dim; ++a) proj += (c >> a & 1 ? b.hi[a] : b.lo[a]) * s.gravity[a];
    top = std::min(top, proj);
  }
  const double depth = (x * s.gravity[0] + y * s.gravity[1] + z * s.gravity[2] - top) / gmag;
  return eos.density(eos.hydrostatic_pressure(gmag * s.initial_gravity_factor(), depth));
}

Particles build_particles(const Scene& s, std::vector<BodyFill>* fills, std::vector<Particles>* placed) {
  Particles P;
  P.dim = s.dim;
  const double vol = std::pow(s.dx, s.dim);

  for (std::size_t bi = 0; bi < s.bodies.size(); ++bi) {
    const BodySpec& b = s.bodies[bi];
    Particles later;  // a body placed during the run (construction) is built apart
    later.dim = s.dim;
    Particles& into = b.placed_at > 0 ? later : P;
    const std::size_t first = into.size();
    BodyFill f = s.find_soil(b.material) ? add_soil_body(into, s, b, bi) : add_fluid_body(into, s, b);
    if (s.walls.type == "mirror" && b.shape && !s.find_soil(b.material))
      f.relaxation = relax_body_against_mirror_walls(s, b, into, first, into.size() - first);
    if (fills) fills->push_back(f);
    if (b.placed_at > 0 && placed) placed->push_back(std::move(later));
  }

  // mirror walls have no particles: their images are made at every step (boundary/mirror_wall.hpp)
  if (s.walls.type == "mirror") return P;
  const int L = wall_layers(s);
  const Kind wall = s.walls.type == "repulsive" ? Kind::RepulsiveWall : Kind::DummyWall;
  // Morris and ghost walls need each wall particle's place relative to the surface
  const bool surface = s.walls.type == "morris" || s.walls.type == "ghost";
  const double rho0 = s.has_fluid() ? s.materials.front().density : s.soils.front().density;
  const std::vector<DrainedFace> drained = drained_faces(s);
  for (std::size_t ck = 0; ck < s.walls.containers.size(); ++ck) {
    const auto& c = s.walls.containers[ck];
    auto is_open = [&](const char* side) { return std::find(c.open.begin(), c.open.end(), side) != c.open.end(); };
    std::array<double, 3> lo = c.lo, hi = c.hi;
    for (int a = 0; a < s.dim; ++a) {
      if (s.domain.periodic[a]) continue;
      if (!is_open(container_side(s.dim, a, false))) lo[a] -= L * s.dx;
      if (!is_open(container_side(s.dim, a, true))) hi[a] += L * s.dx;
    }
    // Repulsive walls (Monaghan 1994) are a single line of particles, the first lattice layer outside the
    // faces: dx from the fluid's first row, the force's range r0, so that the fluid starts at rest. (On
    // the faces themselves, dx/2 from the fluid, the first row started deep inside the range and a corner
    // particle left at 5 c0 in the first step.)
    const int layers = wall == Kind::RepulsiveWall ? 1 : L;
    lattice(s.dim, lo, hi, s.dx, [&](double x, double y, double z) {
      const double q[3] = {x, y, z};
      int outside_axes = 0;
      bool in_layers = true;
      for (int a = 0; a < s.dim; ++a) {
        if (q[a] < c.lo[a] || q[a] > c.hi[a]) {
          ++outside_axes;
          const double dist = q[a] < c.lo[a] ? c.lo[a] - q[a] : q[a] - c.hi[a];
          in_layers = in_layers && dist < layers * s.dx;
        }
      }
      if (outside_axes == 0 || !in_layers) return;
      P.add(x, y, z, rho0 * vol, rho0, wall, 0);
      if (s.mixed_wall_slip())
        P.add_int_field(BodyFields::wall_free_slip, BodyFields::owner).back() = c.slip == "free_slip" ? 1 : 0;
      if (s.has_soil()) {
        std::int32_t axes = 0;
        for (int a = 0; a < s.dim; ++a)
          if (q[a] < c.lo[a] || q[a] > c.hi[a]) axes |= 1 << a;
        P.add_int_field(BodyFields::wall_mirror_axes, BodyFields::owner).back() = axes;
      }
      if (!drained.empty())
        if (const std::int32_t f = drained_face_of(s, drained, ck, q))
          P.add_int_field(DrainedFields::face, DrainedFields::owner).back() = f;
      // the depth behind the nearest point of the container's inner box, and the direction to it (a
      // corner particle's diagonal)
      if (surface) {
        double n[3] = {0, 0, 0}, d2 = 0;
        for (int a = 0; a < s.dim; ++a) {
          n[a] = std::clamp(q[a], c.lo[a], c.hi[a]) - q[a];
          d2 += n[a] * n[a];
        }
        set_surface_geometry(P, std::sqrt(d2), n, outside_axes > 1);
      }
    });
  }
  // Solid blocks of wall particles (a clamp, an obstacle) on the same lattice.
  // They are marked in the optional field "wall_block" (block index + 1): a block holds what is embedded
  // in it (a clamp), so its particles keep their own velocity instead of mirroring the material's.
  for (std::size_t k = 0; k < s.walls.blocks.size(); ++k) {
    const auto& b = s.walls.blocks[k];
    const double f = smooth_start(0.0, b.ramp);  // a ramped block starts at rest (Simulation::step)
    lattice(s.dim, b.lo, b.hi, s.dx, [&](double x, double y, double z) {
      P.add(x, y, z, rho0 * vol, rho0, wall, 0);
      if (s.mixed_wall_slip())
        P.add_int_field(BodyFields::wall_free_slip, BodyFields::owner).back() = s.walls.slip == "free_slip" ? 1 : 0;
      P.add_int_field(BodyFields::wall_block, BodyFields::owner).back() = static_cast<std::int32_t>(k + 1);
      P.vx.back() = f * b.velocity[0]; P.vy.back() = f * b.velocity[1]; P.vz.back() = f * b.velocity[2];
      // the depth below the block's nearest face and that face's outward normal
      const double q[3] = {x, y, z};
      double depth = INFINITY;
      int axis = 0;
      double sign = 0;
      for (int a = 0; a < s.dim; ++a)
        for (const double side : {-1.0, 1.0}) {
          const double d = side < 0 ? q[a] - b.lo[a] : b.hi[a] - q[a];
          if (d < depth) { depth = d; axis = a; sign = side; }
        }
      if (s.has_soil()) P.add_int_field(BodyFields::wall_mirror_axes, BodyFields::owner).back() = 1 << axis;
      if (surface) {
        double n[3] = {0, 0, 0};
        n[axis] = sign;
        set_surface_geometry(P, depth, n);
      }
    });
  }
  // Walls of any shape: the lattice points of the solid within the wall layers of its surface, each with
  // the surface's outward normal (the gradient of the distance). A repulsive wall is one line of
  // particles dx/2 inside the solid: the points of the first layer moved there along the normal, none
  // closer than dx/2 to another. (A box container's line lies on its faces, its fluid dx/2 from them;
  // a shaped body's lattice reaches the surface itself, so the line keeps that dx/2 gap behind it.)
  for (const auto& b : s.walls.boundaries) {
    const std::size_t first = P.size();
    std::vector<geometry::Point> pts = geometry::fill_lattice(*b.shape, s.dx, (wall == Kind::RepulsiveWall ? 1 : L) * s.dx);
    if (wall == Kind::RepulsiveWall) {
      std::vector<geometry::Point> on_surface;
      // the kept points by cell of size dx/2: a point closer than dx/2 lies in a neighbouring cell
      std::map<std::array<long, 3>, std::vector<std::size_t>> cells;
      const auto cell_of = [&](const geometry::Point& q) {
        return std::array<long, 3>{std::lround(std::floor(q[0] / (0.5 * s.dx))), std::lround(std::floor(q[1] / (0.5 * s.dx))),
                                   std::lround(std::floor(q[2] / (0.5 * s.dx)))};
      };
      for (const auto& p : pts) {
        const geometry::Point n = geometry::outward_normal(*b.shape, p, 1e-3 * s.dx);
        const double d = b.shape->distance(p);
        const double move = -0.5 * s.dx - d;  // along the outward normal, to the distance -dx/2
        geometry::Point q{p[0] + move * n[0], p[1] + move * n[1], p[2] + move * n[2]};
        const auto c = cell_of(q);
        bool crowded = false;
        for (long i = -1; i <= 1 && !crowded; ++i)
          for (long j = -1; j <= 1 && !crowded; ++j)
            for (long k = -1; k <= 1 && !crowded; ++k) {
              const auto it = cells.find({c[0] + i, c[1] + j, c[2] + k});
              if (it == cells.end()) continue;
              for (const std::size_t o : it->second) {
                double r2 = 0;
                for (int a = 0; a < 3; ++a) r2 += (q[a] - on_surface[o][a]) * (q[a] - on_surface[o][a]);
                crowded = crowded || r2 < 0.25 * s.dx * s.dx;
              }
            }
        if (crowded) continue;
        cells[c].push_back(on_surface.size());
        on_surface.push_back(q);
      }
      pts = std::move(on_surface);
    }
    for (const auto& p : pts) {
      P.add(p[0], p[1], p[2], rho0 * vol, rho0, wall, 0);
      if (s.mixed_wall_slip())
        P.add_int_field(BodyFields::wall_free_slip, BodyFields::owner).back() = b.slip == "free_slip" ? 1 : 0;
    }
    for (const char* f : {BodyFields::wall_nx, BodyFields::wall_ny, BodyFields::wall_nz}) P.add_field(f, BodyFields::owner);
    double* n[3] = {P.field(BodyFields::wall_nx).data(), P.field(BodyFields::wall_ny).data(),
                    P.field(BodyFields::wall_nz).data()};
    double* depth = surface ? P.add_field(WallSurfaceFields::depth, WallSurfaceFields::owner).data() : nullptr;
    for (std::size_t i = first; i < P.size(); ++i) {
      const geometry::Point nrm = geometry::outward_normal(*b.shape, {P.x[i], P.y[i], P.z[i]}, 1e-3 * s.dx);
      for (int a = 0; a < 3; ++a) n[a][i] = nrm[a];
      if (depth) depth[i] = std::max(0.0, -b.shape->distance({P.x[i], P.y[i], P.z[i]}));
    }
  }
  return P;
}

}  // namespace geosph
