// POV-Ray 3.7's numeric constants, defined once for every layer that reproduces its arithmetic.
#pragma once

namespace wardray {

/// POV-Ray's EPSILON (frame.h): its tolerance for equal floats, grazing angles and degenerate lengths.
inline constexpr double kPovEpsilon = 1.0e-10;

}  // namespace wardray
