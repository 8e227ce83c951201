#include "harness/catalogue.hpp"

#include <limits>

#include "cases/cam_clay_k0_column/cam_clay_k0_column.hpp"
#include "cases/cantilever_beam/cantilever_beam.hpp"
#include "cases/cam_clay_triaxial/cam_clay_triaxial.hpp"
#include "cases/dam_break_2d/dam_break_2d.hpp"
#include "cases/darcy_seepage/darcy_seepage.hpp"
#include "cases/granular_collapse_bui/granular_collapse_bui.hpp"
#include "cases/granular_collapse_scaling/granular_collapse_scaling.hpp"
#include "cases/hydrostatic_tank/hydrostatic_tank.hpp"
#include "cases/oscillating_plate/oscillating_plate.hpp"
#include "cases/poiseuille_flow/poiseuille_flow.hpp"
#include "cases/quicksand/quicksand.hpp"
#include "cases/rankine_earth_pressure/rankine_earth_pressure.hpp"
#include "cases/soil_under_free_water/soil_under_free_water.hpp"
#include "cases/strip_footing/strip_footing.hpp"
#include "cases/structure_sliding/structure_sliding.hpp"
#include "cases/terzaghi_consolidation/terzaghi_consolidation.hpp"

namespace geosph::verify {

const std::vector<CaseEntry>& catalogue() {
  static const std::vector<CaseEntry> cases = {
      {"hydrostatic_tank", run_hydrostatic_tank},
      {"poiseuille_flow", run_poiseuille_flow},
      {"dam_break_2d", run_dam_break_2d},
      {"granular_collapse_bui", run_granular_collapse_bui},
      {"granular_collapse_cam_clay", run_granular_collapse_cam_clay},
      {"granular_collapse_scaling", run_granular_collapse_scaling},
      {"oscillating_plate", run_oscillating_plate},
      {"strip_footing", run_strip_footing},
      {"cam_clay_triaxial", run_cam_clay_triaxial},
      {"cam_clay_k0_column", run_cam_clay_k0_column},
      {"cantilever_beam", run_cantilever_beam},
      {"rankine_active", run_rankine_active},
      {"rankine_passive", run_rankine_passive},
      {"structure_sliding", run_structure_sliding},
      {"terzaghi_consolidation", run_terzaghi_consolidation},
      {"darcy_seepage", run_darcy_seepage},
      {"soil_under_free_water", run_soil_under_free_water},
      {"quicksand", run_quicksand},
  };
  return cases;
}

Record start_record(const CaseConfig& cfg, const CaseContext& ctx) {
  Record r;
  r.case_name = cfg.name;
  r.title = cfg.title;
  r.level = ctx.level;
  r.reference = cfg.reference;
  return r;
}

void add_case_metric(Record& rec, const CaseConfig& cfg, const std::string& name, double value, bool ok) {
  const auto& tol = cfg.tolerance(name);
  rec.add_metric(name, ok ? value : std::numeric_limits<double>::quiet_NaN(), tol.value, tol.why);
}

}  // namespace geosph::verify
