#include "sim/stages.hpp"

#include <map>
#include <sstream>
#include <stdexcept>

namespace geosph {

const char* hook_name(Hook h) {
  switch (h) {
    case Hook::Drift: return "drift";
    case Hook::Rates: return "rates";
    case Hook::Integrate: return "integrate";
    case Hook::Forces: return "forces";
  }
  return "?";
}

void check_stages(const std::vector<Stage>& stages) {
  std::map<std::pair<Hook, std::string>, std::string> writer;
  for (const auto& s : stages) {
    for (const auto& f : s.adds)
      if (!writer.count({s.hook, f}))
        throw std::logic_error("stage '" + s.name + "' adds to '" + f + "', which no earlier stage of the " +
                               hook_name(s.hook) + " hook writes");
    for (const auto& f : s.writes) {
      auto [it, fresh] = writer.emplace(std::make_pair(s.hook, f), s.name);
      if (!fresh)
        throw std::logic_error("stages '" + it->second + "' and '" + s.name + "' both write '" + f + "' in the " +
                               hook_name(s.hook) + " hook");
    }
  }
}

std::string describe_stages(const std::vector<Stage>& stages) {
  std::ostringstream o;
  auto list = [&](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& f : v) s += (s.empty() ? "" : " ") + f;
    return s.empty() ? std::string("-") : s;
  };
  for (const auto& s : stages) {
    o << hook_name(s.hook) << "  " << s.name << ": " << list(s.reads) << " -> " << list(s.writes);
    if (!s.adds.empty()) o << " += " << list(s.adds);
    o << "\n";
  }
  return o.str();
}

}  // namespace geosph
