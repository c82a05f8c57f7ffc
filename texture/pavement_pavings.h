// The pavings of POV-Ray 3.7's pavement pattern: for each cell shape, number of tiles and pattern number, the code of
// each cell over one period and how the period repeats.
#pragma once

#include <cstdint>
#include <vector>

namespace wardray::texture {

/// How a cell's integer coordinates pick its code in a paving's table (`rows` rows of `width` codes). Unless
/// `along_x`, the paving repeats every `period` cells in z, and the row `r` of that period is shifted `shear` cells
/// in x every `step` rows; with `along_x` the roles swap: it repeats every `period` cells in x, and the column is
/// shifted `shear` cells in z every `step` columns.
struct Lattice {
    int width;
    int rows;
    int period;
    int shear;
    int step;
    bool along_x;
};

/// One paving: its lattice and its cell codes, row after row.
struct Paving {
    Lattice lattice;
    std::vector<std::uint16_t> cells;
};

/// The pavings of squares, triangles and hexagons: [number_of_tiles - 1][pattern - 1].
const std::vector<std::vector<Paving>>& square_pavings();
const std::vector<std::vector<Paving>>& triangle_pavings();
const std::vector<std::vector<Paving>>& hexagon_pavings();

}  // namespace wardray::texture
