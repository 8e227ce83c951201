// Ghost walls (boundary/ghost_wall.hpp): the mirror point of a wall particle near a wall and near a
// corner, and the mirrored values: with a linear pressure and a linear shear profile in the fluid,
// every wall particle whose mirror point has a full support carries the hydrostatic pressure at its own
// depth and the shear's continuation through the wall (zero on the surface), to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "boundary/body_fields.hpp"
#include "boundary/geometry.hpp"
#include "boundary/ghost_wall.hpp"
#include "boundary/mirror_mls.hpp"
#include "boundary/soil_wall.hpp"
#include "boundary/wall_surface.hpp"
#include "core/cell_list.hpp"
#include "coupling/seepage_fields.hpp"
#include "soil/soil_fields.hpp"
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

// The soil column saturated (pore water in the soil's box, the sand's porosity and conductivity), with
// walls of the given type.
json saturated_column(const char* walls) {
  auto j = geosph::test::soil_column_scene();
  j["walls"]["type"] = walls;
  j["materials"]["water"] = json::parse(R"({"model": "tait_fluid", "density": 1000, "sound_speed": 20})");
  j["materials"]["sand"]["porosity"] = 0.4;
  j["materials"]["sand"]["hydraulic_conductivity"] = 1e-3;
  j["bodies"].push_back(json::parse(R"({"material": "water", "shape": "box", "min": [0, 0], "max": [0.2, 0.1]})"));
  return j;
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
  PointList mirrors;  // no pair list here: the mirror queries scan the cells
  update_ghost_walls(s, eos, P, cells, {0, -g, 0}, wvx.data(), wvy.data(), wvz.data(), unmirrored, mirrors);
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

// Soil ghost walls: with a linear isotropic stress, a uniform shear stress and a linear velocity in the
// soil, every wall particle whose mirror point has a full support carries the stress at its own depth
// (the mirror value plus the hydrostatic step) with the shear reversed at a free-slip face and kept
// through a corner (the double mirror) and at a no-slip wall, the tangential velocity kept and the
// normal one reversed at a free-slip face, and the opposite velocity through a corner and with no slip.
namespace {

struct SoilGhostCheck {
  int floor = 0, corner = 0, side = 0;
};

SoilGhostCheck check_soil_ghosts(const std::string& slip) {
  auto j = geosph::test::soil_column_scene();
  j["walls"]["type"] = "ghost";
  j["walls"]["slip"] = slip;
  const Scene s = parse_scene(j, "ok.json");
  Particles P = build_particles(s);
  const double rho0 = 2650, g = 9.81, H = 0.1, tau = 300.0, p_top = 100.0;
  const double ux = 0.02, uy = -0.01;  // velocity gradients [1/s]
  const auto p_at = [&](double y) { return p_top + rho0 * g * (H - y); };
  auto& sxx = P.field(SoilFields::xx);
  auto& syy = P.field(SoilFields::yy);
  auto& szz = P.field(SoilFields::zz);
  auto& sxy = P.add_field(SoilFields::xy, SoilFields::owner);  // the soil forces create it (soil/soil_forces.cpp)
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    P.rho[i] = rho0;
    P.m[i] = rho0 * s.dx * s.dx;
    sxx[i] = syy[i] = szz[i] = -p_at(P.y[i]);
    sxy[i] = tau;
    P.vx[i] = ux * P.y[i] + 0.001;
    P.vy[i] = uy * P.x[i] + 0.002 * P.y[i];
  }
  CellList cells;
  EXPECT_EQ(cells.build(P, s.domain, s.support()), -1);
  SoilWalls walls(s);
  walls.allocate(P);
  walls.update(P, cells, {0, -g, 0});
  const auto& wvx = P.field(SoilWallFields::vx);
  const auto& wvy = P.field(SoilWallFields::vy);
  const bool free = slip == "free_slip";
  const double reach = s.support();
  SoilGhostCheck n;
  for (std::size_t w = 0; w < P.size(); ++w) {
    if (P.kind[w] != Kind::DummyWall) continue;
    const double x = P.x[w], y = P.y[w];
    const bool under_floor = y < 0 && x > reach && x < 0.2 - reach;
    const bool in_corner = x < 0 && y < 0;
    const bool at_side = x < 0 && y > 0 && y < H - reach;
    if (!under_floor && !in_corner && !at_side) continue;
    // the nearest soil particle, at (dx/2, dx/2) from the corner: a wall farther than the support from it
    // is in no support, and keeps the values of a wall without soil around
    const double gap_x = x < 0 ? 0.5 * s.dx - x : 0.0, gap_y = y < 0 ? 0.5 * s.dx - y : 0.0;
    if (std::hypot(gap_x, gap_y) >= reach) continue;
    const double xm = in_corner || at_side ? -x : x, ym = in_corner || under_floor ? -y : y;  // the mirror point
    const double vxm = ux * ym + 0.001, vym = uy * xm + 0.002 * ym;
    const std::string at = "x = " + std::to_string(x) + ", y = " + std::to_string(y);
    const double tol = 1e-9 * rho0 * g * H;
    EXPECT_NEAR(sxx[w], -p_at(y), tol) << at;
    EXPECT_NEAR(syy[w], -p_at(y), tol) << at;
    EXPECT_NEAR(szz[w], -p_at(y), tol) << at;
    // the shear reverses at a free-slip face (one reflection), twice through a corner
    EXPECT_NEAR(sxy[w], free && !in_corner ? -tau : tau, 1e-9 * tau) << at;
    double ex = -vxm, ey = -vym;  // opposite velocity: no slip, and the free-slip corner (R = -I)
    if (free && under_floor) ex = vxm;
    if (free && at_side) ey = vym;
    EXPECT_NEAR(wvx[w], ex, 1e-12) << at;
    EXPECT_NEAR(wvy[w], ey, 1e-12) << at;
    (under_floor ? n.floor : in_corner ? n.corner : n.side)++;
  }
  return n;
}

}  // namespace

TEST(GhostWall, SoilStressAndVelocityMirrorFreeSlip) {
  const auto n = check_soil_ghosts("free_slip");
  EXPECT_GT(n.floor, 0);
  EXPECT_GT(n.corner, 0);
  EXPECT_GT(n.side, 0);
}

TEST(GhostWall, SoilStressAndVelocityMirrorNoSlip) {
  const auto n = check_soil_ghosts("no_slip");
  EXPECT_GT(n.floor, 0);
  EXPECT_GT(n.corner, 0);
  EXPECT_GT(n.side, 0);
}

// The reflection: a face's R = I - 2 n n^T, a 2D corner's -I in the plane, a 3D edge's two reversed axes.
TEST(GhostWall, MirrorReflections) {
  const double up[3] = {0, 1, 0}, diag2[3] = {0.6, 0.8, 0}, edge[3] = {0.6, 0, 0.8};
  const Eigen::Matrix3d face = mirror_reflection(up, false);
  EXPECT_EQ(face, Eigen::Vector3d(1, -1, 1).asDiagonal().toDenseMatrix());
  EXPECT_EQ(mirror_reflection(diag2, true), Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix());
  EXPECT_EQ(mirror_reflection(edge, true), Eigen::Vector3d(-1, 1, -1).asDiagonal().toDenseMatrix());
  // an inclined wall: R reverses the normal and keeps the tangent
  const double c = std::sqrt(0.5), n45[3] = {c, c, 0};
  const Eigen::Matrix3d R = mirror_reflection(n45, false);
  EXPECT_NEAR((R * Eigen::Vector3d(c, c, 0) + Eigen::Vector3d(c, c, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((R * Eigen::Vector3d(-c, c, 0) - Eigen::Vector3d(-c, c, 0)).norm(), 0.0, 1e-15);
}

// Pore water at ghost walls (two-phase scenes): with a linear pressure, a constant intrinsic density
// and a linear porosity in the water, a floor wall particle carries the hydrostatic pressure at its own
// depth, the porosity at its mirror point, and the partial density n rho(p_w), to round-off.
TEST(GhostWall, PoreWaterMirrorsItsPorosity) {
  const Scene s = parse_scene(saturated_column("ghost"), "ok.json");
  ASSERT_TRUE(s.two_phase());
  Particles P = build_particles(s);
  std::vector<double>& por = P.find(SeepageFields::porosity) ? P.field(SeepageFields::porosity)
                                                             : P.add_field(SeepageFields::porosity, "seepage");
  const double rho0 = 1000, g = 9.81, H = 0.1, p_top = 20.0;
  const auto n_at = [](double y) { return 0.4 + 0.5 * y; };
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    por[i] = n_at(P.y[i]);
    P.rho[i] = rho0 * por[i];  // the partial density n rho_w
    P.m[i] = P.rho[i] * s.dx * s.dx;
    P.p[i] = p_top + rho0 * g * (H - P.y[i]);
    P.vx[i] = P.vy[i] = 0;
  }
  CellList cells;
  ASSERT_EQ(cells.build(P, s.domain, s.support()), -1);
  std::vector<TaitEos> eos;
  for (const auto& m : s.materials) eos.emplace_back(m);
  std::vector<std::uint8_t> unmirrored;
  PointList mirrors;
  update_ghost_walls(s, eos, P, cells, {0, -g, 0}, nullptr, nullptr, nullptr, unmirrored, mirrors);
  const double* depth = P.find(WallSurfaceFields::depth);
  ASSERT_NE(depth, nullptr);
  int checked = 0;
  for (std::size_t w = 0; w < P.size(); ++w) {
    if (P.kind[w] != Kind::DummyWall || P.y[w] > 0 || P.x[w] < 0.05 || P.x[w] > 0.15) continue;
    const double ym = -P.y[w];  // the mirror point across the floor y = 0
    const std::string at = "x = " + std::to_string(P.x[w]) + ", y = " + std::to_string(P.y[w]);
    EXPECT_EQ(unmirrored[w], 0) << at;
    EXPECT_NEAR(P.p[w], p_top + rho0 * g * (H - P.y[w]), 1e-9 * rho0 * g * H) << at;
    EXPECT_NEAR(por[w], n_at(ym), 1e-12) << at;
    const double rho_w = eos[0].density(P.p[w]) * n_at(ym);
    EXPECT_NEAR(P.rho[w], rho_w, 1e-9 * rho0) << at;
    EXPECT_NEAR(P.m[w], rho_w * s.dx * s.dx, 1e-9 * rho0 * s.dx * s.dx) << at;
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

// Morris and repulsive walls stay fluid-only: a soil scene with them is rejected naming walls.type.
TEST(GhostWall, SoilSceneRejectsFluidOnlyWalls) {
  for (const char* type : {"morris", "repulsive"}) {
    auto j = saturated_column(type);
    test::expect_scene_error(j, "walls.type", "soil needs dummy, ghost or mirror walls");
  }
  EXPECT_NO_THROW(parse_scene(saturated_column("dummy"), "ok.json"));
}
