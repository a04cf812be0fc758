#!/usr/bin/env bash
# make check-api, after the library is built: the library as a dependency.
#   1. every header compiles on its own (it includes what it uses)
#   2. the umbrella header includes every header (tools/gen_umbrella.sh writes it)
#   3. the archive exports only shitsukan symbols (std:: template instances are weak, shared)
#   4. a program with its own stb_image_write implementation links and runs; built without the
#      stb header (as `make install` on a bare machine), PNGs still work; core/status.cpp
#      built with SHITSUKAN_STATUS_NO_ARGUMENTS keeps codes and formats
#   5. a dropped Status is a compile error under -Werror (and the checked form compiles)
#   6. README.md's module map lists what the tree holds, and nothing else
#   7. required outputs are references, not pointers every function null-checks
#   8. every module includes only the modules docs/DESIGN.md's dependency graph allows
#
# Usage: tools/check_api.sh LIBRARY API_DIR   (environment: CXX, CPPFLAGS, CXXFLAGS, JOBS; the
#                                             Makefile passes its values)
set -uo pipefail
cd "$(dirname "$0")/.."
library=$1 api=$2
: "${CXX:=g++}" "${CPPFLAGS:=-Ilib}" "${CXXFLAGS:=-std=c++17}" "${JOBS:=2}"
export CXX CXXFLAGS
mkdir -p "$api"
run() { echo "$*"; "$@"; }  # a command shown as it runs, as make shows a recipe line
# shellcheck disable=SC2086  # CPPFLAGS and CXXFLAGS are lists of flags

# 1.
headers=$(find lib -name '*.hpp' | LC_ALL=C sort)
printf '%s\n' $headers | sed 's|^lib/||' | xargs -P "$JOBS" -I{} sh -c \
  'printf "#include \"%s\"\n" "{}" | $CXX $CXXFLAGS -Ilib -fsyntax-only -x c++ - ||
   { echo "check-api: {} does not compile alone"; exit 255; }' || exit 1
echo "check-api: $(printf '%s\n' $headers | wc -l) headers compile alone"

# 2.
missing=$(for h in $headers; do
  [ "$h" = lib/shitsukan/shitsukan.hpp ] && continue
  grep -qF "#include \"${h#lib/}\"" lib/shitsukan/shitsukan.hpp || echo "${h#lib/}"; done)
if [ -n "$missing" ]; then
  echo "check-api: shitsukan/shitsukan.hpp misses (run tools/gen_umbrella.sh):"; echo "$missing"; exit 1
fi
echo "check-api: shitsukan/shitsukan.hpp includes all of them"

# 3.
bad=$(nm -g --defined-only "$library" | awk 'NF == 3 { print $2, $3 }' |
  awk '($1 ~ /^[TDBRGSC]$/ && $2 !~ /9shitsukan/) || ($1 ~ /^[WVu]$/ && $2 !~ /9shitsukan/ &&
       $2 !~ /^(_ZN?K?St|_ZN?K?9__gnu_cxx|_ZT[ISV]N?St|DW\.ref\.__gxx_personality_v0$)/) { print $2 }' |
  sort -u)
if [ -n "$bad" ]; then
  echo "check-api: libshitsukan.a exports symbols outside namespace shitsukan:"
  echo "$bad" | c++filt | head -20; exit 1
fi
echo "check-api: libshitsukan.a exports only shitsukan symbols (no stbi_*)"

# 4.
run $CXX $CPPFLAGS -std=c++17 -O1 -w tests/consumer/stb_clash.cpp "$library" -o "$api/stb_clash" || exit 1
"$api/stb_clash" "$api/own.png" "$api/ours.png" || exit 1
run $CXX $CXXFLAGS -DSHITSUKAN_NO_STB -Ilib -c lib/shitsukan/image/image_io.cpp -o "$api/image_io_nostb.o" || exit 1
run $CXX $CXXFLAGS -Ilib tests/consumer/png_without_stb.cpp "$api/image_io_nostb.o" "$library" \
  -o "$api/png_without_stb" || exit 1
"$api/png_without_stb" "$api/nostb.png" || exit 1
# the small devices' switch: a Status without its arguments (ports/PORTING.md section 7)
run $CXX $CXXFLAGS -DSHITSUKAN_STATUS_NO_ARGUMENTS -Ilib tests/consumer/status_no_arguments.cpp \
  lib/shitsukan/core/status.cpp lib/shitsukan/core/format_number.cpp \
  -o "$api/status_no_arguments" || exit 1
"$api/status_no_arguments" || exit 1

# 5.
$CXX $CPPFLAGS -std=c++17 -Wall -Werror -DSHITSUKAN_CHECKED -fsyntax-only \
  tests/compile_fail/dropped_status.cpp || { echo "check-api: the checked form does not compile"; exit 1; }
if $CXX $CPPFLAGS -std=c++17 -Wall -Werror -fsyntax-only tests/compile_fail/dropped_status.cpp \
     2> "$api/dropped_status.log"; then
  echo "check-api: dropping a Status compiled under -Werror"; exit 1
fi
grep -q "nodiscard" "$api/dropped_status.log" ||
  { echo "check-api: dropped_status.cpp failed, but not for nodiscard:"; cat "$api/dropped_status.log"; exit 1; }
echo "check-api: a dropped Status does not compile under -Werror (nodiscard)"

# 6. and 7.
python3 tools/check_module_map.py || exit 1
python3 tools/check_output_params.py || exit 1

# 8.
python3 tools/check_modules.py || exit 1
