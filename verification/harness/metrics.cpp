#include "harness/metrics.hpp"

#include "harness/record.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/json_fields.hpp"

namespace geosph::verify {

double relative_l2(const std::vector<double>& sim, const std::vector<double>& ref) {
  if (sim.size() != ref.size() || ref.empty()) throw std::invalid_argument("relative_l2: size mismatch");
  double num = 0, den = 0;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    num += (sim[k] - ref[k]) * (sim[k] - ref[k]);
    den += ref[k] * ref[k];
  }
  return std::sqrt(num / den);
}

double scaled_rms(const std::vector<double>& sim, const std::vector<double>& ref, double scale) {
  if (sim.size() != ref.size() || ref.empty()) throw std::invalid_argument("scaled_rms: size mismatch");
  double s = 0;
  for (std::size_t k = 0; k < ref.size(); ++k) s += (sim[k] - ref[k]) * (sim[k] - ref[k]);
  return std::sqrt(s / ref.size()) / scale;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double xq) {
  if (x.empty()) throw std::invalid_argument("interpolate: empty series");
  if (xq <= x.front()) return y.front();
  if (xq >= x.back()) return y.back();
  std::size_t k = 1;
  while (x[k] < xq) ++k;
  const double w = (xq - x[k - 1]) / (x[k] - x[k - 1]);
  return (1 - w) * y[k - 1] + w * y[k];
}

double observed_order(double dx1, double e1, double dx2, double e2) { return std::log(e1 / e2) / std::log(dx1 / dx2); }

Extrapolation richardson(const std::vector<double>& dx, const std::vector<double>& q, double expected_order) {
  Extrapolation e;
  e.order = expected_order;
  const std::size_t n = q.size();
  if (n < 2) { e.value = n == 1 ? q[0] : NAN; return e; }
  if (n >= 3) {
    const double d1 = q[n - 2] - q[n - 3], d2 = q[n - 1] - q[n - 2];
    if (d1 != 0 && d2 / d1 > 0) { e.order = observed_order(dx[n - 3], d1, dx[n - 2], d2); e.order_observed = true; }
  }
  e.value = q[n - 1] + (q[n - 1] - q[n - 2]) / (std::pow(dx[n - 2] / dx[n - 1], e.order) - 1.0);
  return e;
}

const std::vector<double>& Csv::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return data[c];
  throw InputError(file + ": no column '" + name + "'");
}

std::string Csv::comment(const std::string& key) const {
  for (const auto& line : header_comments) {
    const auto pos = line.find(':');
    if (pos != std::string::npos && line.substr(0, pos) == key) {
      auto v = line.substr(pos + 1);
      return v.substr(v.find_first_not_of(' ') == std::string::npos ? 0 : v.find_first_not_of(' '));
    }
  }
  return "";
}

double Csv::comment_number(const std::string& key) const {
  const std::string v = comment(key);
  return v.empty() ? NAN : std::stod(v);
}

std::vector<std::vector<std::string>> read_csv_rows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open reference data");
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool names = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (names) { names = false; continue; }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

Csv read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open reference data");
  Csv csv;
  csv.file = path;
  std::string line;
  long row = 0;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty()) continue;
    if (line[0] == '#') {
      auto s = line.substr(1);
      csv.header_comments.push_back(s.substr(s.find_first_not_of(' ') == std::string::npos ? 0 : s.find_first_not_of(' ')));
      continue;
    }
    std::stringstream ss(line);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (csv.columns.empty()) {
      csv.columns = cells;
      csv.data.resize(cells.size());
      continue;
    }
    if (cells.size() != csv.columns.size()) throw InputError(path + ": line " + std::to_string(row) + ": wrong number of columns");
    for (std::size_t c = 0; c < cells.size(); ++c) {
      try {
        csv.data[c].push_back(std::stod(cells[c]));
      } catch (const std::exception&) {
        throw InputError(path + ": line " + std::to_string(row) + ": '" + cells[c] + "' is not a number");
      }
    }
  }
  if (csv.columns.empty() || csv.data[0].empty()) throw InputError(path + ": no data rows");
  return csv;
}



void annotate_observed_order(std::vector<Record>& records, double expected_order) {
  for (std::size_t k = 0; k < records.size(); ++k) {
    if (expected_order >= 0) records[k].extra["expected_order"] = expected_order;
    if (k == 0) continue;
    const Record &c = records[k - 1], &f = records[k];
    if (!c.stable || !f.stable || c.metrics.empty() || f.metrics.empty()) continue;
    const double e1 = c.metrics[0].value, e2 = f.metrics[0].value;
    if (e1 > 0 && e2 > 0 && c.dx != f.dx) records[k].extra["observed_order"] = observed_order(c.dx, e1, f.dx, e2);
  }
}

}  // namespace geosph::verify
