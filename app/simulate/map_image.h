#pragma once
// The heat-map images of `rangesim simulate` (range_map.png, range_error.png), drawn in-process:
// one map cell an s x s square (s from 1 to 8: the map at least 200 px across, a full
// ls-conventional map one pixel a cell), NaN cells blank,
// a frame with ticks and their values, the title, both axis labels and a colour bar with its
// values and label, in a 5 x 7 bitmap font drawn at twice its size (app/simulate/bitmap_font.h),
// written as an indexed-colour PNG (app/simulate/png_writer.h). Rows are drawn from the first at
// the bottom, as gnuplot's `matrix with image` did. A map costs a few milliseconds, where gnuplot
// took about a second of CPU for the two images of a full ls-conventional map (parsing the text
// matrix and cairo drawing).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/matrix_rows.h"

namespace rangesim::app {

enum class MapPalette { Viridis, Diverging };

struct MapImageSpec {
  std::string title, x_label, y_label, colour_label;
  double lo = 0, hi = 1;  // colour range: values beyond it take the end colours
  MapPalette palette = MapPalette::Viridis;
  int first_row = 0;  // the y value of the map's row 0
};

// A map row's palette indices at one pixel a cell: the ramp's colour of each finite value on
// [lo, lo + span] (clamped to its ends), index 0 (paper) for NaN and inf.
void map_row_colours(const double* values, int n, double lo, double span, std::uint8_t* out);

// The q-quantile (0 <= q <= 1; the element of rank floor(q (n - 1)) from the smallest) of |a - b|
// over the cells where both maps have a value and the difference is finite, in single precision:
// a colour scale's end, not a figure. -1 where there is no such cell.
double abs_difference_quantile(MatrixRows a, MatrixRows b, double q);

// Draws maps into one image buffer, reused from map to map (a map's first-touched pages cost more
// than drawing it).
class MapImageWriter {
 public:
  MapImageWriter();
  ~MapImageWriter();
  // Takes the memory for such a map's image now, on the calling thread, to be drawn on another:
  // `simulate`'s main thread has its heap on huge pages (app/large_array_pages.h), where a helper
  // thread's own allocator arena took 170 first touches of 4 KB pages for the two images of a full
  // ls-conventional map (1 with this), and the output's CPU 5.07 against 4.47 ms (medians of 61
  // alternating runs).
  void reserve(int rows, int columns, const MapImageSpec& spec);
  // A rows x columns map whose row r row_values(r, v) puts in v[0 .. columns); throws
  // std::runtime_error naming the path when it cannot be written.
  void write(const std::string& path, int rows, int columns, const std::function<void(int, double*)>& row_values,
             const MapImageSpec& spec);

 private:
  struct Buffers;
  std::unique_ptr<Buffers> b_;
};

}  // namespace rangesim::app
