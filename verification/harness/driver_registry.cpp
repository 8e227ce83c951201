#include "harness/driver_registry.hpp"

#include <cstdio>
#include <cstdlib>

namespace geosph::verify {

namespace {
// A function-local static, so that it exists before the first registrar runs whatever the order of
// static initialisation across the case objects.
std::map<std::string, DriverFn>& registry() {
  static std::map<std::string, DriverFn> r;
  return r;
}
}  // namespace

const std::map<std::string, DriverFn>& drivers() { return registry(); }

bool register_driver(const std::string& name, DriverFn fn) {
  if (!registry().emplace(name, std::move(fn)).second) {
    std::fprintf(stderr, "geosph: two case drivers are named '%s'\n", name.c_str());
    std::abort();
  }
  return true;
}

}  // namespace geosph::verify
