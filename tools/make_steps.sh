#!/usr/bin/env bash
# The Makefile's SUBMAKE: runs `make TARGETS` so that each compile, archive and link step prints
# one "[n/N] file" line (V=1: the full commands instead). N comes from a dry run (make -n) of
# the same targets, which lists exactly the steps that are out of date; n from a counter file
# shared by the parallel jobs (tools/progress.sh). make's "'x' is up to date" lines are left out.
#
# Usage: tools/make_steps.sh MAKE [make arguments and targets...]
set -uo pipefail
steps=0
if [ "${V:-0}" != 1 ]; then
  steps=$("$@" -n 2> /dev/null | grep -c 'tools/progress\.sh')
fi
counter=$(mktemp "${TMPDIR:-/tmp}/shitsukan-steps.XXXXXX") || exit 1
trap 'rm -f "$counter"' EXIT
"$@" SHITSUKAN_STEPS="$steps" SHITSUKAN_STEPS_FILE="$counter" |
  grep --line-buffered -v -E ": ('[^']*' is up to date|Nothing to be done for '[^']*')\.$"
exit "${PIPESTATUS[0]}"
