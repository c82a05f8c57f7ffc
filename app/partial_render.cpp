// POV-Ray's partial renders: fractions and pixel numbers to a pixel rectangle.
#include "app/partial_render.h"

#include <algorithm>
#include <cmath>

namespace wardray::app {

namespace {

// POV-Ray compat (measured with povray 3.7: +SR0.25 of 30 rows starts at row 8, +SR1 at row 1, +ER1 is the
// last row, +ER2.5 row 2): the first pixel (from 0) and one past the last.
int first_pixel(std::optional<double> v, int size) {
    if (!v) return 0;
    return *v < 1.0 ? static_cast<int>(std::floor(*v * size)) : static_cast<int>(*v) - 1;
}

int end_pixel(std::optional<double> v, int size) {
    if (!v) return size;
    return std::min(size, *v <= 1.0 ? static_cast<int>(std::floor(*v * size)) : static_cast<int>(*v));
}

}  // namespace

std::variant<std::optional<render::PixelRegion>, std::string> resolve_region(const RegionOptions& r, int width,
                                                                             int height) {
    if (!r.start_row && !r.end_row && !r.start_column && !r.end_column) return std::optional<render::PixelRegion>{};
    const render::PixelRegion region{first_pixel(r.start_column, width), first_pixel(r.start_row, height),
                                     end_pixel(r.end_column, width), end_pixel(r.end_row, height)};
    if (region.y0 >= height) return "the start row is below the image's " + std::to_string(height) + " rows";
    if (region.x0 >= width) return "the start column is right of the image's " + std::to_string(width) + " columns";
    if (region.y1 <= region.y0) return "the end row is above the start row: no row to render";
    if (region.x1 <= region.x0) return "the end column is left of the start column: no column to render";
    return std::optional<render::PixelRegion>{region};
}

}  // namespace wardray::app
