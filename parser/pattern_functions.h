// Pattern and pigment functions: `function { pattern { ... } }` and `function { pigment { ... } }` as calls the
// function VM makes, evaluated by the texture layer through the callbacks of ParseOptions.
#pragma once

#include <memory>
#include <string_view>

#include "parser/parse.h"
#include "parser/splines.h"

namespace wardray::parser {

/// The function VM's call of a pattern function: the pattern's value at (x, y, z).
std::shared_ptr<const ExternalFunction> make_pattern_function(std::shared_ptr<const Pigment> block,
                                                              const ParseOptions& options);

/// The function VM's call of one channel of a pigment function (`F(x, y, z).red` and the like).
std::shared_ptr<const ExternalFunction> make_pigment_channel(std::shared_ptr<const Pigment> block, int channel,
                                                             const ParseOptions& options);

/// The function VM's call of one component of a spline function (`S(t).y`): the spline at its first argument.
std::shared_ptr<const ExternalFunction> make_spline_channel(std::shared_ptr<const Spline> spline, int channel);

/// The channel a dot item names: 0..4 red/x/u, green/y/v, blue/z, filter/t, transmit; 5 gray; 6 hf; -1 none.
int pigment_channel(std::string_view item);

/// Channel `channel` of a colour (5: POV-Ray's grey, 0.297 R + 0.589 G + 0.114 B;
/// 6: `.hf`, (R + G / 255) * 0.996093).
double channel_value(const Color& c, int channel);

}  // namespace wardray::parser
