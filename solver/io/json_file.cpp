#include "io/json_file.hpp"

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace geosph {

namespace {

// Thrown from the parser callback; caught below and turned into an InputError with the file name.
struct StructureError {
  std::string what;
};

nlohmann::json parse_checked(std::istream& in, const std::string& file) {
  // One set of seen keys per open object, and the path of keys to it (for the message).
  std::vector<std::set<std::string>> keys;
  std::vector<std::string> path;
  const auto where = [&] {
    std::string p;  // keys joined by '.', a run of array levels as [] x n
    for (std::size_t k = 0; k < path.size();) {
      if (path[k] != "[]") { p += (p.empty() ? "" : ".") + path[k++]; continue; }
      std::size_t n = 0;
      while (k < path.size() && path[k] == "[]") ++n, ++k;
      p += n == 1 ? "[]" : "[] x " + std::to_string(n);
    }
    return p;
  };
  const nlohmann::json::parser_callback_t check = [&](int depth, nlohmann::json::parse_event_t event,
                                                       nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    switch (event) {
      case E::object_start:
      case E::array_start:
        if (depth >= kMaxJsonDepth)
          throw StructureError{"nested deeper than " + std::to_string(kMaxJsonDepth) + " levels" +
                               (path.empty() ? "" : " (below '" + where() + "')") +
                               "; a scene or case file needs fewer than 10"};
        if (event == E::object_start) keys.emplace_back();
        path.emplace_back(event == E::array_start ? "[]" : "");
        break;
      case E::key: {
        const std::string k = parsed.get<std::string>();
        if (!keys.back().insert(k).second) {
          path.back() = k;
          throw StructureError{"field '" + where() + "': given twice in the same object (each key once)"};
        }
        path.back() = k;
        break;
      }
      case E::object_end:
        keys.pop_back();
        path.pop_back();
        break;
      case E::array_end:
        path.pop_back();
        break;
      case E::value:
        break;
    }
    return true;
  };
  try {
    return nlohmann::json::parse(in, check, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const StructureError& e) {
    throw InputError(file + ": " + e.what);
  } catch (const nlohmann::json::out_of_range& e) {  // 406: a number overflowing double, e.g. 1e309
    throw InputError(file + ": " + e.what() + " (numbers must be finite doubles, |x| < 1.8e308)");
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file + ": not valid JSON: " + e.what());
  }
}

}  // namespace

nlohmann::json read_json_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": cannot open file");
  return parse_checked(in, path.string());
}

nlohmann::json parse_json_text(const std::string& text, const std::string& file) {
  std::istringstream in(text);
  return parse_checked(in, file);
}

}  // namespace geosph
