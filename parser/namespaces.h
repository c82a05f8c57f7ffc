// The parser's own namespace sees the scene description it fills and the function VM it compiles to.
#pragma once

#include "function/function_vm.h"
#include "scene/scene.h"

namespace wardray::parser {

using namespace wardray::scene;     // NOLINT(google-build-using-namespace): the parser builds these types
using namespace wardray::function;  // NOLINT(google-build-using-namespace): and compiles to these

}  // namespace wardray::parser
