#pragma once
// NumPy .npy files (format version 1.0, what numpy.load reads): a 2-D float64 matrix, or a 1-D
// record array with one named field per table column. Large outputs go to disk as raw
// little-endian doubles: no text to format, and full precision.
#include <string>
#include <vector>

#include "app/matrix_rows.h"
#include "systemc/common/table.h"

namespace rangesim::app {

// Written straight to the file `path`, never whole in memory (a full ls-conventional map's points
// are 12 MB); std::runtime_error if the write fails.
// `rows` as a C-order float64 array of shape (rows, columns); every row must have `columns`
// values. NaN stays NaN.
void write_npy_matrix(const std::string& path, MatrixRows rows, std::size_t columns);
// `t` as a record array of shape (rows,): integer columns '<i8', the others '<f8' (NaN = empty).
void write_npy_table(const std::string& path, const systemc::Table& t);

}  // namespace rangesim::app
