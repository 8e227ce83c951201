#include <algorithm>
#include "boundary/wall_input.hpp"

#include "boundary/morris_wall.hpp"
#include "geometry/shape_input.hpp"
#include "io/scene_reference.hpp"

namespace geosph {

const std::vector<std::string>& wall_types() {
  static const std::vector<std::string> types = {"dummy", "repulsive", "morris", "ghost", "mirror"};
  return types;
}

namespace {

const std::vector<std::string> kSides = {"left", "right", "bottom", "top", "front", "back"};

// min/max corners of a box, max > min on every axis
ContainerSpec parse_box(const JsonFields& f, int dim) {
  ContainerSpec b;
  b.lo = f.vector("min", dim);
  b.hi = f.vector("max", dim);
  for (int a = 0; a < dim; ++a)
    if (!(b.hi[a] > b.lo[a])) f.fail("max", "must be greater than min on every axis");
  return b;
}

const bool documented = register_section(
    {"walls", "walls", "Wall particles: one treatment for all walls, containers and blocks.",
     {choice_doc("type", wall_types(), "required",
                 "dummy particles with extrapolated pressure/stress (Adami et al. 2012), repulsive particles "
                 "(Monaghan 1994, fluids only), or Morris no-slip walls (Morris, Fox & Zhu 1997, fluids only: dummy "
                 "pressure, the wall velocity extrapolated per pair across the wall's tangent plane; no free slip), or "
                 "ghost walls (fixed ghost particles, Marrone et al. 2011, fluid, soil and two-phase soil: each wall particle "
                 "takes the fluid's pressure and opposite velocity, or the soil's stress and velocity mirrored across "
                 "the wall (free slip) or copied with the opposite velocity (no slip), at its mirror point, by linear "
                 "moving least squares), or mirror walls (fluids and dry soil, fixed walls: no particles; each particle "
                 "near a wall sees its neighbours mirrored across it at every step, with mirrored (free slip) or "
                 "opposite (no slip) velocity and the hydrostatic pressure step, the soil's stress mirrored "
                 "R sigma R^T (free slip) or copied (no slip): ghost particles of Randles & "
                 "Libersky 1996 at container faces and corners, the multiple boundary tangent method of Yildiz et al. "
                 "2009 at walls.boundaries)"),
      choice_doc("slip", {"no_slip", "free_slip"}, "no_slip", "wall condition of every wall (a container may set its own)"),
      {"layers", FieldType::Integer, "in [1, 10]", "enough to cover the kernel support", "-", "wall particle layers",
       Range::between(1, 10)},
      number_doc("repulsive_strength", Range::non_negative(), "0.05 c0^2", "m^2/s^2", "repulsive walls: D"),
      number_doc("morris_beta_max", Range::between(1, 1000), "1.5", "-",
                 "Morris walls: cap of the pair's velocity factor beta = 1 + d_wall/d_fluid (1.5: Morris et al. 1997)"),
      {"containers", FieldType::Objects, "see walls.containers", "required without blocks or boundaries", "-",
       "boxes walled on their faces"},
      {"blocks", FieldType::Objects, "see walls.blocks", "none", "-", "solid boxes of wall particles"},
      {"boundaries", FieldType::Objects, "see walls.boundaries", "none", "-",
       "walls of any shape (inclined, curved): the surface of a solid shape"}}});

const bool documented_boundaries = register_section(
    {"walls.boundaries", "walls.boundaries[k]",
     "A wall of any shape: the surface of the solid `shape`. Its particles fill the lattice points inside the shape "
     "within the wall layers of its surface (the lattice (i + 1/2) dx) and carry the surface's outward "
     "normal, which free slip uses.",
     {{"shape", FieldType::Object, "see shape", "required", "-", "the solid whose surface is the wall"},
      choice_doc("slip", {"no_slip", "free_slip"}, "walls.slip", "this wall's condition")}});

const bool documented_containers = register_section(
    {"walls.containers", "walls.containers[k]", "A box whose faces (but the open ones) are walls; min/max are the inner faces.",
     {{"min", FieldType::Vector, "dimension numbers", "required", "m", "inner lower corner"},
      {"max", FieldType::Vector, "dimension numbers, > min", "required", "m", "inner upper corner"},
      {"open", FieldType::Texts, "from {left, right, bottom, top, front, back}", "[]", "-",
       "sides without a wall: left/right along x; 2D: bottom/top along y; 3D: front/back along y, bottom/top along z"},
      choice_doc("slip", {"no_slip", "free_slip"}, "walls.slip", "this container's wall condition"),
      {"drained", FieldType::Texts, "from {left, right, bottom, top, front, back}, not open", "[]", "-",
       "saturated soil: sides the pore water drains through at drained_pressure (a filter, a porous stone); the "
       "skeleton rests on them as on a wall, the water that crosses them leaves the run (boundary/drained_face.hpp)"},
      number_doc("drained_pressure", Range::between(-1e5, 1e9), "0", "Pa",
                 "pore pressure at the drained sides (hydrostatic behind them)")}});

const bool documented_blocks = register_section(
    {"walls.blocks", "walls.blocks[k]", "A solid box of wall particles (a clamp, a footing, a piston), optionally moving.",
     {{"min", FieldType::Vector, "dimension numbers", "required", "m", "lower corner"},
      {"max", FieldType::Vector, "dimension numbers, > min", "required", "m", "upper corner"},
      {"velocity", FieldType::Vector, "dimension numbers", "[0, 0(, 0)]", "m/s", "prescribed constant velocity"},
      number_doc("ramp", Range::non_negative(), "0", "s", "the velocity is reached over ramp (smooth start)")}});

}  // namespace

WallSpec parse_walls(const JsonFields& w, int dim) {
  w.section("walls");
  WallSpec walls;
  walls.type = w.choice("type", wall_types());
  walls.slip = w.choice("slip", {"no_slip", "free_slip"}, "no_slip");
  walls.layers = static_cast<int>(w.integer("layers", 1, 10, 0));
  walls.repulsive_strength = w.number("repulsive_strength", Range::non_negative(), 0.0);
  walls.morris_beta_max = w.number("morris_beta_max", Range::between(1, 1000), kMorrisBetaMax);
  if (w.has("morris_beta_max") && walls.type != "morris") w.fail("morris_beta_max", "applies to walls.type \"morris\" only");
  if (!w.has("containers") && !w.has("blocks") && !w.has("boundaries"))
    w.fail("containers", "is missing: walls need 'containers', 'blocks' or 'boundaries'");
  if (w.has("containers"))
    for (auto& c : w.array_of_objects("containers")) {
      c.section("walls.containers");
      ContainerSpec cs = parse_box(c, dim);
      cs.open = c.texts("open", kSides);
      for (const auto& side : cs.open)
        if (dim == 2 && (side == "front" || side == "back"))
          c.fail("open", "\"" + side + "\" is a side of a 3D container (along y); a 2D container has left, right, "
                         "bottom and top");
      cs.slip = c.choice("slip", {"no_slip", "free_slip"}, walls.slip);
      cs.drained = c.texts("drained", kSides);
      for (const auto& side : cs.drained) {
        if (dim == 2 && (side == "front" || side == "back"))
          c.fail("drained", "\"" + side + "\" is a side of a 3D container (along y); a 2D container has left, right, "
                            "bottom and top");
        if (std::find(cs.open.begin(), cs.open.end(), side) != cs.open.end())
          c.fail("drained", "\"" + side + "\" is also open: a drained side is a wall the pore water passes through");
      }
      cs.drained_pressure = c.number("drained_pressure", Range::between(-1e5, 1e9), 0.0);
      if (c.has("drained_pressure") && cs.drained.empty())
        c.fail("drained_pressure", "applies to drained sides only (set 'drained')");
      c.reject_unknown();
      walls.containers.push_back(cs);
    }
  if (w.has("blocks"))
    for (auto& c : w.array_of_objects("blocks")) {
      c.section("walls.blocks");
      ContainerSpec cs = parse_box(c, dim);
      cs.velocity = c.vector("velocity", dim, {0, 0, 0});
      cs.ramp = c.number("ramp", Range::non_negative(), 0.0);
      c.reject_unknown();
      walls.blocks.push_back(cs);
    }
  if (w.has("boundaries"))
    for (auto& c : w.array_of_objects("boundaries")) {
      c.section("walls.boundaries");
      BoundarySpec bs;
      bs.shape = parse_shape(c.object("shape"), dim);
      const geometry::Bounds bb = bs.shape->bounds();
      bs.lo = bb.lo;
      bs.hi = bb.hi;
      bs.slip = c.choice("slip", {"no_slip", "free_slip"}, walls.slip);
      c.reject_unknown();
      walls.boundaries.push_back(bs);
    }
  w.reject_unknown();
  return walls;
}

}  // namespace geosph
