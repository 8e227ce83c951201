// The slip line of a failure wedge behind a translated wall, read from a displacement field the way
// reference/dem/postprocess.py (`wall`) reads the grains', so that SPH and DEM are measured alike.
#pragma once
#include <vector>

namespace geosph::verify {

struct SlipLine {
  std::vector<double> x, y;  // slip points, in units of H (x from the wall, y from the floor)
  double angle_deg = 0;      // least-squares angle from the horizontal over the strips centred at 0.15-0.85 H; NaN under 3 points
};

// Positions (x0, y0) before the move, relative to the wall's foot, and horizontal displacements ux.
// Per 0.1 H strip, the slip point is the x where the median of `sign(travel) ux` over bins `bin` wide
// (a running median of three bins) first falls below half the wall's travel |travel|, interpolated
// between bin centres; points behind Lb are ignored.
SlipLine slip_line(const std::vector<double>& x0, const std::vector<double>& y0, const std::vector<double>& ux,
                   double H, double Lb, double bin, double travel);

// The least-squares angle [deg from the horizontal] of points (x, y) [units of H] over 0.1 < y < 0.9,
// i.e. the eight strips centred at 0.15-0.85 (the bottom strip is disturbed by the wall-floor corner,
// the top one by the settling surface); NaN under 3 points.
double wedge_angle_deg(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace geosph::verify
