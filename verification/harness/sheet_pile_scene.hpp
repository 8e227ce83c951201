// The scene of a single sheet pile in a saturated layer (cases sheet_pile_seepage and sheet_pile_heave):
// a layer -T < y < 0 between side walls at x = -W and W on an impermeable base, a wall-block pile
// -t/2 < x < t/2 from y = -s up to the container's top, free water standing to its own level on each side.
#pragma once
#include <nlohmann/json.hpp>

namespace geosph::verify {

struct SheetPileLayout {
  double T, W, s, t;  // layer thickness, half width, embedment, pile thickness [m]
};

// Scene JSON helpers: a box {"min", "max"} and a polygon shape.
nlohmann::json box_json(double x0, double y0, double x1, double y1);
nlohmann::json polygon_json(std::initializer_list<std::array<double, 2>> vertices);

// Sets the scene's bodies, container (open at `top`) and pile block (to `top` - dx): pore and free water
// to `upstream_level` and `downstream_level`, each hydrostatic below its own level, and the sand layer
// ("sand"; geostatic, held in place when `fixed_sand`).
void build_sheet_pile_scene(nlohmann::json& scene, const SheetPileLayout& g, double upstream_level,
                            double downstream_level, double top, double dx, bool fixed_sand);

}  // namespace geosph::verify
