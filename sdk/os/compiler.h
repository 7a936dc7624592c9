// What the core asks of the compiler beyond standard C++17, in one place (docs/platforms.md).
#pragma once

// Inlines a small hot function (a lambda in the A* inner loop) that the compiler would otherwise call.
#if defined(__GNUC__) || defined(__clang__)
#define NL_ALWAYS_INLINE __attribute__((always_inline))
#else
#define NL_ALWAYS_INLINE  // MSVC has no attribute for lambdas; the loop is only slower
#endif
