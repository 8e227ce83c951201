// One particle's neighbour values as contiguous columns, reused across particles (keep one per thread).
// A pair loop reads the neighbours' arrays (j-indexed, scattered) once, in a scalar pass that fills the
// columns, and then does its arithmetic over the columns alone: that loop has no indirect reads and
// vectorises, and its per-pair results are summed in neighbour order afterwards, so the sums are the
// scalar loop's, bit for bit.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

namespace geosph {

class PairColumns {
 public:
  // Room for `rows` neighbours in `cols` columns; the columns' contents are not kept.
  void reserve(std::size_t rows, int cols) {
    const std::size_t need = rows * static_cast<std::size_t>(cols);
    if (rows > rows_ || need > data_.size()) {
      rows_ = std::max(rows, rows_);
      data_.resize(rows_ * static_cast<std::size_t>(cols));
    }
  }
  double* col(int c) { return data_.data() + static_cast<std::size_t>(c) * rows_; }

 private:
  std::vector<double> data_;
  std::size_t rows_ = 0;
};

}  // namespace geosph
