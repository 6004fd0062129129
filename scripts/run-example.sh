#!/usr/bin/env bash
# Installs dependencies, builds the CLI (Release, same configuration as run-tests.sh so the two do not
# reconfigure each other) and builds the built-in example blade into out/example.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOOLINGGEN_BUILD_TESTS=ON -DCOOLINGGEN_BUILD_BENCH=ON >/dev/null
cmake --build build --target coolinggen_cli
./build/coolinggen build -o out/example "$@"
