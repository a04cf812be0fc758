#!/usr/bin/env bash
# `make test-consumers`: builds tests/consumer/main.cpp as an outside project four ways and
# runs it; every way must report the same version and the same image hash as the program
# linked directly against the Makefile's build/libshitsukan.a.
#   1. CMake add_subdirectory(<this clone>)
#   2. CMake FetchContent from this clone (git, at HEAD: commit your changes first)
#   3. CMake find_package after `cmake --install` of this clone's CMake build
#   4. pkg-config after `make install` (and find_package against that install too)
# and two traps of using it from outside:
#   5. a C++20 project through pkg-config stays C++20 (std::span; the .pc carries no -std)
#   6. add_subdirectory from a parent that set no build type still compiles the library with
#      -O (and a parent's own build type is left alone)
# and the small-device core alone (SHITSUKAN_SMALL_CORE_ONLY) for a Cortex-M0 without an FPU:
#   7. cmake/small-core-toolchain.cmake builds the listed sources, nothing allocates or throws
# Work happens in build/consumers/. Needs cmake, pkg-config, git and a compiler.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
work="$root/build/consumers"
rm -rf "$work"
mkdir -p "$work"
jobs="${JOBS:-2}"
# The consumers build the library without optimisation (faster to compile; the same bits:
# -ffp-contract=off, no fast-math, is what makes results independent of -O).
cmake_flags=(-DCMAKE_BUILD_TYPE= -DCMAKE_CXX_FLAGS=-O0 -Wno-dev)
hashes=()

run_consumer() {  # name, binary
  local out
  out="$("$2" "$work/$1.png")"
  echo "  $1: $out"
  hashes+=("${out##*hash }")
}

echo "-- reference: main.cpp linked with the Makefile's build/libshitsukan.a"
version="$(sed -n 's/^#define SHITSUKAN_VERSION_STRING "\(.*\)"/\1/p' "$root/lib/shitsukan/core/config.hpp")"
make -C "$root" --no-print-directory build/libshitsukan.a >/dev/null
${CXX:-g++} -std=c++17 -O2 -ffp-contract=off -DSHITSUKAN_EXPECTED_VERSION="\"$version\"" \
  -I"$root/lib" "$root/tests/consumer/main.cpp" "$root/build/libshitsukan.a" -o "$work/reference"
run_consumer reference "$work/reference"

echo "-- 1. add_subdirectory"
cmake -S "$root/tests/consumer" -B "$work/subdirectory" -DCONSUME=subdirectory \
  -DSHITSUKAN_DIR="$root" "${cmake_flags[@]}" >/dev/null
cmake --build "$work/subdirectory" -j "$jobs" >/dev/null
run_consumer subdirectory "$work/subdirectory/consumer"

echo "-- 2. FetchContent from the local clone (HEAD)"
cmake -S "$root/tests/consumer" -B "$work/fetchcontent" -DCONSUME=fetchcontent \
  -DSHITSUKAN_DIR="$root" -DSHITSUKAN_GIT_TAG="$(git -C "$root" rev-parse HEAD)" \
  "${cmake_flags[@]}" >/dev/null
cmake --build "$work/fetchcontent" -j "$jobs" >/dev/null
run_consumer fetchcontent "$work/fetchcontent/consumer"

echo "-- 3. find_package after cmake --install"
cmake -S "$root" -B "$work/lib-cmake" -DCMAKE_INSTALL_PREFIX="$work/prefix-cmake" \
  "${cmake_flags[@]}" >/dev/null
cmake --build "$work/lib-cmake" -j "$jobs" >/dev/null
cmake --install "$work/lib-cmake" >/dev/null
for f in include/shitsukan/shitsukan.hpp lib/libshitsukan.a lib/cmake/shitsukan/shitsukanConfig.cmake \
         lib/cmake/shitsukan/shitsukanConfigVersion.cmake lib/pkgconfig/shitsukan.pc; do
  [ -f "$work/prefix-cmake/$f" ] || { echo "cmake --install did not install $f"; exit 1; }
done
cmake -S "$root/tests/consumer" -B "$work/find_package" -DCONSUME=find_package \
  -DCMAKE_PREFIX_PATH="$work/prefix-cmake" "${cmake_flags[@]}" >/dev/null
cmake --build "$work/find_package" -j "$jobs" >/dev/null
run_consumer find_package "$work/find_package/consumer"
# Versions the package must refuse (0.x: only the same minor version matches).
for want in 9.9 0.1; do
  if cmake -S "$root/tests/consumer" -B "$work/find_package_$want" -DCONSUME=find_package \
       -DCMAKE_PREFIX_PATH="$work/prefix-cmake" -DSHITSUKAN_WANT="$want" \
       "${cmake_flags[@]}" >/dev/null 2>&1; then
    echo "test-consumers: find_package(shitsukan $want) accepted version $version"; exit 1
  fi
done
echo "  find_package(shitsukan 9.9) and (0.1) refused, as they should be"

echo "-- 4. pkg-config (and find_package) after make install"
make -C "$root" --no-print-directory install PREFIX="$work/prefix-make" >/dev/null
export PKG_CONFIG_PATH="$work/prefix-make/lib/pkgconfig"
pc_version="$(pkg-config --modversion shitsukan)"
# shellcheck disable=SC2046
${CXX:-g++} -DSHITSUKAN_EXPECTED_VERSION="\"$pc_version\"" -O2 "$root/tests/consumer/main.cpp" \
  $(pkg-config --cflags --libs shitsukan) -o "$work/pkg-config"
run_consumer pkg-config "$work/pkg-config"
cmake -S "$root/tests/consumer" -B "$work/find_package_make" -DCONSUME=find_package \
  -DCMAKE_PREFIX_PATH="$work/prefix-make" "${cmake_flags[@]}" >/dev/null
cmake --build "$work/find_package_make" -j "$jobs" >/dev/null
run_consumer find_package_make "$work/find_package_make/consumer"

echo "-- 5. a C++20 project through pkg-config (std::span)"
# shellcheck disable=SC2046
${CXX:-g++} -std=c++20 -O1 "$root/tests/consumer/cxx20_span.cpp" \
  $(pkg-config --cflags --libs shitsukan) -o "$work/cxx20" ||
  { echo "test-consumers: a C++20 consumer does not compile through pkg-config"; exit 1; }
echo "  $("$work/cxx20")"

echo "-- 6. add_subdirectory's compile flags for the library (configure only)"
# library_flags <dir>: the compile commands of the library's own sources, one a line.
library_flags() {
  python3 -c 'import json, sys
for c in json.load(open(sys.argv[1])):
    if "/lib/shitsukan/" in c["file"]: print(c["command"])' "$1/compile_commands.json"
}
cmake -S "$root/tests/consumer" -B "$work/subdirectory_plain" -DCONSUME=subdirectory \
  -DSHITSUKAN_DIR="$root" -DCMAKE_BUILD_TYPE= -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -Wno-dev >/dev/null
n_lib="$(library_flags "$work/subdirectory_plain" | wc -l)"
n_opt="$(library_flags "$work/subdirectory_plain" | grep -c -- ' -O[1-3s]\? ' || true)"
if [ "$n_lib" -eq 0 ] || [ "$n_opt" -ne "$n_lib" ]; then
  echo "test-consumers: with no build type, $n_opt of $n_lib library sources compile with -O"; exit 1
fi
echo "  no build type in the parent: all $n_lib library sources compile with -O"
cmake -S "$root/tests/consumer" -B "$work/subdirectory_debug" -DCONSUME=subdirectory \
  -DSHITSUKAN_DIR="$root" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
  -Wno-dev >/dev/null
if library_flags "$work/subdirectory_debug" | grep -q -- ' -O'; then
  echo "test-consumers: the library overrode the parent's Debug build type with an -O"; exit 1
fi
echo "  a parent's Debug build type is kept (no -O added)"

echo "-- 7. the small-device core alone for an FPU-less core (cmake/small-core-toolchain.cmake)"
if command -v arm-none-eabi-g++ >/dev/null 2>&1; then
  cmake -S "$root" -B "$work/small-m0" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/small-core-toolchain.cmake" \
    -DSHITSUKAN_SMALL_CORE_ONLY=ON -DCMAKE_BUILD_TYPE=MinSizeRel \
    "-DSHITSUKAN_CPU_FLAGS=-mcpu=cortex-m0 -mthumb -mfloat-abi=soft" -Wno-dev >/dev/null
  cmake --build "$work/small-m0" -j "$jobs" >/dev/null
  n_small="$(grep -c '^lib/.*\.cpp$' "$root/lib/shitsukan/small_device_sources.txt")"
  n_members="$(arm-none-eabi-ar t "$work/small-m0/libshitsukan.a" | wc -l)"
  if [ "$n_members" -ne "$n_small" ]; then
    echo "test-consumers: the small core holds $n_members objects, the list names $n_small"; exit 1
  fi
  if arm-none-eabi-nm -C "$work/small-m0/libshitsukan.a" | grep -E ' U (operator new|malloc|__cxa_throw)'; then
    echo "test-consumers: the small core for Cortex-M0 allocates or throws"; exit 1
  fi
  echo "  Cortex-M0 (soft float): the $n_small small-device sources build into libshitsukan.a"
else
  echo "  skipped: no arm-none-eabi-g++ (make test-mcu installs it)"
fi

for h in "${hashes[@]}"; do
  if [ "$h" != "${hashes[0]}" ]; then
    echo "test-consumers: image hashes differ between the ways of building: ${hashes[*]}"
    exit 1
  fi
done
echo "test-consumers: ${#hashes[@]} builds (Makefile, add_subdirectory, FetchContent," \
     "find_package x2, pkg-config) ran; same version $version, same image bits;" \
     "C++20 through pkg-config, add_subdirectory's -O and the small core alone checked"
