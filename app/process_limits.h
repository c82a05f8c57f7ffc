// What this machine can hold: images refused before they are allocated, and the heap bounded by its memory.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace wardray::app {

/// Why a width x height image cannot fit in this machine's memory (about 32 bytes a pixel); empty when it fits.
std::optional<std::string> image_too_large(int width, int height);

/// Bounds the heap by the machine's memory, so a scene that grows without end fails with bad_alloc (reported at
/// its location) instead of waking the kernel's OOM killer, which may pick another process.
void limit_heap_to_machine_memory();

/// The process's peak resident memory so far, in bytes (0 where the system does not say).
std::size_t peak_resident_bytes();

}  // namespace wardray::app
