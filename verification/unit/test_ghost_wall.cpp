// Ghost walls (boundary/ghost_wall.hpp): the mirror point of a wall particle near a wall and near a
// corner, and the mirrored values: with a linear pressure and a linear shear profile in the fluid,
// every wall particle whose mirror point has a full support carries the hydrostatic pressure at its own
// depth and the shear's continuation through the wall (zero on the surface), to round-off.
#include <gtest/gtest.h>

#include <cmath>

#include "boundary/body_fields.hpp"
#include "boundary/geometry.hpp"
#include "boundary/ghost_wall.hpp"
#include "boundary/wall_surface.hpp"
#include "core/cell_list.hpp"
#include "test_scenes.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

json ghost_tank() {
  return json::parse(R"({
    "name": "tank", "dimension": 2, "dx": 0.05,
    "kernel": {"type": "wendland_c2"},
    "domain": {"min": [-0.3, -0.3], "max": [1.3, 1.3]},
    "time": {"end": 0.01},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0], "max": [1, 1]}],
    "walls": {"type": "ghost", "containers": [{"min": [0, 0], "max": [1, 1.25], "open": ["top"]}]}
  })");
}

}  // namespace

TEST(GhostWall, MirrorPointsAcrossAWallAndThroughACorner) {
  const double below[3] = {0.3, -0.075, 0}, up[3] = {0, 1, 0};
  const auto m = ghost_mirror_point(below, 0.075, up);
  EXPECT_NEAR(m[0], 0.3, 1e-15);
  EXPECT_NEAR(m[1], 0.075, 1e-15);
  // a corner particle at (-a, -b): its normal is the diagonal to the corner, its mirror (a, b)
  const double a = 0.025, b = 0.075, d = std::hypot(a, b);
  const double corner[3] = {-a, -b, 0}, diag[3] = {a / d, b / d, 0};
  const auto c = ghost_mirror_point(corner, d, diag);
  EXPECT_NEAR(c[0], a, 1e-15);
  EXPECT_NEAR(c[1], b, 1e-15);
}

TEST(GhostWall, LinearFieldsMirrorExactly) {
  const Scene s = parse_scene(ghost_tank(), "ok.json");
  Particles P = build_particles(s);
  const double rho0 = 1000, g = 9.81, H = 1.0, shear = 0.4, p_top = 50.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    P.rho[i] = rho0;
    P.m[i] = rho0 * s.dx * s.dx;
    P.p[i] = p_top + rho0 * g * (H - P.y[i]);
    P.vx[i] = shear * P.y[i];  // zero on the floor
    P.vy[i] = 0;
  }
  CellList cells;
  ASSERT_EQ(cells.build(P, s.domain, s.support()), -1);
  std::vector<TaitEos> eos;
  for (const auto& m : s.materials) eos.emplace_back(m);
  std::vector<double> wvx(P.size()), wvy(P.size()), wvz(P.size());
  std::vector<std::uint8_t> unmirrored;
  update_ghost_walls(s, eos, P, cells, {0, -g, 0}, wvx.data(), wvy.data(), wvz.data(), unmirrored);
  const double* depth = P.find(WallSurfaceFields::depth);
  ASSERT_NE(depth, nullptr);
  int floor = 0, corner = 0;
  for (std::size_t w = 0; w < P.size(); ++w) {
    if (P.kind[w] != Kind::DummyWall || P.y[w] > 0.7) continue;  // mirror points well under the surface
    const bool under_floor = P.x[w] > 0 && P.x[w] < 1 && P.y[w] < 0;
    const bool in_corner = P.x[w] < 0 && P.y[w] < 0;
    if (!under_floor && !in_corner) continue;
    EXPECT_NEAR(P.p[w], p_top + rho0 * g * (H - P.y[w]), 1e-9 * rho0 * g * H) << "x = " << P.x[w] << ", y = " << P.y[w];
    EXPECT_NEAR(wvx[w], shear * P.y[w], 1e-12) << "x = " << P.x[w] << ", y = " << P.y[w];
    EXPECT_NEAR(wvy[w], 0.0, 1e-12);
    EXPECT_NEAR(P.rho[w], eos[0].density(P.p[w]), 1e-12 * rho0);
    EXPECT_EQ(unmirrored[w], 0);
    (under_floor ? floor : corner)++;
  }
  // the side walls above the water have no fluid at their mirror points
  int above = 0;
  for (std::size_t w = 0; w < P.size(); ++w)
    if (P.kind[w] == Kind::DummyWall && P.y[w] > H + s.support()) {
      EXPECT_EQ(unmirrored[w], 1) << "x = " << P.x[w] << ", y = " << P.y[w];
      ++above;
    }
  EXPECT_GT(above, 0);
  const int L = wall_layers(s);
  EXPECT_EQ(floor, 20 * L);  // L layers under the 20-particle-wide floor
  EXPECT_EQ(corner, L * L);  // the L x L corner block
}

// Ghost walls are for fluids: a soil scene with them is rejected naming walls.type.
TEST(GhostWall, SoilSceneRejected) {
  auto j = geosph::test::soil_column_scene();
  j["walls"]["type"] = "ghost";
  test::expect_scene_error(j, "walls.type", "soil needs dummy walls");
}
