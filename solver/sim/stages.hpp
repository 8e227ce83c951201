// The time step as an ordered list of stages. Each stage belongs to one hook of the step (when it
// runs) and declares the fields it reads, the fields it writes (overwrites) and the fields it adds to
// (accumulates into, after their writer). Core fields carry the particle set they touch, e.g.
// "a[soil]"; optional fields their registry name. Within one hook no two stages write the same field
// and every accumulated field has an earlier writer, so the order that carries physics is the one
// visible table (Simulation::stage_table) and a stage cannot silently overwrite another's result.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace geosph {

enum class Hook {
  Drift,      // after the positions moved: kinematic motion (t still t^n)
  Rates,      // at x^{n+1}, v^{n+1/2}: continuity, stress rates and updates
  Integrate,  // rho^{n+1} and the other integrated fields from their rates
  Forces,     // accelerations a^{n+1} at the new state (also once at t = 0)
};
const char* hook_name(Hook h);

struct Stage {
  std::string name;
  Hook hook;
  std::vector<std::string> reads, writes, adds;
  std::function<void()> run;
};

// Throws std::logic_error naming the stages if two stages of one hook write the same field, or a
// stage adds to a field that no earlier stage of its hook wrote.
void check_stages(const std::vector<Stage>& stages);
// One line per stage: hook, name, reads -> writes (+= adds).
std::string describe_stages(const std::vector<Stage>& stages);

}  // namespace geosph
