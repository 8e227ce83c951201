// Strict reading of one JSON object: every field is checked for presence, type and range, and
// fields nobody asked for are reported as unknown. Errors name the file, the field path and what is
// allowed, e.g.  scene.json: field 'materials.water.density': must be > 0, got -1
#pragma once
#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace geosph {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Range {
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;
  static Range positive() { return {0, 1e300, true, false}; }
  static Range non_negative() { return {0, 1e300, false, false}; }
  static Range between(double a, double b) { return {a, b, false, false}; }
  static Range open(double a, double b) { return {a, b, true, true}; }
  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string describe() const;
};

class JsonFields {
 public:
  JsonFields(const nlohmann::json& obj, std::string file, std::string path);

  double number(const std::string& key, Range range) const;
  double number(const std::string& key, Range range, double fallback) const;
  long integer(const std::string& key, long lo, long hi) const;
  long integer(const std::string& key, long lo, long hi, long fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string text(const std::string& key) const;
  std::string text(const std::string& key, const std::string& fallback) const;
  std::string choice(const std::string& key, const std::vector<std::string>& allowed) const;
  std::string choice(const std::string& key, const std::vector<std::string>& allowed, const std::string& fallback) const;
  // A fixed-length numeric array (n = the scene dimension); missing entries are not filled.
  std::array<double, 3> vector(const std::string& key, int n) const;
  std::array<double, 3> vector(const std::string& key, int n, std::array<double, 3> fallback) const;
  std::vector<std::string> texts(const std::string& key, const std::vector<std::string>& allowed) const;
  // An array of points, each an array of n finite numbers (e.g. a polygon's vertices).
  std::vector<std::array<double, 3>> points(const std::string& key, int n) const;
  // An array of such point arrays (e.g. a polygon's holes); empty if the key is absent.
  std::vector<std::vector<std::array<double, 3>>> point_lists(const std::string& key, int n) const;
  JsonFields object(const std::string& key) const;
  std::optional<JsonFields> optional_object(const std::string& key) const;
  std::vector<JsonFields> array_of_objects(const std::string& key) const;
  bool has(const std::string& key) const { return obj_.contains(key); }
  bool is_object(const std::string& key) const { return obj_.contains(key) && obj_.at(key).is_object(); }
  std::vector<std::string> keys() const;

  // Names the section this object is (io/scene_reference.hpp): its documented fields are listed when
  // an unknown one is found, and the fields read are recorded for the documentation test.
  const JsonFields& section(std::string tag) const { tag_ = std::move(tag); return *this; }
  // Throws if the object holds a field that no call above asked for.
  void reject_unknown() const;

  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  std::string where(const std::string& key) const;
  const std::string& file() const { return file_; }

 private:
  const nlohmann::json& get(const std::string& key) const;
  const nlohmann::json& obj_;
  std::string file_, path_;
  mutable std::set<std::string> used_;
  mutable std::string tag_;
};

}  // namespace geosph
