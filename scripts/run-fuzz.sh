#!/usr/bin/env bash
# Builds the libFuzzer harnesses of the input readers (fuzz/) with clang under ASan + UBSan in build-fuzz
# and runs each for FUZZ_SECONDS (default 60) on its seed corpus: fuzz/seeds/<target>, the regression
# inputs (tests/fuzz_regressions/<target>), the examples' configs (data/examples, data/repro) and their
# point files (data/c3x). Prints the executions per run;
# fails on any crash, sanitizer report, broken promise, timeout (> 10 s per input) or > 2 GB of memory.
# The reproducer of a finding is written to build-fuzz/findings/ (replay: build-fuzz/fuzz/<target> FILE).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-60}
out=build-fuzz

cmake -S . -B "$out" -G Ninja -DCOOLINGGEN_FUZZ=ON -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" >/dev/null
start=$(date +%s)
cmake --build "$out" -j"$(nproc)"
echo "fuzz build: $(( $(date +%s) - start )) s"
python3 fuzz/make_dictionary.py data/schema/coolinggen.schema.json >"$out/config.dict"

status=0
# run TARGET DICT SEED_DIR...: new inputs go to $out/corpus/TARGET, the seed directories are only read.
run() {
  local target=$1 dict=$2
  shift 2
  mkdir -p "$out/corpus/$target" "$out/findings"
  local log="$out/$target.log"
  if ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 "$out/fuzz/$target" -max_total_time="$seconds" \
    -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 -dict="$dict" -artifact_prefix="$out/findings/$target-" \
    "$out/corpus/$target" "$@" >"$log" 2>&1; then
    echo "$target: $(sed -n 's/^stat::number_of_executed_units: *//p' "$log") executions in $seconds s," \
      "$(sed -n 's/^stat::new_units_added: *//p' "$log") new inputs, corpus $(ls "$out/corpus/$target" | wc -l) files, 0 crashes"
  else
    echo "$target: FAILED (a finding; the last lines of $log:)"
    tail -n 40 "$log"
    return 1
  fi
}
# The two harnesses side by side (one core each): the stage costs one FUZZ_SECONDS, not two.
# Every example config is a seed, those with blade.import too: the reader reads the imported file's syntax
# only (the cut at the streamlines is the blade model's, build_model).
run fuzz_config "$out/config.dict" fuzz/seeds/config tests/fuzz_regressions/config data/examples data/repro &
config_job=$!
run fuzz_point_file fuzz/point_file.dict fuzz/seeds/point_file tests/fuzz_regressions/point_file data/c3x || status=1
wait "$config_job" || status=1
exit $status
