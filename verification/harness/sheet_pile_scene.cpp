#include "harness/sheet_pile_scene.hpp"

namespace geosph::verify {

using nlohmann::json;

json box_json(double x0, double y0, double x1, double y1) { return json{{"min", {x0, y0}}, {"max", {x1, y1}}}; }

json polygon_json(std::initializer_list<std::array<double, 2>> vertices) {
  json p = json::array();
  for (const auto& q : vertices) p.push_back({q[0], q[1]});
  return json{{"type", "polygon"}, {"vertices", p}};
}

void build_sheet_pile_scene(json& sc, const SheetPileLayout& g, double upstream_level, double downstream_level,
                            double top, double dx, bool fixed_sand) {
  const double a = 0.5 * g.t;
  json sand = {{"material", "sand"}, {"initial", "geostatic"},
               {"shape", polygon_json({{-g.W, -g.T}, {g.W, -g.T}, {g.W, 0}, {a, 0}, {a, -g.s}, {-a, -g.s}, {-a, 0}, {-g.W, 0}})}};
  if (fixed_sand) sand["fixed"] = true;
  sc["bodies"] = json::array({
      {{"material", "water"}, {"initial", "hydrostatic"},
       {"shape", polygon_json({{-g.W, -g.T}, {0, -g.T}, {0, -g.s}, {-a, -g.s}, {-a, upstream_level}, {-g.W, upstream_level}})}},
      {{"material", "water"}, {"initial", "hydrostatic"},
       {"shape", polygon_json({{0, -g.T}, {g.W, -g.T}, {g.W, downstream_level}, {a, downstream_level}, {a, -g.s}, {0, -g.s}})}},
      sand});
  sc["walls"]["containers"] = json::array({box_json(-g.W, -g.T, g.W, top)});
  sc["walls"]["containers"][0]["open"] = {"top"};
  sc["walls"]["blocks"] = json::array({box_json(-a, -g.s, a, top - dx)});
}

}  // namespace geosph::verify
