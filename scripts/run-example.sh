#!/usr/bin/env bash
# Installs dependencies, builds CoolingGen (Release) and builds the built-in example blade into out/example.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOOLINGGEN_BUILD_TESTS=OFF -DCOOLINGGEN_BUILD_BENCH=OFF >/dev/null
cmake --build build --target coolinggen_cli
./build/coolinggen build -o out/example "$@"
