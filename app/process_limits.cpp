// What this machine can hold: images refused before they are allocated, and the heap bounded by its memory.
#include "app/process_limits.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <sstream>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WARDRAY_HAS_ASAN 1
#endif
#endif
#ifndef WARDRAY_HAS_ASAN
#define WARDRAY_HAS_ASAN 0
#endif

namespace wardray::app {

// A film of floats, the antialiasing buffers and the writer's copy: about 32 bytes a pixel, asked for before
// anything is parsed or allocated.
std::optional<std::string> image_too_large(int width, int height) {
    constexpr double k_bytes_per_pixel = 32.0;
    const double needed = static_cast<double>(width) * height * k_bytes_per_pixel;
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page_size <= 0) return std::nullopt;
    const double memory = static_cast<double>(pages) * static_cast<double>(page_size);
    if (needed <= memory) return std::nullopt;
    constexpr double k_gib = 1024.0 * 1024.0 * 1024.0;
    std::ostringstream s;
    s.precision(3);
    s << "a " << width << "x" << height << " image needs about " << needed / k_gib
      << " GiB for its pixels, more than this machine's " << memory / k_gib << " GiB of memory";
    return s.str();
}

void limit_heap_to_machine_memory() {
#if defined(__SANITIZE_ADDRESS__) || WARDRAY_HAS_ASAN
    // AddressSanitizer's shadow memory counts as data: under any such limit every later allocation fails.
    return;
#endif
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGESIZE);
    rlimit limit{};
    if (pages <= 0 || page_size <= 0 || getrlimit(RLIMIT_DATA, &limit) != 0) return;
    const auto memory = static_cast<rlim_t>(pages) * static_cast<rlim_t>(page_size);
    if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur <= memory) return;
    limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? memory : std::min(memory, limit.rlim_max);
    setrlimit(RLIMIT_DATA, &limit);
}

std::size_t peak_resident_bytes() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0 || usage.ru_maxrss < 0) return 0;
    return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

}  // namespace wardray::app
