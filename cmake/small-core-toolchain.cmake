# A toolchain file for the small-device core on a bare-metal core (any -mcpu, with or without
# an FPU), for a GCC cross compiler. With SHITSUKAN_SMALL_CORE_ONLY=ON it builds
# libshitsukan.a from lib/shitsukan/small_device_sources.txt alone (no exceptions, no RTTI, no
# allocation, no stdio); your firmware links it with its own start-up code (ports/cortex-m/
# README.md says what a port provides). For example:
#
#   cmake -S . -B build-m0 -DCMAKE_TOOLCHAIN_FILE=cmake/small-core-toolchain.cmake \
#         -DSHITSUKAN_SMALL_CORE_ONLY=ON -DCMAKE_BUILD_TYPE=MinSizeRel \
#         "-DSHITSUKAN_CPU_FLAGS=-mcpu=cortex-m0 -mthumb -mfloat-abi=soft"
#   cmake --build build-m0
#
# Another GCC cross compiler: -DSHITSUKAN_CROSS=<prefix>- with its own SHITSUKAN_CPU_FLAGS (it
# needs the C++ headers of its C library: <cmath>, <cstdint>, <cstring>).
#
# A core without an FPU works: the float and double arithmetic becomes soft-float library
# calls, the results are the same bits (IEEE arithmetic, -ffp-contract=off, the library's own
# elementary functions), only slower.
set(CMAKE_SYSTEM_NAME Generic)
set(SHITSUKAN_CROSS "arm-none-eabi-" CACHE STRING "Prefix of the cross compiler's tools")
set(SHITSUKAN_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"
    CACHE STRING "Flags that choose the core (-mcpu, -mthumb, -mfpu, -mfloat-abi, -march, -mabi)")
set(CMAKE_C_COMPILER "${SHITSUKAN_CROSS}gcc")
set(CMAKE_CXX_COMPILER "${SHITSUKAN_CROSS}g++")
set(CMAKE_C_FLAGS_INIT "${SHITSUKAN_CPU_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT "${SHITSUKAN_CPU_FLAGS}")
# No start-up code or linker script here: the compiler checks build a static library.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES SHITSUKAN_CROSS SHITSUKAN_CPU_FLAGS)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
