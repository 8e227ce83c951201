// Cantilever sheet pile in dry sand at its limit state (issue 18, item 2). A flexible elastic pile
// (structure body of thickness t, bending stiffness EI per metre run, smooth) stands in Drucker-Prager
// sand already excavated to the dredge level in front of it; gravity is ramped from zero (the "ramped
// gravity" of a staged analysis) and then held. A pile that stands comes to rest; one that fails keeps
// rotating into the excavation. Recorded: the head displacement and rotation, the head's drift over
// the last part of the hold; at the deeper embedment the bending moment along the pile from the
// structure's stress across its section,
//   M(y) = -I * sum_k sigma_yy,k (x_k - xbar) / sum_k (x_k - xbar)^2,  I = t^3 / 12
// (the row's linear fit: beam theory), positive with tension on the retained side, against the
// free-earth (net-pressure) method; the moment of the contact forces above each section (the soil's
// load, scored against the method too) and that of all forces above it, the pile's weight and inertia
// included (what the section carries by equilibrium: the check of the stress moment, recorded).

#include <algorithm>
#include <cmath>
#include <map>

#include "boundary/body_fields.hpp"
#include "coupling/soil_structure_contact.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"
#include "io/scene.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

struct Layout {
  double H, D, below, left, right, t, EI;
  double y_toe() const { return below; }
  double y_dredge() const { return below + D; }
  double y_top() const { return below + D + H; }
};

nlohmann::json box(double x0, double y0, double x1, double y1) {
  return {{"type", "box"}, {"min", {x0, y0}}, {"max", {x1, y1}}};
}

// The scene at spacing dx: the case's scene.json (materials, time and its gravity ramp, walls) with the
// geometry of this embedment, the excavation in front of the pile made; the pile's Young's modulus from EI = E t^3 / (12 (1 - nu^2)) (plane strain plate).
Scene build_scene(const CaseConfig& cfg, const Layout& g, double dx) {
  nlohmann::json j = cfg.scene_json;
  j["dx"] = dx;
  const double x0 = -g.left, x1 = g.t + g.right;
  j["domain"] = {{"min", {x0 - 1.0, -1.0}}, {"max", {x1 + 1.0, g.y_top() + 2.0}}};
  auto& pile = j["materials"]["pile"];
  const double nu = pile.at("poisson_ratio").get<double>();
  pile["young_modulus"] = 12.0 * g.EI * (1.0 - nu * nu) / (g.t * g.t * g.t);
  const nlohmann::json pile_box = box(0.0, g.y_toe(), g.t, g.y_top());
  j["bodies"] = nlohmann::json::array();
  j["bodies"].push_back({{"material", "sand"},
                         {"shape", {{"type", "difference"},
                                    {"parts", {box(x0, 0.0, x1, g.y_top()), pile_box,
                                               box(g.t, g.y_dredge(), x1 + 1.0, g.y_top() + 1.0)}}}}});
  j["bodies"].push_back({{"material", "pile"}, {"shape", "box"}, {"min", {0.0, g.y_toe()}}, {"max", {g.t, g.y_top()}},
                         {"structure", true}, {"interface_friction_angle", cfg.spec.at("interface_friction_angle")}});
  j["walls"]["containers"] = {{{"min", {x0, 0.0}}, {"max", {x1, g.y_top() + 1.0}}, {"open", {"top"}}}};
  return parse_scene(j, (cfg.dir / "scene.json").string());
}

// The pile's particles by row (initial lattice row from the toe) and their ids.
struct PileRows {
  std::vector<std::vector<std::int64_t>> ids;  // per row, bottom to top
  std::vector<double> y0;                      // initial row heights
};

PileRows pile_rows(const Particles& P, std::size_t pile_body, double y_toe, double dx) {
  PileRows r;
  const auto& body = P.int_field(BodyFields::structure_body);
  std::map<long, std::vector<std::int64_t>> rows;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (body[i] == static_cast<std::int32_t>(pile_body + 1)) rows[std::lround((P.y[i] - y_toe) / dx - 0.5)].push_back(P.id[i]);
  for (auto& [k, v] : rows) {
    r.ids.push_back(v);
    r.y0.push_back(y_toe + (k + 0.5) * dx);
  }
  return r;
}

struct PileState {
  std::vector<double> xc, moment, contact_fx;  // per row: centre x, M from stress [N m/m], contact force [N/m]
  // per row: the moment about the row's centre of every force on the rows above but the pile's own
  // SPH forces: contact, weight (the leaning pile's P-delta) and inertia, F = f_contact + m (g - a)
  std::vector<double> moment_all;
};

PileState pile_state(const Particles& P, const PileRows& rows, double I, double gx, double gy) {
  std::unordered_map<std::int64_t, std::size_t> at;
  for (std::size_t i = 0; i < P.size(); ++i) at[P.id[i]] = i;
  const auto& syy = P.field(SoilFields::yy);
  const auto& fx = P.field(ContactFields::fx);
  const auto& fy = P.field(ContactFields::fy);
  PileState s;
  const std::size_t n = rows.ids.size();
  std::vector<double> yc(n), Fx(n), Fy(n), Fx_y(n), Fy_x(n);
  for (std::size_t r = 0; r < n; ++r) {
    const auto& row = rows.ids[r];
    double xbar = 0, ybar = 0, f = 0;
    for (auto id : row) { xbar += P.x[at.at(id)]; ybar += P.y[at.at(id)]; }
    xbar /= static_cast<double>(row.size());
    ybar /= static_cast<double>(row.size());
    double sxs = 0, sxx = 0;
    for (auto id : row) {
      const std::size_t i = at.at(id);
      sxs += syy[i] * (P.x[i] - xbar);
      sxx += (P.x[i] - xbar) * (P.x[i] - xbar);
      f += fx[i];
      const double Fxi = fx[i] + P.m[i] * (gx - P.ax[i]), Fyi = fy[i] + P.m[i] * (gy - P.ay[i]);
      Fx[r] += Fxi; Fy[r] += Fyi; Fx_y[r] += Fxi * P.y[i]; Fy_x[r] += Fyi * P.x[i];
    }
    s.xc.push_back(xbar);
    yc[r] = ybar;
    s.moment.push_back(sxx > 0 ? -I * sxs / sxx : 0.0);
    s.contact_fx.push_back(f);
  }
  // positive as the contact moment below: sum of F_x (y - y_c) - F_y (x - x_c) over the rows above
  s.moment_all.assign(n, 0.0);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t q = r + 1; q < n; ++q)
      s.moment_all[r] += Fx_y[q] - yc[r] * Fx[q] - (Fy_x[q] - s.xc[r] * Fy[q]);
  return s;
}

// expected: "stands" or "fails" (the outcome is scored), or "limit" (the embedment of the free-earth
// method: the bending moment is scored, since there the pile carries the limit pressures whether or not
// it comes to rest)
Record run_at(const CaseConfig& cfg, const CaseContext& ctx, const std::string& variant, double dx) {
  const nlohmann::json& sp = cfg.spec;
  const nlohmann::json& v = sp.at("variants").at(variant);
  const double ratio = v.at("embedment_ratio").get<double>();
  const std::string expected = v.at("expected").get<std::string>();
  if (expected != "stands" && expected != "fails" && expected != "limit")
    throw InputError((cfg.dir / "case.json").string() + ": field 'variants." + variant +
                     ".expected': must be \"stands\", \"fails\" or \"limit\"");
  const double D_free = sp.at("free_earth_embedment").get<double>();
  Layout g{sp.at("retained_height"), ratio * D_free, sp.at("sand_below_toe"), sp.at("retained_width"),
           sp.at("excavated_width"), sp.at("pile_thickness").get<double>(), sp.at("pile_bending_stiffness")};
  const Scene scene = build_scene(cfg, g, dx);
  const double I = g.t * g.t * g.t / 12.0;
  Simulation sim(scene);
  const PileRows rows = pile_rows(sim.particles(), 1, g.y_toe(), dx);
  const PileState s0 = pile_state(sim.particles(), rows, I, scene.gravity[0], scene.gravity[1]);
  Record rec = start_record(cfg, ctx);
  rec.variant = variant;
  const std::size_t top = rows.ids.size() - 1;
  // head displacement (towards the excavation) and rotation (slope of the centre line over the top H/5)
  const auto head = [&](const PileState& s, double& u, double& theta) {
    u = s.xc[top] - s0.xc[top];
    const std::size_t k = std::min<std::size_t>(top, static_cast<std::size_t>(std::lround(0.2 * g.H / dx)));
    theta = std::atan2((s.xc[top] - s0.xc[top]) - (s.xc[top - k] - s0.xc[top - k]), rows.y0[top] - rows.y0[top - k]);
  };
  Series motion{"SPH pile head", "simulation", "head", "time [s]", "head displacement / H", {}, {}};
  const double t_hold = scene.gravity_ramp, t_drift = scene.t_end - sp.at("drift_window").get<double>();
  std::vector<double> window_t, window_u;  // head displacement over the drift window
  double next = 0;
  PileState avg;
  avg.moment.assign(rows.ids.size(), 0.0);
  avg.contact_fx.assign(rows.ids.size(), 0.0);
  avg.moment_all.assign(rows.ids.size(), 0.0);
  long samples = 0;
  const bool ok = run_timed(sim, rec, [&](const Simulation& sm) {
    if (sm.time() < next) return;
    next = sm.time() + 0.01;
    double u, th;
    const PileState ps = pile_state(sm.particles(), rows, I, scene.gravity[0], scene.gravity[1]);
    head(ps, u, th);
    if (sm.time() >= t_drift) {  // the profiles averaged over the window (the contact forces chatter step to step)
      window_t.push_back(sm.time());
      window_u.push_back(u);
      for (std::size_t r = 0; r < rows.ids.size(); ++r) {
        avg.moment[r] += ps.moment[r];
        avg.contact_fx[r] += ps.contact_fx[r];
        avg.moment_all[r] += ps.moment_all[r];
      }
      ++samples;
    }
    motion.x.push_back(sm.time());
    motion.y.push_back(u / g.H);
  }, ctx.progress);
  double u_end, theta_end;
  head(pile_state(sim.particles(), rows, I, scene.gravity[0], scene.gravity[1]), u_end, theta_end);
  for (std::size_t r = 0; r < rows.ids.size(); ++r) {
    avg.moment[r] /= std::max(samples, 1L);
    avg.contact_fx[r] /= std::max(samples, 1L);
    avg.moment_all[r] /= std::max(samples, 1L);
  }
  const PileState& s1 = avg;
  // stands: the head moved less than stands_drift x H over the last drift_window of the hold, by the
  // least-squares slope of u(t) there (a pile at rest still rings by about 1 cm)
  double tm = 0, um = 0, stu = 0, stt = 0;
  for (std::size_t k = 0; k < window_t.size(); ++k) { tm += window_t[k]; um += window_u[k]; }
  tm /= std::max<std::size_t>(window_t.size(), 1);
  um /= std::max<std::size_t>(window_t.size(), 1);
  for (std::size_t k = 0; k < window_t.size(); ++k) {
    stu += (window_t[k] - tm) * (window_u[k] - um);
    stt += (window_t[k] - tm) * (window_t[k] - tm);
  }
  const double drift = window_t.size() > 2 && stt > 0 ? std::abs(stu / stt) * (window_t.back() - window_t.front()) / g.H : NAN;
  const bool stands = ok && std::isfinite(drift) && drift < sp.at("stands_drift").get<double>();
  rec.extra["embedment_m"] = g.D;
  rec.extra["embedment_over_free_earth"] = ratio;
  rec.extra["pile_thickness_m"] = g.t;
  rec.extra["pile_bending_stiffness_Nm2_per_m"] = g.EI;
  rec.extra["retained_height_over_dx"] = g.H / dx;
  rec.extra["gravity_ramp_s"] = t_hold;
  rec.extra["head_displacement_end_m"] = u_end;
  rec.extra["head_rotation_end_deg"] = theta_end * 180.0 / M_PI;
  rec.extra["head_drift_in_window_over_H"] = drift;
  rec.extra["stands"] = stands;
  rec.series.push_back(motion);
  if (expected != "limit")
    add_case_metric(rec, cfg, "limit_state_outcome_error", stands == (expected == "stands") ? 0.0 : 1.0, ok);
  if (expected != "fails") {
    // moment profiles (depth from the retained surface), from the stress and from the contact forces
    const Csv ref = read_csv(cfg.reference_file(ctx, sp.at("reference_file")).string());
    const auto& ref_depth = ref.column("depth_m");
    const auto& ref_pressure = ref.column("net_pressure_kPa");
    const auto& ref_moment = ref.column("moment_kNm_per_m");
    Series m_stress{"SPH, from the pile's stress (mean over the window)", "simulation", "moment", "bending moment [kN m/m]", "depth [m]", {}, {}};
    Series m_contact{"SPH, from the contact forces above", "simulation", "moment", m_stress.xlabel, m_stress.ylabel, {}, {}};
    Series m_all{"SPH, from all forces above (contact, weight, inertia)", "simulation", "moment", m_stress.xlabel, m_stress.ylabel, {}, {}};
    Series p_net{"SPH net contact pressure", "simulation", "pressure", "net pressure [kPa]", "depth [m]", {}, {}};
    double M_max = -1e300, z_max = NAN, Mc_max = -1e300, zc_max = NAN, Ma_max = -1e300, za_max = NAN;
    const std::size_t end_rows = static_cast<std::size_t>(std::ceil(scene.support() / dx));
    for (std::size_t r = 0; r <= top; ++r) {
      const double depth = g.y_top() - rows.y0[r];
      double Mc = 0;  // contact forces above the section's height
      for (std::size_t q = r + 1; q <= top; ++q) Mc += s1.contact_fx[q] * (rows.y0[q] - rows.y0[r]);
      m_stress.x.push_back(s1.moment[r] / 1e3);
      m_stress.y.push_back(-depth);
      m_contact.x.push_back(Mc / 1e3);
      m_contact.y.push_back(-depth);
      m_all.x.push_back(s1.moment_all[r] / 1e3);
      m_all.y.push_back(-depth);
      p_net.x.push_back(s1.contact_fx[r] / dx / 1e3);
      p_net.y.push_back(-depth);
      // the largest moments away from the pile's free ends, whose rows have a truncated kernel along
      // the pile too (within 2h of an end the row's stress fit is not the section's)
      if (r < end_rows || r + end_rows > top) continue;
      if (s1.moment[r] > M_max) { M_max = s1.moment[r]; z_max = depth; }
      if (Mc > Mc_max) { Mc_max = Mc; zc_max = depth; }
      if (s1.moment_all[r] > Ma_max) { Ma_max = s1.moment_all[r]; za_max = depth; }
    }
    Series m_ref{"free-earth method (Das, net pressure)", "analytical", "moment", m_stress.xlabel, m_stress.ylabel, {}, {}};
    Series p_ref{"free-earth method (Das, net pressure)", "analytical", "pressure", p_net.xlabel, p_net.ylabel, {}, {}};
    double M_ref = 0, z_ref = 0;
    for (std::size_t k = 0; k < ref_depth.size(); ++k) {
      m_ref.x.push_back(ref_moment[k]);
      m_ref.y.push_back(-ref_depth[k]);
      p_ref.x.push_back(ref_pressure[k]);
      p_ref.y.push_back(-ref_depth[k]);
      if (ref_moment[k] > M_ref) { M_ref = ref_moment[k]; z_ref = ref_depth[k]; }
    }
    M_ref *= 1e3;
    for (auto* s : {&m_stress, &m_contact, &m_all, &m_ref, &p_net, &p_ref}) rec.series.push_back(*s);
    rec.extra["max_moment_kNm_per_m"] = M_max / 1e3;
    rec.extra["max_moment_depth_m"] = z_max;
    rec.extra["max_moment_from_contact_kNm_per_m"] = Mc_max / 1e3;
    rec.extra["max_moment_from_contact_depth_m"] = zc_max;
    // recorded, not scored: what the pile's section must carry by equilibrium (the stress moment's check)
    rec.extra["max_moment_from_all_forces_kNm_per_m"] = Ma_max / 1e3;
    rec.extra["max_moment_from_all_forces_depth_m"] = za_max;
    rec.extra["free_earth_max_moment_kNm_per_m"] = M_ref / 1e3;
    rec.extra["free_earth_max_moment_depth_m"] = z_ref;
    if (expected == "limit") {
      add_case_metric(rec, cfg, "max_moment_rel_error", std::abs(M_max - M_ref) / M_ref, ok);
      add_case_metric(rec, cfg, "max_moment_depth_error_over_H", std::abs(z_max - z_ref) / g.H, ok);
      add_case_metric(rec, cfg, "max_equilibrium_moment_rel_error", std::abs(Mc_max - M_ref) / M_ref, ok);
    }
  }
  rec.snapshot = field_snapshot(sim, SoilFields::plastic_strain, "-");
  return rec;
}

}  // namespace

// Each embedment of case.json's "variants" at each spacing of the level.
std::vector<Record> run_cantilever_sheet_pile(const CaseContext& ctx, const std::string& case_name) {
  return run_each_variant(ctx, case_name, run_at);
}

GEOSPH_CASE_DRIVER(cantilever_sheet_pile, run_cantilever_sheet_pile);

}  // namespace geosph::verify
