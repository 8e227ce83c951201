// Poiseuille flow start-up (Morris, Fox & Zhu 1997, Sec. 4.1): fluid at rest between no-slip plates,
// periodic along x, driven by a body force from t = 0. The particle velocities at several times are
// compared with the series solution; run at two (quick) or three (full) spacings, the observed
// order of convergence is recorded.

#include <algorithm>
#include <cmath>

#include "analytical/poiseuille.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"

namespace geosph::verify {

std::vector<Record> run_poiseuille_flow(const CaseContext& ctx, const std::string& case_name) {
  const CaseConfig cfg = load_case(ctx, case_name);
  const auto times = cfg.spec.at("compare_times").get<std::vector<double>>();
  std::vector<Record> out;
  for (const double dx : cfg.level.at("dx").get<std::vector<double>>()) {
    Scene scene = cfg.scene(dx);
    const auto& wall = scene.walls.containers.front();
    const reference::PoiseuilleStartup ref{scene.body_force[0], scene.materials.front().kinematic_viscosity,
                                           wall.hi[1] - wall.lo[1]};
    Simulation sim(scene);
    Record rec = start_record(cfg, ctx);
    rec.variant = "";
    double worst = 0;
    bool ok = true;
    for (std::size_t k = 0; k < times.size() && ok; ++k) {
      ok = run_timed(sim, rec, {}, ctx.progress, times[k]);
      if (!ok) break;
      const auto& P = sim.particles();
      std::vector<double> vs, vr;
      std::vector<std::pair<double, double>> profile;
      for (std::size_t i = 0; i < P.size(); ++i) {
        if (P.kind[i] != Kind::Fluid) continue;
        vs.push_back(P.vx[i]);
        vr.push_back(ref.velocity(P.y[i] - wall.lo[1], sim.time()));
        profile.emplace_back(P.y[i], P.vx[i]);
      }
      const double err = scaled_rms(vs, vr, ref.max_velocity());
      worst = std::max(worst, err);
      rec.extra["velocity_rms_over_vmax_at_t"][std::to_string(times[k])] = err;
      // one profile per compare time: particle velocities averaged per lattice row
      std::sort(profile.begin(), profile.end());
      Series s{"SPH t=" + std::to_string(times[k]).substr(0, 4) + " s", "simulation", "profiles", "y [m]", "v_x [m/s]", {}, {}};
      Series a{"series t=" + std::to_string(times[k]).substr(0, 4) + " s", "analytical", "profiles", "y [m]", "v_x [m/s]", {}, {}};
      for (std::size_t q = 0; q < profile.size();) {
        std::size_t r = q;
        double ys = 0, vsum = 0;
        while (r < profile.size() && profile[r].first - profile[q].first < 0.5 * dx) { ys += profile[r].first; vsum += profile[r].second; ++r; }
        s.x.push_back(ys / (r - q)); s.y.push_back(vsum / (r - q));
        q = r;
      }
      for (int m = 0; m <= 40; ++m) {
        const double y = ref.L * m / 40.0;
        a.x.push_back(y); a.y.push_back(ref.velocity(y, sim.time()));
      }
      rec.series.push_back(s);
      rec.series.push_back(a);
    }
    add_case_metric(rec, cfg, "velocity_rms_over_vmax", worst, ok);
    out.push_back(rec);
  }
  // Expected order 1 (observed 0.87 between L/dx = 20 and 40, flattening to 0.3 at 80). The wall
  // velocity is not what limits it: ghost walls (--walls ghost), exact for a linear profile through
  // the wall, give the dummy walls' errors to two digits (0.0072, 0.0040, 0.0033). Morris walls with
  // the published cap beta_max = 1.5 are first order with a six times larger constant: beyond the cap
  // they mis-extrapolate the wall velocity by O(dx).
  annotate_observed_order(out, 1.0);
  return out;
}

GEOSPH_CASE_DRIVER(poiseuille_flow, run_poiseuille_flow);

}  // namespace geosph::verify
