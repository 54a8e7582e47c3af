#pragma once
// A 5 x 7 bitmap font (printable ASCII) for the labels of the in-process map images
// (app/simulate/map_image.h). Characters it has no glyph for are drawn as '?'.
namespace rangesim::app {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7;

// The glyph's 7 rows, top first; bit 4 of a row is its leftmost column.
const unsigned char* glyph_rows(char c);

}  // namespace rangesim::app
