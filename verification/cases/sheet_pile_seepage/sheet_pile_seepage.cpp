// Steady seepage under a single sheet pile (two-phase SPH, coupling/seepage): a saturated layer of
// thickness T on an impermeable base, a held skeleton, an impermeable pile (a wall block of thickness
// t) of embedment s, free water standing H higher on the upstream side than on the downstream side.
// Once the pore pressure has diffused to its steady state the total head in the layer solves Laplace's
// equation. Scored against the finite-volume solution of the same geometry (reference/analytical/
// sheet_pile_seepage: the pile's thickness and the side walls as in the scene), and recorded beside the
// thin-pile conformal-mapping solution (Harr 1962) that a zero-thickness pile would give:
//   - the toe head h(0, -s) = H/2, exact for both by antisymmetry;
//   - the head field of every pore-water particle, the heads along both pile faces;
//   - the discharge under the pile, q / (k H);
//   - the exit gradient next to the pile, the mean vertical gradient over the top s/2 of a strip s/2 wide.
// The head of a water particle is h = y + w(p)/g with w = integral dp/rho of the Tait equation, the
// quantity that is constant in water at rest (hydrostatic_pressure in fluid/equation_of_state.hpp);
// H is the head difference the two reservoirs hold at the time (their levels drift by < 1% in a run).

#include <algorithm>
#include <cmath>

#include "analytical/sheet_pile_seepage.hpp"
#include "coupling/seepage_fields.hpp"
#include "fluid/equation_of_state.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"
#include "harness/sheet_pile_scene.hpp"

namespace geosph::verify {

namespace {

using nlohmann::json;

struct Geometry {
  double T, W, s, t, H, Hd, dx;
};

// Time-averaged head of the pore water on the lattice cells of the layer (the water hardly moves in a
// run: a few millimetres), with the mean position of what fell in each cell.
struct HeadBins {
  int nx, ny;
  double x0, y0, dx;
  std::vector<double> h, x, y;
  std::vector<int> n;
  HeadBins(const Geometry& g) : nx(static_cast<int>(std::lround(2 * g.W / g.dx))), ny(static_cast<int>(std::lround(g.T / g.dx))),
                                x0(-g.W), y0(-g.T), dx(g.dx), h(nx * ny), x(nx * ny), y(nx * ny), n(nx * ny) {}
  void add(double px, double py, double head) {
    const int i = static_cast<int>(std::floor((px - x0) / dx)), j = static_cast<int>(std::floor((py - y0) / dx));
    if (i < 0 || i >= nx || j < 0 || j >= ny) return;
    const int c = j * nx + i;
    h[c] += head; x[c] += px; y[c] += py; ++n[c];
  }
};

Record run_variant(const CaseConfig& base, const CaseContext& ctx, const std::string& variant, double spacing) {
  CaseConfig cfg = base;
  const json& G = cfg.spec.at("geometry");
  const double sT = cfg.spec.at("variants").at(variant).at("s_over_T").get<double>();
  Geometry g{G.at("T"), G.at("W"), 0, G.at("pile_thickness_dx").get<double>() * spacing, G.at("H"), G.at("downstream_depth"), spacing};
  g.s = sT * g.T;
  const double top = g.Hd + g.H + G.at("freeboard").get<double>();
  // the pile is `pile_thickness_dx` spacings thick, the thinnest wall block whose two faces' wall particles
  // never share a water neighbour (support 2h = 2.6 dx with the cubic spline)
  build_sheet_pile_scene(cfg.scene_json, {g.T, g.W, g.s, g.t}, g.Hd + g.H, g.Hd, top, g.dx, true);
  const Scene scene = cfg.scene(spacing);
  const TaitEos eos(scene.materials.front());
  const double grav = -scene.gravity[1];
  const double k = scene.find_soil("sand")->hydraulic_conductivity;
  auto head = [&](double y, double p) { return y + eos.pressure_head(grav, p); };

  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  rec.variant = variant;
  const double t_avg = scene.t_end - cfg.spec.at("averaging_s").get<double>();
  HeadBins bins(g);
  double up_sum = 0, down_sum = 0, q_sum = 0;
  int samples = 0;
  Series level{"SPH", "simulation", "reservoir_heads", "t [s]", "head difference / H", {}, {}};
  Series flow{"SPH", "simulation", "discharge_history", "t [s]", "q / (k H) under the pile", {}, {}};
  double next = 0;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    if (s.time() < next) return;
    next += 0.01;
    const Particles& P = s.particles();
    const auto& n = P.extra_fields().at(SeepageFields::porosity);
    double up = 0, down = 0, q = 0;
    int nu = 0, nd = 0;
    const bool averaging = s.time() >= t_avg;
    for (std::size_t j = 0; j < P.size(); ++j) {
      if (P.kind[j] != Kind::Fluid) continue;
      const double x = P.x[j], y = P.y[j], h = head(y, P.p[j]);
      if (y > 0) {  // the reservoirs, away from the ground, the free surface, the pile and the side walls
        const double clear = 1.5 * g.dx;
        if (x < -0.5 * g.t - 3 * g.dx && x > -g.W + 3 * g.dx && y > clear && y < g.Hd + g.H - clear) { up += h; ++nu; }
        if (x > 0.5 * g.t + 3 * g.dx && x < g.W - 3 * g.dx && y > clear && y < g.Hd - clear) { down += h; ++nd; }
      } else if (y < 0) {
        if (averaging) bins.add(x, y, h);
        if (std::abs(x) < 0.5 * g.t && y < -g.s) q += P.m[j] / P.rho[j] * n[j] * P.vx[j];
      }
    }
    if (!nu || !nd) return;
    level.x.push_back(s.time());
    level.y.push_back((up / nu - down / nd) / g.H);
    flow.x.push_back(s.time());
    flow.y.push_back(q / g.t / (k * (up / nu - down / nd)));
    if (averaging) {
      up_sum += up / nu; down_sum += down / nd; q_sum += q / g.t;  // flow across the section under the pile
      ++samples;
    }
  }, ctx.progress);
  rec.series.push_back(level);
  rec.series.push_back(flow);

  const double h_up = up_sum / std::max(samples, 1), h_down = down_sum / std::max(samples, 1);
  const double H = h_up - h_down;  // the head difference the reservoirs hold
  const reference::SheetPileLaplace fd({g.T, g.W, g.s, g.t, g.dx / 8});
  const reference::ThinSheetPile thin{sT};
  // every cell of pore water: its time-averaged head / H against the reference at its mean position
  std::vector<double> hs, hr;
  double toe = 0, toe_n = 0, exit_s = 0, exit_r = 0, exit_depth = 0, exit_n = 0;
  auto face = [](const char* name, const char* role) { return Series{name, role, "pile_faces", "depth / s", "h / H", {}, {}}; };
  Series up_face = face("SPH, upstream face", "simulation"), down_face = face("SPH, downstream face", "simulation");
  Series up_fd = face("finite volume (this pile), upstream", "analytical");
  Series down_fd = face("finite volume (this pile), downstream", "analytical");
  Series thin_face = face("thin pile (Harr 1962), downstream", "analytical");
  for (int c = 0; c < bins.nx * bins.ny; ++c) {
    if (!bins.n[c]) continue;
    const double x = bins.x[c] / bins.n[c], y = bins.y[c] / bins.n[c], h = (bins.h[c] / bins.n[c] - h_down) / H;
    const double r = fd.head(x, y);
    hs.push_back(h); hr.push_back(r);
    const double ax = std::abs(x) - 0.5 * g.t;
    if (ax < g.dx && y > -g.s) {  // the column of water cells against a pile face
      (x < 0 ? up_face : down_face).x.push_back(-y / g.s);
      (x < 0 ? up_face : down_face).y.push_back(h);
      (x < 0 ? up_fd : down_fd).x.push_back(-y / g.s);
      (x < 0 ? up_fd : down_fd).y.push_back(r);
    }
    if (std::abs(x) < 0.5 * g.t && y < -g.s && y > -g.s - g.dx) { toe += h; ++toe_n; }
    if (x > 0.5 * g.t && ax < 0.5 * g.s && y > -0.5 * g.s) {
      exit_s += h; exit_r += r; exit_depth += -y; ++exit_n;
    }
  }
  for (double d = 0.025; d < 1.0; d += 0.05) { thin_face.x.push_back(d); thin_face.y.push_back(thin.downstream_face_head(d * sT)); }
  // along the downstream ground surface: the mean vertical gradient over the top two rows of each column
  // (mean head / mean depth), x from the pile's face
  Series surf_sph{"SPH", "simulation", "exit_gradient", "x / s from the downstream face", "i s / H", {}, {}};
  Series surf_ref = surf_sph, surf_thin = surf_sph;
  surf_ref.name = "finite volume (this pile)"; surf_ref.role = "analytical";
  surf_thin.name = "thin pile (Harr 1962)"; surf_thin.role = "analytical";
  for (int i = 0; i < bins.nx; ++i) {
    double hs_c = 0, hr_c = 0, d_c = 0, xm = 0;
    int m = 0;
    for (int j = bins.ny - 2; j < bins.ny; ++j) {
      const int c = j * bins.nx + i;
      if (!bins.n[c]) continue;
      const double x = bins.x[c] / bins.n[c], y = bins.y[c] / bins.n[c];
      if (x <= 0.5 * g.t) continue;
      hs_c += (bins.h[c] / bins.n[c] - h_down) / H; hr_c += fd.head(x, y); d_c += -y; xm += x; ++m;
    }
    if (m < 2) continue;
    const double xs = (xm / m - 0.5 * g.t) / g.s;
    surf_sph.x.push_back(xs); surf_sph.y.push_back(hs_c / d_c * g.s);
    surf_ref.x.push_back(xs); surf_ref.y.push_back(hr_c / d_c * g.s);
    surf_thin.x.push_back(xs); surf_thin.y.push_back(thin.exit_gradient_times_T_over_H(xs * sT) * sT);
  }
  for (Series* sr : {&surf_sph, &surf_ref, &surf_thin}) rec.series.push_back(*sr);
  for (Series* sr : {&up_face, &down_face, &up_fd, &down_fd}) {  // by depth
    std::vector<std::size_t> o(sr->x.size());
    for (std::size_t i = 0; i < o.size(); ++i) o[i] = i;
    std::sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return sr->x[a] < sr->x[b]; });
    Series sorted = *sr;
    for (std::size_t i = 0; i < o.size(); ++i) { sorted.x[i] = sr->x[o[i]]; sorted.y[i] = sr->y[o[i]]; }
    rec.series.push_back(sorted);
  }
  rec.series.push_back(thin_face);
  double e2 = 0;
  for (std::size_t i = 0; i < hs.size(); ++i) e2 += (hs[i] - hr[i]) * (hs[i] - hr[i]);
  const double q = q_sum / std::max(samples, 1) / (k * H);
  const double toe_h = toe / std::max(toe_n, 1.0);
  const double exit_sph = exit_s / exit_depth, exit_fd = exit_r / exit_depth;

  rec.extra["s_over_T"] = sT;
  rec.extra["pile_thickness_over_T"] = g.t / g.T;
  rec.extra["head_difference_measured_m"] = H;
  rec.extra["head_difference_set_m"] = g.H;
  rec.extra["averaged_samples"] = samples;
  rec.extra["toe_head_over_H"] = toe_h;
  rec.extra["discharge_over_kH"] = q;
  rec.extra["discharge_over_kH_finite_volume"] = fd.discharge_over_kH();
  rec.extra["discharge_over_kH_thin_pile"] = thin.discharge_over_kH();
  rec.extra["exit_gradient_mean_top_half"] = exit_sph * g.s;  // i s / H: the heads are already / H
  rec.extra["exit_gradient_mean_top_half_finite_volume"] = exit_fd * g.s;
  rec.extra["exit_gradient_at_face_thin_pile_times_s_over_H"] = thin.exit_gradient_at_face_times_T_over_H() * sT;
  add_case_metric(rec, cfg, "toe_head_error", std::abs(toe_h - 0.5), ok && toe_n > 0);
  add_case_metric(rec, cfg, "head_rms_error", std::sqrt(e2 / std::max<std::size_t>(hs.size(), 1)), ok && !hs.empty());
  add_case_metric(rec, cfg, "discharge_rel_error", std::abs(q / fd.discharge_over_kH() - 1.0), ok && samples > 0);
  add_case_metric(rec, cfg, "exit_gradient_rel_error", std::abs(exit_sph / exit_fd - 1.0), ok && exit_n > 0);
  rec.snapshot = pressure_snapshot(sim);
  return rec;
}

}  // namespace

std::vector<Record> run_sheet_pile_seepage(const CaseContext& ctx, const std::string& case_name) {
  return run_each_variant(ctx, case_name, run_variant);
}

GEOSPH_CASE_DRIVER(sheet_pile_seepage, run_sheet_pile_seepage);

}  // namespace geosph::verify
