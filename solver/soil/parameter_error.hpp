// The error of a point model's validate(): std::invalid_argument "<field> must be <range>, got <value>"
// (an angle given in radians is reported in degrees), which the scene reader turns into an error
// naming the file and the material's field.
#pragma once
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace geosph::soil {

[[noreturn]] inline void reject_parameter(const std::string& field, const std::string& range, double value,
                                          bool in_degrees = false) {
  std::ostringstream msg;
  msg.precision(10);
  msg << field << " must be " << range << ", got ";
  if (in_degrees)
    msg << value * 180.0 / std::numbers::pi << " degrees";
  else
    msg << value;
  throw std::invalid_argument(msg.str());
}

}  // namespace geosph::soil
