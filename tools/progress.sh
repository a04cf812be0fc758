#!/bin/sh
# One "[n/N] what" line of a build (tools/make_steps.sh): n counts the steps done so far in
# COUNTER_FILE (locked, so parallel jobs count once each), N is the dry run's total.
# Usage: tools/progress.sh COUNTER_FILE TOTAL WHAT...
file=$1 total=$2
shift 2
if [ -z "$file" ]; then echo "$*"; exit 0; fi  # a make run without tools/make_steps.sh
n=$(flock "$file" sh -c 'echo >> "$1" && wc -l < "$1"' sh "$file")
echo "[$n/$total] $*"
