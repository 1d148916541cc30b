#!/bin/sh
# The secure round trip against the unsecured one, side by side in one run (docs/benchmarks.md,
# "DDS Security"). Two gearcoupling-service instances run at once on the loopback configuration:
# one plain, one with DDS Security (certificates made now by deploy/security/make-security.sh,
# configured through deploy/cyclonedds-secure.example.xml). gc_bench_service then measures the
# latency of each in turn, ROUNDS times, alternating, so both see the same load on this shared
# machine; the medians of the per-round p50s and their ratio are printed last.
#
#   bench/secure_bench.sh [BUILD_DIR]     (SECURE_BENCH_ROUNDS=5, SECURE_BENCH_REQUESTS=3000)
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
rounds=${SECURE_BENCH_ROUNDS:-5}
requests=${SECURE_BENCH_REQUESTS:-3000}
loopback="file://$here/deploy/cyclonedds-loopback.xml"
secure="$loopback,file://$here/deploy/cyclonedds-secure.example.xml"
export GC_SECURITY_DIR
GC_SECURITY_DIR=$(mktemp -d /tmp/gc-secure-bench-XXXXXX)
bash "$here/deploy/security/make-security.sh" "$GC_SECURITY_DIR" --client bench >/dev/null
prefix=$(cat "$GC_SECURITY_DIR/client-bench/client_id_prefix")
. "$(dirname "$0")/../tests/claim_domain.sh"  # one domain per run, 1-200
claim_domain plain_domain 9
claim_domain secure_domain 8 100
echo "# $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg); plain domain $plain_domain, secure domain $secure_domain; $rounds rounds of $requests requests"

CYCLONEDDS_URI=$loopback "$build/service/gearcoupling-service" --domain "$plain_domain" --log-level warn &
plain=$!
CYCLONEDDS_URI=$secure GC_IDENTITY=service-main \
  "$build/service/gearcoupling-service" --domain "$secure_domain" --log-level warn &
secured=$!
trap 'kill -TERM $plain $secured 2>/dev/null || true; rm -rf "$GC_SECURITY_DIR"' EXIT

results=""
round=1
while [ "$round" -le "$rounds" ]; do
  out=$(CYCLONEDDS_URI=$loopback timeout 300 "$build/bench/gc_bench_service" \
          --domain "$plain_domain" --latency-requests "$requests" --clients "")
  results="$results$(echo "$out" | sed "s/^/plain /")
"
  out=$(CYCLONEDDS_URI=$secure GC_IDENTITY=client-bench timeout 300 "$build/bench/gc_bench_service" \
          --domain "$secure_domain" --latency-requests "$requests" --clients "" --client-id-prefix "$prefix")
  results="$results$(echo "$out" | sed "s/^/secure /")
"
  round=$((round + 1))
done
printf '%s' "$results"

# Median over the rounds of each mode's p50, per calculation, and secure / plain.
printf '%s' "$results" | awk '
  $2 == "latency" { for (i = 1; i <= NF; i++) if ($i ~ /^p50=/) { v = $i; sub("p50=", "", v); sub("us", "", v); p[$1 " " $3] = p[$1 " " $3] " " v } }
  function median(list,   n, a, i, j, t) {
    n = split(list, a, " ")
    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] + 0 < a[i] + 0) { t = a[i]; a[i] = a[j]; a[j] = t }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
  }
  END {
    split("jam_angle induced_moments", cs, " ")
    for (k = 1; k <= 2; k++) {
      c = cs[k]; a = median(p["plain " c]); b = median(p["secure " c])
      printf "%s p50 median: plain %.1f us, secure %.1f us, secure / plain = %.2f\n", c, a, b, b / a
    }
  }'
