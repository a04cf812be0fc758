// shitsukan/core/config.hpp — version and compile-time switches.
//
// Manual
//   std::printf("shitsukan %s\n", SHITSUKAN_VERSION_STRING);  // "0.2.0"
//   static_assert(SHITSUKAN_VERSION_MAJOR == 0, "the version as numbers too");
//   // SHITSUKAN_VERSION_STRING is also the .pc's Version and the CMake package version
//   // (CHANGELOG.md says what changed). Define before any shitsukan header:
//   //   SHITSUKAN_NO_ASSERT       to compile SHITSUKAN_ASSERT checks out;
//   //   SHITSUKAN_ASSERT(expr)    to route programmer-bug checks to your own handler
//   //                             (see assert.hpp).
#pragma once

#define SHITSUKAN_VERSION_MAJOR 0
#define SHITSUKAN_VERSION_MINOR 2
#define SHITSUKAN_VERSION_PATCH 0
#define SHITSUKAN_VERSION_STRING "0.2.0"

// Scalars: the library writes float (the papers' 4-byte reals, okada1987 §5: "4-byte
// floating point except the spline, 8-byte") and double only where a paper or precision
// demands it. There is no Float alias: the 0.1 one was used nowhere (CHANGELOG.md).
