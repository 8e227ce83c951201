#include "io/json_fields.hpp"

#include "io/scene_reference.hpp"

#include <cmath>
#include <sstream>

namespace geosph {

std::string Range::describe() const {
  std::ostringstream s;
  s.precision(12);
  const bool has_lo = lo > -1e299, has_hi = hi < 1e299;
  if (has_lo && has_hi) s << "in " << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
  else if (has_lo) s << (lo_open ? "> " : ">= ") << lo;
  else if (has_hi) s << (hi_open ? "< " : "<= ") << hi;
  else s << "a finite number";
  return s.str();
}

JsonFields::JsonFields(const nlohmann::json& obj, std::string file, std::string path)
    : obj_(obj), file_(std::move(file)), path_(std::move(path)) {
  if (!obj_.is_object()) {
    throw InputError(file_ + ": field '" + (path_.empty() ? std::string("(top level)") : path_) +
                     "': must be a JSON object");
  }
}

std::string JsonFields::where(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void JsonFields::fail(const std::string& key, const std::string& what) const {
  throw InputError(file_ + ": field '" + where(key) + "': " + what);
}

const nlohmann::json& JsonFields::get(const std::string& key) const {
  used_.insert(key);
  auto it = obj_.find(key);
  if (it == obj_.end()) fail(key, "is missing (required)");
  return *it;
}

static std::string shown(const nlohmann::json& v) {
  std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

double JsonFields::number(const std::string& key, Range range) const {
  const auto& v = get(key);
  if (!v.is_number()) fail(key, "must be a number " + range.describe() + ", got " + shown(v));
  const double d = v.get<double>();
  if (!std::isfinite(d) || !range.contains(d)) fail(key, "must be " + range.describe() + ", got " + shown(v));
  return d;
}

double JsonFields::number(const std::string& key, Range range, double fallback) const {
  if (!obj_.contains(key)) { used_.insert(key); return fallback; }
  return number(key, range);
}

long JsonFields::integer(const std::string& key, long lo, long hi) const {
  const auto& v = get(key);
  if (!v.is_number_integer() || v.get<long>() < lo || v.get<long>() > hi)
    fail(key, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + shown(v));
  return v.get<long>();
}

long JsonFields::integer(const std::string& key, long lo, long hi, long fallback) const {
  if (!obj_.contains(key)) { used_.insert(key); return fallback; }
  return integer(key, lo, hi);
}

bool JsonFields::boolean(const std::string& key, bool fallback) const {
  if (!obj_.contains(key)) { used_.insert(key); return fallback; }
  const auto& v = get(key);
  if (!v.is_boolean()) fail(key, "must be true or false, got " + shown(v));
  return v.get<bool>();
}

std::string JsonFields::text(const std::string& key) const {
  const auto& v = get(key);
  if (!v.is_string()) fail(key, "must be a string, got " + shown(v));
  return v.get<std::string>();
}

std::string JsonFields::text(const std::string& key, const std::string& fallback) const {
  if (!obj_.contains(key)) { used_.insert(key); return fallback; }
  return text(key);
}

static std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& a : v) s += (s.empty() ? "" : ", ") + a;
  return s;
}

std::string JsonFields::choice(const std::string& key, const std::vector<std::string>& allowed) const {
  const auto& v = get(key);
  if (v.is_string())
    for (const auto& a : allowed)
      if (a == v.get<std::string>()) return a;
  fail(key, "must be one of {" + join(allowed) + "}, got " + shown(v));
}

std::string JsonFields::choice(const std::string& key, const std::vector<std::string>& allowed,
                               const std::string& fallback) const {
  if (!obj_.contains(key)) { used_.insert(key); return fallback; }
  return choice(key, allowed);
}

std::array<double, 3> JsonFields::vector(const std::string& key, int n) const {
  const auto& v = get(key);
  const std::string want = "must be an array of " + std::to_string(n) + " finite numbers";
  if (!v.is_array() || static_cast<int>(v.size()) != n) fail(key, want + ", got " + shown(v));
  std::array<double, 3> out{0, 0, 0};
  for (int a = 0; a < n; ++a) {
    if (!v[a].is_number() || !std::isfinite(v[a].get<double>())) fail(key, want + ", got " + shown(v));
    out[a] = v[a].get<double>();
  }
  return out;
}

std::array<double, 3> JsonFields::vector(const std::string& key, int n, std::array<double, 3> fallback) const {
  if (!obj_.contains(key)) { used_.insert(key); return fallback; }
  return vector(key, n);
}

namespace {

// v as a list of points of n finite numbers, or an empty optional if it is not one.
bool read_points(const nlohmann::json& v, int n, std::vector<std::array<double, 3>>& out) {
  if (!v.is_array()) return false;
  for (const auto& p : v) {
    if (!p.is_array() || static_cast<int>(p.size()) != n) return false;
    std::array<double, 3> q{0, 0, 0};
    for (int a = 0; a < n; ++a) {
      if (!p[a].is_number() || !std::isfinite(p[a].get<double>())) return false;
      q[a] = p[a].get<double>();
    }
    out.push_back(q);
  }
  return true;
}

}  // namespace

std::vector<std::array<double, 3>> JsonFields::points(const std::string& key, int n) const {
  const auto& v = get(key);
  std::vector<std::array<double, 3>> out;
  if (!read_points(v, n, out))
    fail(key, "must be an array of points, each an array of " + std::to_string(n) + " finite numbers, got " + shown(v));
  return out;
}

std::vector<std::vector<std::array<double, 3>>> JsonFields::point_lists(const std::string& key, int n) const {
  if (!obj_.contains(key)) { used_.insert(key); return {}; }
  const auto& v = get(key);
  const std::string want = "must be an array of point arrays (each point " + std::to_string(n) + " finite numbers)";
  if (!v.is_array()) fail(key, want + ", got " + shown(v));
  std::vector<std::vector<std::array<double, 3>>> out;
  for (const auto& e : v) {
    out.emplace_back();
    if (!read_points(e, n, out.back())) fail(key, want + ", got " + shown(v));
  }
  return out;
}

std::vector<std::string> JsonFields::texts(const std::string& key, const std::vector<std::string>& allowed) const {
  if (!obj_.contains(key)) { used_.insert(key); return {}; }
  const auto& v = get(key);
  const std::string want = "must be an array of strings from {" + join(allowed) + "}";
  if (!v.is_array()) fail(key, want + ", got " + shown(v));
  std::vector<std::string> out;
  for (const auto& e : v) {
    bool ok = e.is_string();
    if (ok) { ok = false; for (const auto& a : allowed) ok = ok || a == e.get<std::string>(); }
    if (!ok) fail(key, want + ", got " + shown(e));
    out.push_back(e.get<std::string>());
  }
  return out;
}

JsonFields JsonFields::object(const std::string& key) const {
  const auto& v = get(key);
  if (!v.is_object()) fail(key, "must be a JSON object, got " + shown(v));
  return JsonFields(v, file_, where(key));
}

std::optional<JsonFields> JsonFields::optional_object(const std::string& key) const {
  if (!obj_.contains(key)) { used_.insert(key); return std::nullopt; }
  return object(key);
}

std::vector<JsonFields> JsonFields::array_of_objects(const std::string& key) const {
  const auto& v = get(key);
  if (!v.is_array() || v.empty()) fail(key, "must be a non-empty array of JSON objects, got " + shown(v));
  std::vector<JsonFields> out;
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (!v[k].is_object()) fail(key + "[" + std::to_string(k) + "]", "must be a JSON object, got " + shown(v[k]));
    out.emplace_back(v[k], file_, where(key) + "[" + std::to_string(k) + "]");
  }
  return out;
}

std::vector<std::string> JsonFields::keys() const {
  std::vector<std::string> k;
  for (auto it = obj_.begin(); it != obj_.end(); ++it) k.push_back(it.key());
  return k;
}

void note_scene_field(const std::string& tag, const std::string& key);  // io/scene_reference.cpp

void JsonFields::reject_unknown() const {
  for (const auto& u : used_) note_scene_field(tag_.empty() ? "(untagged) " + path_ : tag_, u);
  for (auto it = obj_.begin(); it != obj_.end(); ++it) {
    if (!used_.count(it.key())) {
      std::set<std::string> fields(used_);
      if (!tag_.empty())
        for (const auto& k : documented_keys(tag_)) fields.insert(k);
      std::string known;
      for (const auto& u : fields) known += (known.empty() ? "" : ", ") + u;
      fail(it.key(), "is not a known field here (known: " + known + ")");
    }
  }
}

}  // namespace geosph
