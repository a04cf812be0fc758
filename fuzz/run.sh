#!/usr/bin/env bash
# make fuzz, after the harnesses are built: each harness (fuzz/fuzz_*.cpp, built into
# FUZZ_DIR) first replays its committed seed corpus (fuzz/corpus/<name>/: must be clean, else a
# regression), then explores for FUZZ_SECONDS from a fixed libFuzzer seed. A finding's input is
# saved as FUZZ_DIR/crash-*; new interesting inputs go to FUZZ_DIR/corpus-<name>/, not into the
# repository. See fuzz/README.md.
#
# Usage: fuzz/run.sh FUZZ_DIR   (environment: FUZZ_SECONDS, FUZZ_SEED, FUZZ_STRICT, FUZZ_TIMEOUT;
#                               the Makefile passes its values)
set -uo pipefail
cd "$(dirname "$0")/.."
dir=$1
seconds=${FUZZ_SECONDS:-20}
seed=${FUZZ_SEED:-1}
strict=${FUZZ_STRICT:-1}
timeout=${FUZZ_TIMEOUT:-120}
fuzzers=$(for src in fuzz/fuzz_*.cpp; do name=$(basename "$src" .cpp); echo "$dir/$name"; done)

for f in $fuzzers; do
  name=$(basename "$f")
  log=$dir/$name.replay.log
  if ! "$f" -runs=0 -timeout="$timeout" -rss_limit_mb=2048 "fuzz/corpus/$name" > "$log" 2>&1; then
    tail -40 "$log"; echo "fuzz: $name FAILS ON ITS COMMITTED CORPUS (a regression)"; exit 1
  fi
  echo "fuzz: $name: committed corpus ($(ls "fuzz/corpus/$name" | wc -l) inputs) replayed clean"
done

found=0
for f in $fuzzers; do
  name=$(basename "$f")
  mkdir -p "$dir/corpus-$name"
  log=$dir/$name.log
  if ! "$f" -seed="$seed" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 \
       -print_final_stats=1 -artifact_prefix="$dir/" "$dir/corpus-$name" "fuzz/corpus/$name" \
       > "$log" 2>&1; then
    grep -m1 "contract broken\|ERROR" "$log"
    echo "fuzz: $name FOUND A DEFECT (input saved under $dir/)"; found=1; continue
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  echo "fuzz: $name: $runs executions in $seconds s, no finding"
done
if [ $found = 1 ] && [ "$strict" = 1 ]; then exit 1; fi
if [ $found = 1 ]; then
  echo "fuzz: findings reported, not failing (FUZZ_STRICT=0: open findings in fuzz/findings/)"
fi
exit 0
