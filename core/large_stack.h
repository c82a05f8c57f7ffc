// Running a function on a thread with a large stack, for recursive descents over input nested thousands deep.
#pragma once

#include <cstddef>
#include <functional>

namespace wardray {

/// Runs `work` to completion on a new thread whose stack holds `stack_bytes` (reserved, committed only as used),
/// passing it that size, or 0 when no such thread could be made and `work` runs on the calling thread instead.
/// An exception `work` throws is rethrown here.
void run_with_stack(std::size_t stack_bytes, const std::function<void(std::size_t stack_bytes)>& work);

}  // namespace wardray
