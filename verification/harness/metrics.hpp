// Error measures shared by the catalogue cases.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace geosph::verify {

// sqrt( sum (a - b)^2 / sum b^2 )
double relative_l2(const std::vector<double>& sim, const std::vector<double>& ref);
// sqrt( mean (a - b)^2 ) / scale
double scaled_rms(const std::vector<double>& sim, const std::vector<double>& ref, double scale);
// Piecewise-linear interpolation of (x, y) at xq (x increasing); clamps outside the range.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double xq);
// Observed order p from errors e1 (spacing dx1) and e2 (dx2): e ~ dx^p.
double observed_order(double dx1, double e1, double dx2, double e2);

// Richardson extrapolation to dx -> 0 of a quantity q(dx) computed at spacings dx (coarse to fine,
// constant ratio): q_f + (q_f - q_c)/(r^p - 1) from the two finest; p is observed from the last three
// values when there are three and they converge monotonically, else `expected_order`.
struct Extrapolation {
  double value = 0, order = 0;
  bool order_observed = false;
};
Extrapolation richardson(const std::vector<double>& dx, const std::vector<double>& q, double expected_order);

// Two-column numeric CSV; lines starting with '#' are the provenance header (returned).
struct Csv {
  std::vector<std::string> header_comments, columns;
  std::vector<std::vector<double>> data;  // data[column][row]
  const std::vector<double>& column(const std::string& name) const;
  std::string comment(const std::string& key) const;  // value of a '# key: value' line
  double comment_number(const std::string& key) const;  // its leading number; NaN when absent
  std::string file;
};
Csv read_csv(const std::string& path);
// The rows of a CSV with text cells: '#' lines (the provenance header) and the column-name line skipped.
std::vector<std::vector<std::string>> read_csv_rows(const std::string& path);

struct Record;
// For records of one case at successive spacings (coarse to fine): the observed order of the first
// metric between each pair, stored on the finer record as "observed_order", and the expected
// order (if >= 0) as "expected_order".
void annotate_observed_order(std::vector<Record>& records, double expected_order);

}  // namespace geosph::verify
