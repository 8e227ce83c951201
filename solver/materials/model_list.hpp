// Compile-time helpers over a std::variant of model types: their names, parsing by name, and
// whether any alternative has a trait.
#pragma once
#include <string>
#include <variant>
#include <vector>

namespace geosph::materials {

template <class Variant> struct ModelList;

template <class... M>
struct ModelList<std::variant<M...>> {
  static std::vector<std::string> names() { return {std::string(M::name)...}; }
  // Parses the alternative called `name` (which must be one of names()).
  template <class Fields>
  static std::variant<M...> parse(const std::string& name, const Fields& f) {
    std::variant<M...> out;
    ((name == M::name ? (out = M::parse(f), true) : false) || ...);
    return out;
  }
  // " or "-joined names of the alternatives whose trait holds, e.g. for messages.
  template <class Pred>
  static std::string names_where(Pred pred) {
    std::string s;
    ((pred(M{}) ? (s += (s.empty() ? "" : " or ") + std::string(M::name), 0) : 0), ...);
    return s;
  }
};

}  // namespace geosph::materials
