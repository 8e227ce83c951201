#include "io/scene.hpp"

#include <algorithm>
#include <cmath>

#include "boundary/body_input.hpp"
#include "boundary/geometry.hpp"
#include "boundary/wall_input.hpp"
#include "sim/construction.hpp"
#include "sim/gravity_loading.hpp"
#include "geometry/lattice_fill.hpp"
#include "io/json_fields.hpp"
#include "io/json_file.hpp"
#include "core/provenance.hpp"
#include "io/scene_reference.hpp"
#include "materials/model_list.hpp"

namespace geosph {

namespace {

bool is_solid_material(const Scene& s, const std::string& name) {
  for (const auto& m : s.soils)
    if (m.name == name) return true;
  return false;
}

// The scene's own sections (the top level, kernel, domain, time, output, numerics) for the scene
// reference; the materials, bodies and walls are declared by the modules that read them.
const bool documented_top = register_section(
    {"scene", "(top level)", "One simulation: its resolution, domain, gravity, time, materials, bodies and walls.",
     {{"name", FieldType::Text, "any", "required", "-", "the scene's name (in outputs and records)"},
      {"dimension", FieldType::Integer, "2 or 3", "required", "-", "2D (plane strain) or 3D", Range::between(2, 3)},
      number_doc("dx", Range::positive(), "required", "m", "particle spacing of the lattice"),
      {"kernel", FieldType::Object, "see kernel", "wendland_c2", "-", "the SPH kernel"},
      {"domain", FieldType::Object, "see domain", "required", "-", "the box every particle stays in"},
      {"gravity", FieldType::Vector, "dimension numbers", "[0, 0(, 0)]", "m/s^2", "gravitational acceleration"},
      {"body_force", FieldType::Vector, "dimension numbers", "[0, 0(, 0)]", "m/s^2",
       "extra acceleration on every material particle (e.g. a pressure gradient driving a periodic flow)"},
      {"time", FieldType::Object, "see time", "required", "-", "end time and step control"},
      {"output", FieldType::Object, "see output", "first and last state", "-", "HDF5 snapshots (geosph run)"},
      {"numerics", FieldType::Object, "see numerics", "defaults", "-", "sorting, blow-up bound, corrections"},
      {"materials", FieldType::Object, "name -> material", "required", "-", "the materials by name (see materials)"},
      {"bodies", FieldType::Objects, "see bodies", "required", "-", "the bodies filled with particles"},
      {"walls", FieldType::Object, "see walls", "none", "-", "wall particles"},
      {"gravity_loading", FieldType::Object, "see gravity_loading", "none", "-",
       "a gravity-loading stage before t = 0 (solids settle under their weight)"},
      {"excavations", FieldType::Objects, "see excavations", "none", "-",
       "excavation stages: regions of soil and fluid removed at set times"}}});

const bool documented_kernel = register_section(
    {"kernel", "kernel", "The SPH smoothing kernel and its smoothing length h.",
     {choice_doc("type", {"cubic_spline", "wendland_c2", "quintic_spline"}, "required", "kernel function"),
      number_doc("h_over_dx", Range::between(0.8, 3.0), "cubic_spline 1.3, wendland_c2 1.6, quintic_spline 1.0", "-", "h / dx")}});

const bool documented_domain = register_section(
    {"domain", "domain", "The domain box: a particle leaving it stops the run with a diagnosis.",
     {{"min", FieldType::Vector, "dimension numbers", "required", "m", "lower corner"},
      {"max", FieldType::Vector, "dimension numbers, > min", "required", "m", "upper corner"},
      {"periodic", FieldType::Texts, "from {x, y, z}", "[]", "-",
       "periodic axes (length a whole number of dx and at least 3 kernel supports)"}}});

const bool documented_time = register_section(
    {"time", "time", "End time and the time-step limits (CFL, force and viscous conditions).",
     {number_doc("end", Range::positive(), "required", "s", "simulated time"),
      number_doc("cfl", Range{0, 1, true, false}, "0.2", "-", "acoustic (CFL) factor on h / c_max"),
      number_doc("force_factor", Range{0, 1, true, false}, "0.25", "-", "factor on sqrt(h / a_max)"),
      number_doc("viscous_factor", Range{0, 0.5, true, false}, "0.125", "-", "factor on h^2 / nu"),
      {"max_steps", FieldType::Integer, "in [1, 2000000000]", "100000000", "-", "step limit",
       Range::between(1, 2e9)},
      number_doc("gravity_ramp", Range::non_negative(), "0", "s", "gravity grows smoothly over this time (<= end)"),
      number_doc("gravity_ramp_from", Range{0, 1, false, true}, "0", "-",
                 "fraction of the gravity at t = 0 when ramped (initial states use it)")}});

const bool documented_output = register_section(
    {"output", "output", "Snapshots written by geosph run (HDF5 + XDMF index).",
     {number_doc("interval", Range::non_negative(), "0 (first and last state only)", "s", "time between snapshots")}});

const bool documented_numerics = register_section(
    {"numerics", "numerics", "Numerical settings.",
     {{"reorder_every", FieldType::Integer, "in [0, 100000]", "20", "-",
       "steps between sorting particles by cell (0: never)", Range::between(0, 100000)},
      number_doc("max_density_variation", Range{0, 10, true, false}, "0.5", "-",
                 "|rho/rho0 - 1| beyond this stops the run as a blow-up"),
      number_doc("pair_list_skin", Range{0, 1, false, false}, "0.1", "kernel supports",
                 "reach of the Verlet pair list beyond the kernel support, rebuilt when a particle has moved "
                 "half of it (0: no list, every query scans the cells)"),
      {"kernel_gradient_correction", FieldType::Boolean, "true, false", "false", "-",
       "solids: corrected velocity gradient (Bonet & Lok 1999), exact for linear fields at free surfaces"},
      {"kernel_gradient_correction_stress", FieldType::Boolean, "true, false (true needs kernel_gradient_correction)",
       "false", "-",
       "solids: the stress divergence with the corrected kernel gradient on both sides of each pair, "
       "(S_i B_i^-T + S_j B_j^-T) . grad W (linear momentum conserved): a free strip carries its waves at the "
       "plate velocity (case elastic_strip_wave)"}}});

const bool documented_materials = register_section(
    {"materials", "materials.<name>", "A material by name; its \"model\" decides the other fields.",
     {choice_doc("model", [] {
        std::vector<std::string> m = fluid_model_names();
        for (const auto& s : solid_model_names()) m.push_back(s);
        return m;
      }(), "required", "the constitutive model (its section below: materials:<model> or materials:solid:<model>)")}});

}  // namespace

Scene parse_scene(const nlohmann::json& j, const std::string& file) {
  Scene s;
  s.file = file;
  s.source = j.dump();  // canonical: keys sorted, no whitespace or comments
  s.hash = content_hash(s.source);
  JsonFields top(j, file, "");
  top.section("scene");
  s.name = top.text("name");
  s.dim = static_cast<int>(top.integer("dimension", 2, 3));
  s.dx = top.number("dx", Range::positive());
  const int d = s.dim;

  if (auto k = top.optional_object("kernel")) {
    k->section("kernel");
    const std::string kname = k->choice("type", {"cubic_spline", "wendland_c2", "quintic_spline"});
    s.kernel = kernel_from_name(kname);
    s.h_over_dx = k->number("h_over_dx", Range::between(0.8, 3.0), default_h_over_dx(s.kernel));
    k->reject_unknown();
  } else {
    s.h_over_dx = default_h_over_dx(s.kernel);
  }

  auto dom = top.object("domain");
  dom.section("domain");
  s.domain.dim = d;
  s.domain.lo = dom.vector("min", d);
  s.domain.hi = dom.vector("max", d);
  for (const auto& a : dom.texts("periodic", {"x", "y", "z"})) {
    if (a[0] - 'x' >= d) dom.fail("periodic", "axis '" + a + "' does not exist in " + std::to_string(d) + "D");
    s.domain.periodic[a[0] - 'x'] = true;
  }
  for (int a = 0; a < d; ++a)
    if (!(s.domain.hi[a] > s.domain.lo[a])) dom.fail("max", "must be greater than domain.min on every axis");
  dom.reject_unknown();

  s.gravity = top.vector("gravity", d, {0, 0, 0});
  s.body_force = top.vector("body_force", d, {0, 0, 0});

  auto t = top.object("time");
  t.section("time");
  s.t_end = t.number("end", Range::positive());
  s.cfl = t.number("cfl", Range{0, 1, true, false}, 0.2);
  s.force_factor = t.number("force_factor", Range{0, 1, true, false}, 0.25);
  s.viscous_factor = t.number("viscous_factor", Range{0, 0.5, true, false}, 0.125);
  s.max_steps = t.integer("max_steps", 1, 2000000000L, 100000000L);
  s.gravity_ramp = t.number("gravity_ramp", Range::non_negative(), 0.0);
  s.gravity_ramp_from = t.number("gravity_ramp_from", Range{0, 1, false, true}, 0.0);
  t.reject_unknown();

  if (auto o = top.optional_object("output")) {
    o->section("output");
    s.output_interval = o->number("interval", Range::non_negative(), 0.0);
    o->reject_unknown();
  }
  if (auto n = top.optional_object("numerics")) {
    n->section("numerics");
    s.reorder_every = static_cast<int>(n->integer("reorder_every", 0, 100000, 20));
    s.max_density_variation = n->number("max_density_variation", Range{0, 10, true, false}, 0.5);
    s.pair_list_skin = n->number("pair_list_skin", Range{0, 1, false, false}, 0.1);
    s.kernel_gradient_correction = n->boolean("kernel_gradient_correction", false);
    s.kernel_gradient_correction_stress = n->boolean("kernel_gradient_correction_stress", false);
    if (s.kernel_gradient_correction_stress && !s.kernel_gradient_correction)
      n->fail("kernel_gradient_correction_stress", "needs numerics.kernel_gradient_correction true (the correction "
                                                   "matrix comes from the velocity-gradient pass)");
    n->reject_unknown();
  }

  auto mats = top.object("materials");
  mats.section("*");  // its keys are names, not fields
  for (const auto& name : mats.keys()) {
    auto m = mats.object(name);
    std::vector<std::string> models = fluid_model_names();
    const std::vector<std::string> solids = solid_model_names();
    models.insert(models.end(), solids.begin(), solids.end());
    const std::string model = m.choice("model", models);
    m.section(model == "tait_fluid" ? "materials:" + model : "materials:solid:" + model);
    if (model == "tait_fluid") s.materials.push_back(parse_fluid_material(m, name));
    else s.soils.push_back(parse_solid_material(m, name, model));
  }
  if (s.materials.empty() && s.soils.empty()) mats.fail("", "must define at least one material");
  mats.reject_unknown();

  for (auto& b : top.array_of_objects("bodies")) s.bodies.push_back(parse_body(b, s));
  if (auto w = top.optional_object("walls")) s.walls = parse_walls(*w, d);
  if (auto g = top.optional_object("gravity_loading")) s.gravity_loading = parse_gravity_loading(*g);
  if (top.has("excavations"))
    for (auto& e : top.array_of_objects("excavations")) s.excavations.push_back(parse_excavation(e, d));
  top.reject_unknown();
  validate_scene(s);
  return s;
}

// Intersection volume of two boxes (dim axes).
static double overlap_volume(int dim, const std::array<double, 3>& alo, const std::array<double, 3>& ahi,
                             const std::array<double, 3>& blo, const std::array<double, 3>& bhi) {
  double v = 1;
  for (int a = 0; a < dim; ++a) v *= std::max(0.0, std::min(ahi[a], bhi[a]) - std::max(alo[a], blo[a]));
  return v;
}

// The body's shape (its box when it has none).
static geometry::ShapePtr shape_of(const Scene& s, const BodySpec& b) {
  return b.shape ? b.shape : geometry::make_box(s.dim, b.lo, b.hi);
}

// Two bodies overlap: their boxes share volume, or for shaped bodies a lattice point of one lies inside
// the other.
static bool bodies_overlap(const Scene& s, const BodySpec& a, const BodySpec& b) {
  if (!a.shape && !b.shape) return overlap_volume(s.dim, a.lo, a.hi, b.lo, b.hi) > 1e-9 * std::pow(s.dx, s.dim);
  return geometry::shapes_overlap(*shape_of(s, a), *shape_of(s, b), s.dx);
}

// Structure bodies: none may overlap a soil body at start (the contact would begin with the soil
// inside the structure), every structure in a scene with soil names its interface friction, and a
// prescribed motion must keep the structure inside the domain until time.end.
static void validate_structures(const Scene& s) {
  auto fail = [&](const std::string& field, const std::string& what) {
    throw InputError(s.file + ": field '" + field + "': " + what);
  };
  const char* axes = "xyz";
  bool any_soil = false;
  for (const auto& b : s.bodies) any_soil = any_soil || (!b.structure && is_solid_material(s, b.material));
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const BodySpec& st = s.bodies[k];
    if (!st.structure) continue;
    const std::string field = "bodies[" + std::to_string(k) + "]";
    if (s.has_fluid()) fail(field + ".structure", "structures are coupled with soil only; this scene also has a fluid");
    if (any_soil && st.interface_friction_angle < 0)
      fail(field + ".interface_friction_angle",
           "is required for a structure in a scene with soil (the soil-structure interface friction angle delta, "
           "in [0, 90) degrees)");
    for (std::size_t o = 0; o < s.bodies.size(); ++o) {
      const BodySpec& so = s.bodies[o];
      if (so.structure || !is_solid_material(s, so.material)) continue;
      if (bodies_overlap(s, st, so))
        fail(field, "the structure overlaps the soil body bodies[" + std::to_string(o) +
                        "] at start; structure and soil may touch but not intersect");
    }
    if (!st.motion.active) continue;
    // corners at time.end: rotated about the centre by omega * t and translated by v * t (the ramp only
    // shortens the path, so this bounds it)
    const double th = st.motion.angular_velocity * s.t_end;
    for (int c = 0; c < (1 << s.dim); ++c) {
      std::array<double, 3> q{};
      for (int a = 0; a < s.dim; ++a) q[a] = (c >> a & 1 ? st.hi[a] : st.lo[a]) - st.motion.centre[a];
      const double rx = std::cos(th) * q[0] - std::sin(th) * q[1], ry = std::sin(th) * q[0] + std::cos(th) * q[1];
      q[0] = rx; q[1] = ry;
      for (int a = 0; a < s.dim; ++a) {
        const double x = st.motion.centre[a] + q[a] + st.motion.velocity[a] * s.t_end;
        if (!s.domain.periodic[a] && (x < s.domain.lo[a] || x > s.domain.hi[a]))
          fail(field + ".motion", std::string("the prescribed motion carries the structure outside the domain along ") +
                                      axes[a] + " by time.end = " + std::to_string(s.t_end) + " s (corner reaches " +
                                      std::to_string(x) + " m)");
      }
    }
  }
}

// Fluid and soil meet only as a saturated soil and its pore water: every soil body in a scene with
// a fluid must be saturated (porosity given) and lie inside the fluid bodies, which fill its pores;
// one fluid material (the pore water).
static void validate_two_phase(const Scene& s) {
  auto fail = [&](const std::string& field, const std::string& what) {
    throw InputError(s.file + ": field '" + field + "': " + what);
  };
  if (!s.has_fluid()) {
    for (const auto& m : s.soils)
      if (m.saturated())
        fail("materials." + m.name + ".porosity", "saturated soil needs its pore water: the scene has no fluid material");
    return;
  }
  if (!s.has_soil()) return;
  for (const auto& b : s.bodies)
    if (b.structure) return;  // rejected with its own message in validate_structures
  if (s.materials.size() > 1) fail("materials", "a two-phase scene (saturated soil) takes one fluid, its pore water");
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const BodySpec& b = s.bodies[k];
    const SoilMaterial* m = s.find_soil(b.material);
    if (!m || b.structure) continue;
    const std::string field = "bodies[" + std::to_string(k) + "]";
    if (!m->saturated())
      fail("materials." + m->name + ".porosity",
           "is missing: soil in a scene with a fluid is a saturated soil and needs its porosity in (0, 1) (and "
           "hydraulic_conductivity or grain_size)");
    // every soil particle lies in a body of the water (several water bodies may share a layer: the
    // two reservoirs of a sheet pile, each starting hydrostatic below its own level)
    std::vector<geometry::ShapePtr> waters;
    bool inside = false;  // a box of water holding a box of soil needs no lattice walk
    for (const auto& w : s.bodies) {
      if (w.material != s.materials.front().name) continue;
      waters.push_back(shape_of(s, w));
      bool in = !b.shape && !w.shape;
      for (int a = 0; a < s.dim; ++a) in = in && w.lo[a] <= b.lo[a] + 1e-12 && w.hi[a] >= b.hi[a] - 1e-12;
      inside = inside || in;
    }
    if (!inside) {
      inside = true;
      for (const auto& p : geometry::fill_lattice(*shape_of(s, b), s.dx)) {
        bool in = false;
        for (const auto& w : waters) in = in || w->contains(p, s.dx);
        inside = inside && in;
      }
    }
    if (!inside)
      fail(field, "the saturated soil body must lie inside the bodies of the fluid \"" + s.materials.front().name +
                      "\" (its pore water)");
  }
}

// Construction events happen within the run, excavations in time order and inside the domain; a
// two-phase scene cannot have them yet (the seepage coupling's partner sets are built once).
static void validate_construction(const Scene& s) {
  auto fail = [&](const std::string& field, const std::string& what) {
    throw InputError(s.file + ": field '" + field + "': " + what);
  };
  const char* axes = "xyz";
  for (std::size_t k = 0; k < s.excavations.size(); ++k) {
    const ExcavationSpec& e = s.excavations[k];
    const std::string field = "excavations[" + std::to_string(k) + "]";
    if (e.time > s.t_end) fail(field + ".time", "must not exceed time.end (" + std::to_string(s.t_end) + " s)");
    if (k > 0 && e.time < s.excavations[k - 1].time) fail(field + ".time", "excavations must be listed in time order");
    for (int a = 0; a < s.dim; ++a)
      if (e.hi[a] < s.domain.lo[a] || e.lo[a] > s.domain.hi[a])
        fail(field + ".shape", std::string("lies outside the domain along ") + axes[a]);
    if (!geometry::holds_lattice_point(*e.shape, s.dx))
      fail(field + ".shape", e.shape->describe() + " holds no lattice point at dx = " + std::to_string(s.dx) +
                                 " m (it is smaller than a particle)");
  }
  for (std::size_t k = 0; k < s.bodies.size(); ++k)
    if (s.bodies[k].placed_at > s.t_end)
      fail("bodies[" + std::to_string(k) + "].placed_at", "must not exceed time.end (" + std::to_string(s.t_end) + " s)");
  if (s.has_construction() && s.two_phase())
    fail(s.excavations.empty() ? "bodies" : "excavations",
         "construction stages are not yet available for saturated (two-phase) soil");
  if (s.gravity_loading.after_construction && !s.has_construction())
    fail("gravity_loading.after_construction", "is set but the scene has no excavation and no placed body");
}

// No two bodies may overlap (their particles would sit on top of each other) except a saturated soil
// inside its pore water, and no body may reach into a wall block or the wall layers behind a closed
// side of a container. Touching is allowed. A rigid structure (prescribed motion) may pass through
// wall layers: walls and rigid structures do not act on each other (a retaining wall's foot reaches
// below the ground's surface, as in rankine_active).
static void validate_overlaps(const Scene& s) {
  auto fail = [&](const std::string& field, const std::string& what) {
    throw InputError(s.file + ": field '" + field + "': " + what);
  };
  const double tiny = 1e-9 * std::pow(s.dx, s.dim);
  const auto is_fluid = [&](const BodySpec& b) { return !is_solid_material(s, b.material); };
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    for (std::size_t k = i + 1; k < s.bodies.size(); ++k) {
      const BodySpec &a = s.bodies[i], &b = s.bodies[k];
      if (is_fluid(a) != is_fluid(b) && s.two_phase()) continue;  // pore water and its soil skeleton
      if (a.placed_at > 0 || b.placed_at > 0) continue;  // checked when placed (sim/construction.hpp)
      if (bodies_overlap(s, a, b))
        fail("bodies[" + std::to_string(k) + "]", "overlaps bodies[" + std::to_string(i) +
                                                      "]: their particles would sit on top of each other; bodies "
                                                      "may touch but not intersect");
    }
  // boundary/geometry.cpp: dummy walls are wall_layers deep, repulsive walls one line on the surface
  const double L = (s.walls.type == "repulsive" ? 1 : wall_layers(s)) * s.dx;
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const BodySpec& b = s.bodies[k];
    if (b.is_rigid_structure()) continue;
    const std::string field = "bodies[" + std::to_string(k) + "]";
    for (std::size_t c = 0; c < s.walls.blocks.size(); ++c) {
      BodySpec block;
      block.lo = s.walls.blocks[c].lo;
      block.hi = s.walls.blocks[c].hi;
      if (bodies_overlap(s, b, block)) fail(field, "overlaps the wall block walls.blocks[" + std::to_string(c) + "]");
    }
    for (std::size_t c = 0; c < s.walls.boundaries.size(); ++c)
      if (geometry::shapes_overlap(*shape_of(s, b), *s.walls.boundaries[c].shape, s.dx))
        fail(field, "reaches into the solid of the wall walls.boundaries[" + std::to_string(c) +
                        "] (bodies may touch a wall's surface but not cross it)");
    for (std::size_t c = 0; c < s.walls.containers.size(); ++c) {
      const ContainerSpec& w = s.walls.containers[c];
      for (int a = 0; a < s.dim; ++a) {
        if (s.domain.periodic[a]) continue;
        for (int side = 0; side < 2; ++side) {
          const char* name = container_side(s.dim, a, side == 1);
          if (std::find(w.open.begin(), w.open.end(), name) != w.open.end()) continue;
          auto lo = w.lo, hi = w.hi;  // the wall's layers behind this side
          for (int o = 0; o < s.dim; ++o)
            if (o != a) { lo[o] -= L; hi[o] += L; }
          if (side == 0) { hi[a] = w.lo[a]; lo[a] = w.lo[a] - L; } else { lo[a] = w.hi[a]; hi[a] = w.hi[a] + L; }
          BodySpec layers;
          layers.lo = lo;
          layers.hi = hi;
          // a shaped body only where its lattice points are (its bounding box may reach further)
          if (b.shape ? bodies_overlap(s, b, layers) : overlap_volume(s.dim, b.lo, b.hi, lo, hi) > tiny)
            fail(field, std::string("reaches into the wall layers of walls.containers[") + std::to_string(c) + "] (its " +
                            name + " side, " + std::to_string(L) + " m thick)");
        }
      }
    }
  }
}

void validate_scene(const Scene& s) {
  auto fail = [&](const std::string& field, const std::string& what) {
    throw InputError(s.file + ": field '" + field + "': " + what);
  };
  const char* axes = "xyz";
  for (int a = 0; a < s.dim; ++a) {
    if (s.domain.periodic[a]) {
      if (s.domain.length(a) < 3 * s.support())
        fail("domain", std::string("periodic along ") + axes[a] + " needs a length of at least 3 kernel supports (" +
                           std::to_string(3 * s.support()) + " m)");
      const double cells = s.domain.length(a) / s.dx;
      if (std::abs(cells - std::round(cells)) > 1e-6)
        fail("domain", std::string("periodic length along ") + axes[a] + " must be a whole number of dx");
    }
  }
  // every body and every wall layer must lie inside the domain
  const double wall_thick = s.walls.type == "mirror" ? 0.0 : wall_layers(s) * s.dx;  // mirror walls: no particles
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    for (int a = 0; a < s.dim; ++a)
      if (s.bodies[b].lo[a] < s.domain.lo[a] || s.bodies[b].hi[a] > s.domain.hi[a])
        fail("bodies[" + std::to_string(b) + "]", std::string("extends outside the domain along ") + axes[a] +
                                                   " (particles must start inside domain.min..domain.max)");
  for (std::size_t c = 0; c < s.walls.containers.size(); ++c)
    for (int a = 0; a < s.dim; ++a) {
      if (s.domain.periodic[a]) continue;
      const auto& open = s.walls.containers[c].open;  // an open side has no wall layers
      const double lo_thick = std::find(open.begin(), open.end(), container_side(s.dim, a, false)) != open.end() ? 0.0 : wall_thick;
      const double hi_thick = std::find(open.begin(), open.end(), container_side(s.dim, a, true)) != open.end() ? 0.0 : wall_thick;
      if (s.walls.containers[c].lo[a] - lo_thick < s.domain.lo[a] - 1e-12 ||
          s.walls.containers[c].hi[a] + hi_thick > s.domain.hi[a] + 1e-12)
        fail("walls.containers[" + std::to_string(c) + "]",
             std::string("its wall layers (") + std::to_string(wall_thick) + " m thick) extend outside the domain along " +
                 axes[a]);
    }
  for (std::size_t c = 0; c < s.walls.blocks.size(); ++c)
    for (int a = 0; a < s.dim; ++a)
      if (s.walls.blocks[c].lo[a] < s.domain.lo[a] || s.walls.blocks[c].hi[a] > s.domain.hi[a])
        fail("walls.blocks[" + std::to_string(c) + "]", std::string("extends outside the domain along ") + axes[a]);
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    if (s.bodies[b].shape && !geometry::holds_lattice_point(*s.bodies[b].shape, s.dx))
      fail("bodies[" + std::to_string(b) + "].shape", s.bodies[b].shape->describe() + " holds no lattice point at dx = " +
                                                         std::to_string(s.dx) + " m (it is smaller than a particle)");
  // shaped bodies and walls fill the lattice (i + 1/2) dx; a box beside them lines up with it only if its
  // lower corner is a whole multiple of dx (its own lattice starts there)
  bool shaped = !s.walls.boundaries.empty();
  for (const auto& b : s.bodies) shaped = shaped || b.shape != nullptr;
  auto on_lattice = [&](const std::array<double, 3>& lo, const std::string& field) {
    for (int a = 0; a < s.dim; ++a) {
      const double q = lo[a] / s.dx;
      if (std::abs(q - std::round(q)) > 1e-6)
        fail(field, std::string("this box's min along ") + axes[a] + " (" + std::to_string(lo[a]) +
                        " m) is not a whole multiple of dx: with shaped bodies or walls in the scene, every box must "
                        "start on their lattice (i + 1/2) dx, or its particles would not line up with theirs");
    }
  };
  if (shaped) {
    for (std::size_t b = 0; b < s.bodies.size(); ++b)
      if (!s.bodies[b].shape) on_lattice(s.bodies[b].lo, "bodies[" + std::to_string(b) + "].min");
    for (std::size_t c = 0; c < s.walls.containers.size(); ++c)
      on_lattice(s.walls.containers[c].lo, "walls.containers[" + std::to_string(c) + "].min");
    for (std::size_t c = 0; c < s.walls.blocks.size(); ++c)
      on_lattice(s.walls.blocks[c].lo, "walls.blocks[" + std::to_string(c) + "].min");
  }
  for (std::size_t c = 0; c < s.walls.boundaries.size(); ++c)
    if (!geometry::holds_lattice_point(*s.walls.boundaries[c].shape, s.dx))
      fail("walls.boundaries[" + std::to_string(c) + "].shape",
           s.walls.boundaries[c].shape->describe() + " holds no lattice point at dx = " + std::to_string(s.dx) +
               " m (it is thinner than a particle)");
  for (std::size_t c = 0; c < s.walls.boundaries.size(); ++c)
    for (int a = 0; a < s.dim; ++a)
      if (s.walls.boundaries[c].lo[a] < s.domain.lo[a] || s.walls.boundaries[c].hi[a] > s.domain.hi[a])
        fail("walls.boundaries[" + std::to_string(c) + "].shape", std::string("extends outside the domain along ") + axes[a]);
  if (s.gravity_ramp > s.t_end) fail("time.gravity_ramp", "must not exceed time.end");
  if (s.gravity_loading.active) {
    if (!s.has_soil()) fail("gravity_loading", "needs a soil or structure body (it settles the solids under their weight)");
    if (s.gravity[0] == 0 && s.gravity[1] == 0 && s.gravity[2] == 0) fail("gravity_loading", "needs gravity");
    if (s.gravity_ramp > 0) fail("gravity_loading", "and time.gravity_ramp exclude each other (use gravity_loading.ramp)");
    if (s.two_phase()) fail("gravity_loading", "is not yet available for saturated (two-phase) soil");
    if (s.gravity_loading.model == "elastic")
      for (const auto& m : s.soils)
        if (!std::visit([](const auto& mm) { return requires { mm.elastic; }; }, m.model))
          fail("gravity_loading.model", "\"elastic\" needs constant elastic moduli; \"" + m.name + "\" is " +
                                            m.model_name() + " (use \"material\")");
  }
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    if (s.bodies[b].surcharge.ramp > s.t_end) fail("bodies[" + std::to_string(b) + "].surcharge.ramp", "must not exceed time.end");
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    if (s.bodies[b].initial == "geostatic")
      for (int a = 0; a < s.dim - 1; ++a)
        if (s.gravity[a] != 0 || s.gravity[s.dim - 1] > 0)
          fail("bodies[" + std::to_string(b) + "].initial",
               std::string("\"geostatic\" needs gravity pointing along -") + (s.dim == 2 ? "y" : "z"));
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    for (const auto& m : s.soils)
      if (m.name == s.bodies[b].material && s.bodies[b].initial == "geostatic" &&
          std::visit([](const auto& model) { return model.needs_initial_pressure; }, m.model) &&
          !(s.gravity[s.dim - 1] * s.initial_gravity_factor() < 0))
        fail("bodies[" + std::to_string(b) + "].initial",
             "\"geostatic\" without gravity at t = 0 gives p' = 0, but the " + m.model_name() + " material \"" +
                 m.name + "\" needs p' > 0 at start (use \"isotropic\" with a pressure)");
  validate_construction(s);
  validate_structures(s);
  validate_two_phase(s);
  validate_overlaps(s);
  if (s.has_soil() && s.has_walls() && s.walls.type != "dummy" && s.walls.type != "ghost" && s.walls.type != "mirror")
    fail("walls.type", "soil needs dummy, ghost or mirror walls (they carry the soil's stress); \"" + s.walls.type +
                           "\" walls are for fluids only");
  for (std::size_t k = 0; k < s.walls.containers.size(); ++k)
    if (!s.walls.containers[k].drained.empty() && (!s.two_phase() || (s.walls.type != "dummy" && s.walls.type != "ghost")))
      fail("walls.containers[" + std::to_string(k) + "].drained",
           "drained sides let the pore water of saturated soil leave: they need a two-phase scene (soil with porosity "
           "and its pore water) and dummy or ghost walls");
  if (s.two_phase() && s.walls.type == "mirror")
    fail("walls.type", "\"mirror\" walls do not take saturated (two-phase) soil yet: its pore water and skeleton "
                       "would need their images coupled; use \"dummy\" or \"ghost\"");
  if (s.walls.type == "mirror" && !s.walls.blocks.empty())
    fail("walls.blocks", "are not available with walls.type \"mirror\" (mirror walls are fixed walls without particles; "
                         "a block, which may move or hold a structure, is made of particles: use \"dummy\" or \"ghost\")");
  if (s.walls.type == "morris") {  // Morris et al.'s (1997) treatment is a no-slip condition
    const char* why = "is \"free_slip\", but Morris walls (walls.type \"morris\") are no-slip walls; use walls.type "
                      "\"dummy\" for free slip";
    if (s.walls.slip == "free_slip") fail("walls.slip", why);
    for (std::size_t k = 0; k < s.walls.containers.size(); ++k)
      if (s.walls.containers[k].slip == "free_slip") fail("walls.containers[" + std::to_string(k) + "].slip", why);
    for (std::size_t k = 0; k < s.walls.boundaries.size(); ++k)
      if (s.walls.boundaries[k].slip == "free_slip") fail("walls.boundaries[" + std::to_string(k) + "].slip", why);
  }
}

Scene load_scene(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string() + ": cannot open scene file");
  return parse_scene(read_json_file(path), path.string());
}

}  // namespace geosph
