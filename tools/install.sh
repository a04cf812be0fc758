#!/usr/bin/env bash
# make install, after the library and the tool are built: headers, libshitsukan.a, the
# shitsukan tool, shitsukan.pc for pkg-config and a CMake package (shitsukanConfig.cmake and
# its version file) under DESTDIR/PREFIX. Needs only a compiler: no test framework, no apt-get
# (without the stb header write_png uses the library's own, uncompressed PNG encoder). The
# version is core/config.hpp's.
#
# Usage: tools/install.sh PREFIX LIBRARY CLI   (DESTDIR from the environment, as make passes it)
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=$1 library=$2 cli=$3
root=${DESTDIR:-}$prefix
version=$(sed -n 's/^#define SHITSUKAN_VERSION_STRING "\(.*\)"/\1/p' lib/shitsukan/core/config.hpp)
major=${version%%.*}
minor=${version#*.}; minor=${minor%%.*}
run() { echo "$*"; "$@"; }
mkdir -p "$root/include" "$root/lib/pkgconfig" "$root/lib/cmake/shitsukan" "$root/bin"
run install -m 755 "$cli" "$root/bin/shitsukan"
echo "install -m 644 lib/shitsukan/**/*.hpp $root/include/shitsukan/"
(cd lib && find shitsukan -name '*.hpp' -exec install -D -m 644 {} "$root/include/{}" \;)
run install -m 644 "$library" "$root/lib/libshitsukan.a"
echo "cmake/shitsukan.pc.in -> $root/lib/pkgconfig/shitsukan.pc"
sed -e "s|@SHITSUKAN_PC_PREFIX@|$prefix|" -e 's|@SHITSUKAN_PC_INCLUDEDIR@|${prefix}/include|' \
    -e 's|@SHITSUKAN_PC_LIBDIR@|${prefix}/lib|' -e "s|@SHITSUKAN_PC_VERSION@|$version|" \
    cmake/shitsukan.pc.in > "$root/lib/pkgconfig/shitsukan.pc"
run install -m 644 cmake/shitsukanConfig-make.cmake.in "$root/lib/cmake/shitsukan/shitsukanConfig.cmake"
echo "cmake/shitsukanConfigVersion-make.cmake.in -> $root/lib/cmake/shitsukan/shitsukanConfigVersion.cmake"
sed -e "s|@VERSION@|$version|" -e "s|@MAJOR@|$major|" -e "s|@MINOR@|$minor|" \
    cmake/shitsukanConfigVersion-make.cmake.in > "$root/lib/cmake/shitsukan/shitsukanConfigVersion.cmake"
echo "installed shitsukan $version into $root"
