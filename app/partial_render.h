// POV-Ray's partial renders: +SR/+ER/+SC/+EC resolved to the pixels they name.
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "app/options.h"
#include "render/renderer.h"

namespace wardray::app {

/// The pixels a partial render covers, as POV-Ray 3.7 reads the switches: a start below 1 is a fraction of the
/// size (row floor(f × height), counting from 0), else a pixel number from 1; an end of at most 1 is a fraction
/// (up to floor(f × height)), else a pixel number. Empty when no edge is given (the whole image); the message
/// says what is wrong ("+SR40 is below the image's 30 rows").
std::variant<std::optional<render::PixelRegion>, std::string> resolve_region(const RegionOptions& region, int width,
                                                                             int height);

}  // namespace wardray::app
