#!/usr/bin/env bash
# Part of make check-lengths: the Makefile stays build rules (at most 300 lines; long recipes
# belong in scripts beside what they check) and README.md stays a ten-minute read (at most
# 20 KB; reference and history live in docs/, fuzz/, ports/ and CHANGELOG.md).
set -uo pipefail
cd "$(dirname "$0")/.."
status=0
makefile_lines=$(wc -l < Makefile)
readme_bytes=$(wc -c < README.md)
if [ "$makefile_lines" -gt 300 ]; then
  echo "check_sizes: Makefile has $makefile_lines lines, over 300 (move long recipes into scripts)"
  status=1
fi
if [ "$readme_bytes" -gt 20480 ]; then
  echo "check_sizes: README.md is $readme_bytes bytes, over 20 KB (20480; move reference to docs/)"
  status=1
fi
[ $status = 0 ] && echo "check_sizes: Makefile $makefile_lines lines (<= 300), README.md $readme_bytes bytes (<= 20480)"
exit $status
