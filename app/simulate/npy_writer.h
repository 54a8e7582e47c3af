#pragma once
// NumPy .npy files (format version 1.0, what numpy.load reads): a 2-D float64 matrix, or a 1-D
// record array with one named field per table column. Large outputs go to disk as raw
// little-endian doubles: no text to format, and full precision.
#include <string>
#include <vector>

#include "systemc/common/table.h"

namespace rangesim::app {

// `rows` as a C-order float64 array of shape (rows, columns); every row must have `columns`
// values. NaN stays NaN.
std::string npy_matrix(const std::vector<std::vector<double>>& rows, std::size_t columns);
// `t` as a record array of shape (rows,): integer columns '<i8', the others '<f8' (NaN = empty).
std::string npy_table(const systemc::Table& t);

}  // namespace rangesim::app
