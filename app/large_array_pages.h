#pragma once
// The rangesim executable's memory on transparent huge pages (app/large_array_pages.cpp).

namespace rangesim::app {

// Called by main before `simulate`: the heap the process grows from here on is advised onto 2 MB
// pages.
void heap_on_huge_pages();

}  // namespace rangesim::app
