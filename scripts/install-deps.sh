#!/usr/bin/env bash
# Installs CoolingGen's build dependencies from Debian's packages (bookworm), and the tests' glTF
# validator from npm into tests/tools/node_modules. Idempotent: does nothing when everything is already
# installed. Run as root or with sudo available.
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libocct-visualization-dev libocct-ocaf-dev
  libtbb-dev libeigen3-dev libboost-test-dev nlohmann-json3-dev libcli11-dev
  libvtk9-dev libgmsh-dev libcgns-dev admesh cgns-convert libssl-dev xvfb xauth
  python3-meshio pybind11-dev python3-dev python3-numpy python3-distributed
  clang libclang-rt-14-dev
  slurm-wlm munge
  chromium nodejs
)
# node and npm may come from elsewhere (e.g. NodeSource's nodejs, which includes npm and conflicts with
# Debian's npm): Debian's npm only when no npm is on PATH.
command -v npm > /dev/null 2>&1 || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The Khronos glTF validator for the tests (tests/tools/package.json + lock; not needed to build).
tools="$(dirname "$0")/../tests/tools"
if [ ! -d "$tools/node_modules/gltf-validator" ]; then
  (cd "$tools" && npm ci --no-audit --no-fund --loglevel=error)
fi
