#include "boundary/body_input.hpp"

#include "geometry/shape_input.hpp"
#include "io/scene_reference.hpp"
#include "materials/model_list.hpp"

namespace geosph {

namespace {

const bool documented =
    register_section({"bodies", "bodies[k]", "A body of one material filled with particles on the dx lattice.",
                      {{"material", FieldType::Text, "a key of materials", "required", "-", "the body's material"},
                       {"shape", FieldType::Text, "\"box\" (min..max) or a shape object (see shape)", "required", "-",
                        "the body's shape; a box fills its own lattice from min, a shape object the points (i + 1/2) dx inside it"},
                       {"min", FieldType::Vector, "dimension numbers", "required with \"box\"", "m", "lower corner of the box"},
                       {"max", FieldType::Vector, "dimension numbers, > min", "required with \"box\"", "m",
                        "upper corner of the box"},
                       choice_doc("initial", {"rest", "hydrostatic", "geostatic", "isotropic"}, "rest",
                                  "initial state: rest (rho0), hydrostatic (fluid, Tait), geostatic (soil: sigma_v = "
                                  "rho g depth, sigma_h = K0 sigma_v), isotropic (soil: sigma = -pressure I)"),
                       number_doc("k0", Range::open(0, 10), "nu/(1 - nu)", "-", "geostatic: lateral stress ratio K0"),
                       number_doc("pressure", Range::positive(), "required with isotropic", "Pa",
                                  "isotropic: the initial mean effective stress p'"),
                       {"surcharge", FieldType::Object, "see bodies.surcharge", "none", "-",
                        "a vertical pressure on the soil body's top row"},
                       {"velocity", FieldType::Vector, "dimension numbers", "[0, 0(, 0)]", "m/s", "initial velocity"},
                       number_doc("placed_at", Range::positive(), "0 (from the start)", "s",
                                  "construction: the body appears at this time (a fill layer, an embankment lift), with "
                                  "its initial state; it must not overlap what is there then"),
                       {"fixed", FieldType::Boolean, "true, false", "false", "-",
                        "solid bodies: held in place (velocity zero), e.g. a clamped root"},
                       {"structure", FieldType::Boolean, "true, false", "false", "-",
                        "a structure body (linear_elastic or von_mises) meeting soil through frictional contact"},
                       number_doc("interface_friction_angle", Range{0, 90, false, true}, "required with soil", "deg",
                                  "structures: Coulomb friction angle delta of the soil-structure interface"),
                       {"motion", FieldType::Object, "see bodies.motion", "none", "-",
                        "structures: prescribed rigid motion (makes the structure rigid)"}}});

const bool documented_surcharge = register_section(
    {"bodies.surcharge", "bodies[k].surcharge", "Surcharge on a soil body's top row (permeable: pore water drains through it).",
     {number_doc("pressure", Range::positive(), "required", "Pa", "downward pressure, reached over ramp"),
      number_doc("ramp", Range::non_negative(), "0", "s", "smooth-start time of the pressure")}});

const bool documented_motion = register_section(
    {"bodies.motion", "bodies[k].motion", "Prescribed rigid motion of a structure: translation and rotation about a centre.",
     {{"velocity", FieldType::Vector, "dimension numbers", "[0, 0(, 0)]", "m/s", "velocity of the reference point"},
      number_doc("angular_velocity", Range::between(-100, 100), "0", "rad/s", "counter-clockwise rotation (2D only)"),
      {"centre", FieldType::Vector, "dimension numbers", "the centre of the bounding box", "m", "reference point (rotation centre) at t = 0"},
      number_doc("ramp", Range::non_negative(), "0", "s", "smooth-start time of the motion")}});

}  // namespace

BodySpec parse_body(const JsonFields& b, const Scene& s) {
  b.section("bodies");
  const int d = s.dim;
  BodySpec body;
  body.material = b.text("material");
  bool is_fluid = false;
  for (const auto& m : s.materials) is_fluid = is_fluid || m.name == body.material;
  const SoilMaterial* solid = s.find_soil(body.material);
  if (solid) b.section("bodies:" + solid->model_name());  // a model may add body fields of its own
  const bool is_soil = solid != nullptr;
  if (!is_fluid && !is_soil) b.fail("material", "names no material in 'materials' (got \"" + body.material + "\")");
  body.structure = b.boolean("structure", false);
  const bool structure_allowed =
      solid && std::visit([](const auto& m) { return m.structure_allowed; }, solid->model);
  if (body.structure && !structure_allowed)
    b.fail("structure", "needs a " +
                            materials::ModelList<materials::SolidModel>::names_where(
                                [](const auto& m) { return m.structure_allowed; }) +
                            " material; \"" + body.material + "\" is " +
                            (is_fluid ? std::string("a fluid") : std::string(1, '"').append(solid->model_name()).append(1, '"')));
  if (b.is_object("shape")) {
    body.shape = parse_shape(b.object("shape"), d);
    const geometry::Bounds bb = body.shape->bounds();
    body.lo = bb.lo;
    body.hi = bb.hi;
  } else {
    b.choice("shape", {"box"});
    body.lo = b.vector("min", d);
    body.hi = b.vector("max", d);
    for (int a = 0; a < d; ++a)
      if (!(body.hi[a] > body.lo[a])) b.fail("max", "must be greater than min on every axis");
  }
  body.initial = is_fluid         ? b.choice("initial", {"rest", "hydrostatic"}, "rest")
                 : body.structure ? b.choice("initial", {"rest"}, "rest")
                                  : b.choice("initial", {"rest", "geostatic", "isotropic"}, "rest");
  if (is_soil && b.has("k0")) body.k0 = b.number("k0", Range::open(0, 10));
  if (body.initial == "isotropic") body.pressure = b.number("pressure", Range::positive());
  if (solid) std::visit([&](const auto& m) { m.read_body(b, body, body.material); }, solid->model);
  if (auto sc = b.optional_object("surcharge")) {
    sc->section("bodies.surcharge");
    if (!is_soil || body.structure) b.fail("surcharge", "is only allowed on soil bodies");
    body.surcharge.pressure = sc->number("pressure", Range::positive());
    body.surcharge.ramp = sc->number("ramp", Range::non_negative(), 0.0);
    sc->reject_unknown();
  }
  body.velocity = b.vector("velocity", d, {0, 0, 0});
  body.fixed = b.boolean("fixed", false);
  if (b.has("placed_at")) {
    body.placed_at = b.number("placed_at", Range::positive());
    if (body.structure) b.fail("placed_at", "is for soil and fluid bodies; structures are there from the start");
  }
  if (body.fixed && is_fluid) b.fail("fixed", "is only allowed for soil/solid bodies");
  if (body.structure) {
    body.interface_friction_angle = b.number("interface_friction_angle", Range{0, 90, false, true}, -1.0);
    if (auto mo = b.optional_object("motion")) {
      mo->section("bodies.motion");
      if (body.fixed) b.fail("motion", "cannot be combined with \"fixed\": true");
      body.motion.active = true;
      body.motion.velocity = mo->vector("velocity", d, {0, 0, 0});
      body.motion.angular_velocity = mo->number("angular_velocity", Range::between(-100, 100), 0.0);
      if (body.motion.angular_velocity != 0 && d == 3)
        mo->fail("angular_velocity", "prescribed rotation is implemented in 2D only (about z)");
      std::array<double, 3> mid{};
      for (int a = 0; a < d; ++a) mid[a] = 0.5 * (body.lo[a] + body.hi[a]);
      body.motion.centre = mo->vector("centre", d, mid);
      body.motion.ramp = mo->number("ramp", Range::non_negative(), 0.0);
      mo->reject_unknown();
    }
  }
  b.reject_unknown();
  return body;
}

}  // namespace geosph
