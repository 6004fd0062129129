#!/usr/bin/env bash
# Installs dependencies, builds everything (Release), runs the whole test suite, a short benchmark smoke
# run, the kernel and algorithm tests again under AddressSanitizer + UndefinedBehaviorSanitizer, and
# the input readers' libFuzzer harnesses for 60 s each (scripts/run-fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=$(nproc)

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOOLINGGEN_SANITIZE=OFF -DCOOLINGGEN_BUILD_TESTS=ON -DCOOLINGGEN_BUILD_BENCH=ON -DCOOLINGGEN_TEST_SLURM=ON >/dev/null
cmake --build build -j"$jobs"
(cd build && ctest --output-on-failure -j"$jobs")

for b in build/bench/bench_*; do
  if [ -f "$b" ] && [ -x "$b" ]; then "$b" --quick; fi
done

# -O1 -g1: line numbers in the sanitizers' reports at half the compile time of -O2 -g (CI budget).
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCOOLINGGEN_SANITIZE=ON -DCOOLINGGEN_BUILD_BENCH=OFF >/dev/null
kernel_tests=$(cd build-asan && ctest -N -L 'kernel|algo' | sed -n 's/^ *Test *#[0-9]*: //p')
cmake --build build-asan -j"$jobs" --target $kernel_tests
(cd build-asan && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --output-on-failure -j"$jobs" -L 'kernel|algo')

scripts/run-fuzz.sh
