#!/usr/bin/env bash
# README's main command: installs the packages, builds, starts gearcoupling-service on loopback
# with the bundled NREL couplings, shows a first query through it (and the same in process),
# then keeps serving until Ctrl-C. `bash deploy/run.sh --once` stops after the queries.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target gearcoupling gearcoupling-service

export CYCLONEDDS_URI="${CYCLONEDDS_URI:-file://$PWD/deploy/cyclonedds-loopback.xml}"
domain="${GC_DOMAIN:-0}"
./build/service/gearcoupling-service --domain "$domain" --catalogue data/couplings &
service=$!
trap 'kill -TERM $service 2>/dev/null; wait $service 2>/dev/null || true' EXIT INT TERM

cli=./build/clients/cli/gearcoupling
echo "== first queries, through the service (--remote) on domain $domain"
$cli jam-angle --remote --domain "$domain"
$cli contact --torque-nm 1.5e6 --misalignment-deg 0.5 --mu 0.1 --remote --domain "$domain"
$cli moments --torque-nm 1.5e6 --misalignment-deg 0.45 --mu 0.12 --remote --domain "$domain"
$cli restoring-torque --remote --domain "$domain"
echo "== the same moments in process (identical output)"
$cli moments --torque-nm 1.5e6 --misalignment-deg 0.45 --mu 0.12

if [ "${1:-}" = "--once" ]; then exit 0; fi
echo "== gearcoupling-service serving on domain $domain (loopback); Ctrl-C stops it"
wait $service
