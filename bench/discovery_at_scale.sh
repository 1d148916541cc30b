#!/bin/sh
# Discovery at scale (issue 9): N gearcoupling CLI processes started at once, each asking one
# gearcoupling-service instance for a jam angle over DDS, on the loopback-only configuration and
# a domain of this run's own. Prints how many were answered, within 10 s and at all, and the
# spread of their wall times (docs/benchmarks.md, "Discovery at scale").
#
#   bench/discovery_at_scale.sh [BUILD_DIR] [N]      (defaults: build, 100)
#
# GEARCOUPLING / GEARCOUPLING_SERVICE override the binaries (to measure another build).
# BENCH_CYCLONEDDS_URI overrides the service's configuration. Bounded: every process runs under
# timeout (the CLI waits at most 30 s for its reply).
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
n=${2:-100}
cli=${GEARCOUPLING:-$build/clients/cli/gearcoupling}
service_bin=${GEARCOUPLING_SERVICE:-$build/service/gearcoupling-service}
export CYCLONEDDS_URI="${BENCH_CYCLONEDDS_URI:-file://$here/deploy/cyclonedds-loopback.xml}"
# The CLI processes use the client configuration (no participant-index port, so clients do not
# discover each other; BENCH_CLIENT_CYCLONEDDS_URI overrides it, e.g. with the service's).
client_uri=${BENCH_CLIENT_CYCLONEDDS_URI:-file://$here/deploy/cyclonedds-loopback-client.xml}
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain domain 9
work=$(mktemp -d)
echo "# $n CLI processes at once; service $CYCLONEDDS_URI, clients $client_uri, domain $domain, $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"

"$service_bin" --domain "$domain" --log-level warn 2>"$work/service.log" &
service=$!
trap 'kill -TERM $service 2>/dev/null || true; rm -rf "$work"' EXIT
# The service is up once one CLI call is answered (not counted).
timeout 30 "$cli" jam-angle --remote --domain "$domain" --coupling nrel_upwind --timeout-s 20 \
  >/dev/null

start=$(date +%s.%N)
i=0
while [ $i -lt "$n" ]; do
  ( rc=0
    CYCLONEDDS_URI=$client_uri timeout 40 "$cli" jam-angle --remote --domain "$domain" --coupling nrel_upwind \
      --timeout-s 30 >"$work/out.$i" 2>&1 || rc=$?
    echo "$rc $(date +%s.%N)" >"$work/done.$i" ) &
  i=$((i + 1))
done
wait_until=$(( $(date +%s) + 60 ))
while [ "$(ls "$work" | grep -c '^done\.')" -lt "$n" ] && [ "$(date +%s)" -lt $wait_until ]; do
  sleep 0.2
done

results=$(cat "$work"/done.* 2>/dev/null || true)
ok=$(echo "$results" | awk '$1 == 0' | wc -l)
failed=$(echo "$results" | awk 'NF == 2 && $1 != 0' | wc -l)
echo "$results" | awk -v start="$start" '$1 == 0 { print $2 - start }' | sort -g >"$work/times"
in10=$(awk '$1 <= 10' "$work/times" | wc -l)
echo "answered: $ok of $n ($in10 within 10 s), failed: $failed, unfinished: $((n - ok - failed))"
if [ "$ok" -gt 0 ]; then
  awk '{ t[NR] = $1 } END { i9 = int(0.9 * NR + 0.5); if (i9 < 1) i9 = 1
    printf "wall time from start, answered processes: median %.2f s, 90%% %.2f s, max %.2f s\n",
           t[int((NR + 1) / 2)], t[i9], t[NR] }' "$work/times"
fi
if ! kill -0 "$service" 2>/dev/null; then
  wait "$service" && status=0 || status=$?
  echo "the service exited (status $status) during the run; its log ends:"; tail -5 "$work/service.log"
fi
first_failure=$(grep -l -v '^0 ' "$work"/done.* 2>/dev/null | head -1 || true)
if [ -n "$first_failure" ]; then
  echo "first failure: $(cat "$work/out.${first_failure##*.}" | head -3)"
fi
