#!/usr/bin/env bash
# make check-small: the small-device core (lib/shitsukan/small_device_sources.txt) keeps its
# promises. Its .cpp files, compiled with -fno-exceptions -fno-rtti -Wdouble-promotion
# -fstack-usage into OBJ_DIR by the Makefile, must allocate nothing, throw nothing, call no
# stdio or allocating C library function and keep every function's stack within the budget;
# no small-device file may include a std container or string; every small-device header must
# compile alone under the same flags.
#
# Usage: tools/check_small.sh OBJ_DIR   (the Makefile passes CXX, CPPFLAGS, CXXFLAGS and
#                                       SMALL_FLAGS in the environment)
set -uo pipefail
cd "$(dirname "$0")/.."
obj_dir=$1
: "${CXX:=g++}" "${CPPFLAGS:=-Ilib}" "${CXXFLAGS:=-std=c++17}" "${SMALL_FLAGS:=}"

# The stack budget per function (bytes, from -fstack-usage; chosen: a quarter of the 16 KB main
# stack ports/cortex-m reserves, so a call chain of a few library frames fits). Known over it,
# listed rather than hidden: none (incircle_exact's 37.8 KB of expansion arithmetic became a
# 2048-bit fixed-point sum of 1.1 KB).
STACK_BUDGET=4096
STACK_OVER_BUDGET_KNOWN=""
# C library calls that may allocate (stdio buffers, printf's float and wide paths in newlib) or
# pull stdio into a firmware. Status messages use core/format_number (no printf) and the
# default assert handler traps under SHITSUKAN_SMALL_DEVICE (no fprintf/abort); IST digit
# labels too (format_integer). Known users, listed rather than hidden: none.
STDIO_CALLS='v?sn?printf|v?fprintf|printf|puts|fputs|fopen|fwrite|fflush|strdup|strndup|stderr|stdout|abort'
STDIO_KNOWN=""

known_re() {  # "a b" -> "a|b" (+ suffix), or a pattern that matches nothing
  if [ -n "$1" ]; then printf '%s%s' "$(printf '%s' "$1" | tr -s ' ' '|')" "$2"; else printf '%s' "$3"; fi
}
STACK_KNOWN_RE=$(known_re "$STACK_OVER_BUDGET_KNOWN" "" no-function-is-a-known-exception)
STDIO_KNOWN_RE=$(known_re "$STDIO_KNOWN" ":" no-object-is-a-known-exception)

tools/small_sources.sh --check || exit 1
srcs=$(grep -v '^#' lib/shitsukan/small_device_sources.txt)
cpps=$(printf '%s\n' "$srcs" | grep '\.cpp$')
hpps=$(printf '%s\n' "$srcs" | grep '\.hpp$')
n_srcs=$(printf '%s\n' "$srcs" | wc -l)
n_cpps=$(printf '%s\n' "$cpps" | wc -l)
n_hpps=$(printf '%s\n' "$hpps" | wc -l)
objs=$(printf '%s\n' "$cpps" | sed "s|^\(.*\)\.cpp$|$obj_dir/\1.o|")
# shellcheck disable=SC2086  # word splitting of the lists and flags is intended below

bad=$(nm -C --undefined-only $objs 2>/dev/null |
  grep -E ' (operator new|operator delete|malloc|calloc|realloc|free|__cxa_throw|__cxa_allocate_exception)' | sort -u)
if [ -n "$bad" ]; then echo "check-small: allocation or exceptions in small-device files:"; echo "$bad"; exit 1; fi
stdio=$(nm -A --undefined-only $objs 2>/dev/null | grep -E " U ($STDIO_CALLS)\$" | grep -v -E "$STDIO_KNOWN_RE" || true)
if [ -n "$stdio" ]; then echo "check-small: C library calls that may allocate or pull in stdio:"; echo "$stdio"; exit 1; fi
for f in $srcs; do
  h=$($CXX $CPPFLAGS -std=c++17 -M "$f" | tr ' ' '\n' |
      grep -E '/bits/(stl_vector|basic_string|unique_ptr|stl_map|stl_list|stl_deque|hashtable)\.h' | sort -u)
  if [ -n "$h" ]; then echo "check-small: $f includes host containers:"; echo "$h"; exit 1; fi
done
header_flags=$(printf '%s\n' $SMALL_FLAGS | grep -v -x -e -fstack-usage | tr '\n' ' ')
for h in $hpps; do
  printf '#include "%s"\n' "${h#lib/}" | $CXX $CPPFLAGS $CXXFLAGS $header_flags -fsyntax-only -x c++ - ||
    { echo "check-small: header ${h#lib/} does not compile alone under the small-device flags"; exit 1; }
done
su=$(cat $(printf '%s\n' $objs | sed 's/\.o$/.su/'))
unbounded=$(printf '%s\n' "$su" | awk -F'\t' '$3 ~ /dynamic/ && $3 !~ /bounded/')
if [ -n "$unbounded" ]; then echo "check-small: unbounded stack (VLA/alloca):"; echo "$unbounded"; exit 1; fi
over=$(printf '%s\n' "$su" | awk -F'\t' -v b=$STACK_BUDGET '$2 > b' | grep -v -E "$STACK_KNOWN_RE" || true)
if [ -n "$over" ]; then echo "check-small: functions over the $STACK_BUDGET-byte stack budget:"; echo "$over"; exit 1; fi
deepest=$(printf '%s\n' "$su" | grep -v -E "$STACK_KNOWN_RE" | sort -t'	' -k2 -n -r | head -1 | awk -F'\t' '{ print $2 " bytes: " $1 }')
known=$(printf '%s\n' "$su" | grep -E "$STACK_KNOWN_RE" | awk -F'\t' '{ print $2 " bytes: " $1 }')
echo "check-small: $n_cpps small-device .cpp files compile with -fno-exceptions -fno-rtti -Wdouble-promotion and allocate nothing;"
echo "check-small: all $n_srcs small-device files ($n_cpps .cpp, $n_hpps headers) include no std containers or strings; the $n_hpps headers compile alone under the same flags"
echo "check-small: stack per function <= $STACK_BUDGET bytes (-fstack-usage), deepest $deepest"
[ -n "$STACK_OVER_BUDGET_KNOWN" ] && echo "check-small: KNOWN over budget: $known"
echo "check-small: no stdio or allocating C library call ($STDIO_CALLS)${STDIO_KNOWN:+ outside the KNOWN users $STDIO_KNOWN}"
exit 0
