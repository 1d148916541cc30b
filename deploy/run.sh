#!/usr/bin/env bash
# README's main command: installs the packages, builds, and runs the main job on the bundled
# NREL upwind coupling.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target gearcoupling
./build/clients/cli/gearcoupling jam-angle
./build/clients/cli/gearcoupling contact --torque 1.5e6 --misalignment-deg 0.5
./build/clients/cli/gearcoupling moments --torque 1.5e6 --misalignment-deg 0.45 --mu 0.12
./build/clients/cli/gearcoupling restoring-torque
