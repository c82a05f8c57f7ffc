// Running a function on a thread with a large stack, for recursive descents over input nested thousands deep.
#pragma once

#include <cstddef>
#include <functional>

namespace wardray {

/// Runs `work` to completion on a new thread whose stack holds `stack_bytes` (reserved, committed only as used),
/// passing it that size, or 0 when no such thread could be made and `work` runs on the calling thread instead.
/// An exception `work` throws is rethrown here.
void run_with_stack(std::size_t stack_bytes, const std::function<void(std::size_t stack_bytes)>& work);

/// Under AddressSanitizer, clears the poison of every frame between here and the top of the run_with_stack thread
/// this runs on; elsewhere, and in other builds, does nothing. ASan does this itself when an exception is thrown,
/// but refuses when more than 64 MB of stack is in use (google/sanitizers#189), and the stale poison of the
/// unwound frames then shows up as false stack-buffer-overflow reports. Called where the parser's exceptions are
/// constructed, just before they are thrown from deep in a descent.
void unpoison_stack_above_here() noexcept;

}  // namespace wardray
