#!/usr/bin/env bash
# run_fuzzer.sh FUZZER WORK_DIR SECONDS MAX_LEN SEED_DIR...: runs a libFuzzer target for SECONDS,
# starting from the seeds, keeping what it finds in WORK_DIR/corpus and a crashing, leaking or
# timed-out input in WORK_DIR/ (its path is printed). Exits non-zero when the fuzzer found one.
set -euo pipefail
fuzzer=$1 work=$2 seconds=$3 max_len=$4
shift 4
mkdir -p "$work/corpus"
seeds=()
for dir in "$@"; do [ -d "$dir" ] && seeds+=("$dir"); done
# -timeout: one input taking 20 s is a finding. -rss_limit_mb: as libFuzzer's default, said aloud.
exec "$fuzzer" -max_total_time="$seconds" -max_len="$max_len" -timeout=20 -rss_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix="$work/" "$work/corpus" "${seeds[@]}"
