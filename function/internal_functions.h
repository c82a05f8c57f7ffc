// POV-Ray's built-in functions behind functions.inc's `function { internal(n) }`: their parameter counts, and the
// ones wardray evaluates.
#pragma once

#include <cstddef>

#include "function/function_vm.h"

namespace wardray::function {

/// An internal function over its arguments: x, y, z, then its own parameters P0, P1, ...
using InternalFunction = double (*)(const double* args, const EvalContext& context);

/// How many arguments internal function `n` takes (x, y, z and its parameters), or 0 for no such function.
std::size_t internal_function_arity(int n);

/// Internal function `n`, or null when it is not evaluated yet.
InternalFunction internal_function(int n);

}  // namespace wardray::function
