// Whether this build runs under AddressSanitizer (GCC's __SANITIZE_ADDRESS__ or clang's __has_feature), whose
// frames, speed and memory differ enough for limits and tests to take it into account.
#pragma once

namespace wardray {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool k_address_sanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool k_address_sanitizer = true;
#else
inline constexpr bool k_address_sanitizer = false;
#endif
#else
inline constexpr bool k_address_sanitizer = false;
#endif

}  // namespace wardray
