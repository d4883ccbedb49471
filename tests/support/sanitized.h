#pragma once

/// Whether this test binary is built with AddressSanitizer (`make test-sanitize`). The sanitizer
/// build runs the whole suite once more to catch memory and undefined-behaviour errors, about ten
/// times slower; the few tests whose instances are large only to make a property likely to show
/// run a smaller instance there (the same code paths, fewer of them), and the full instance in
/// `make test`.

namespace vantage::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizer = true;
#else
inline constexpr bool kUnderSanitizer = false;
#endif
#else
inline constexpr bool kUnderSanitizer = false;
#endif

}  // namespace vantage::testing
