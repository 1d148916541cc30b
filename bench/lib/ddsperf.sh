# Cyclone's ddsperf as the anchor of the latency benchmarks (service_bench.sh, control_loop.sh):
# `. bench/lib/ddsperf.sh`. ddsperf prints half the round trip (the one-way latency: (now - source
# timestamp) / 2 in process_pong, src/tools/ddsperf/ddsperf.c); the callers double it, or record
# the whole round trip (bench/ddsperf_roundtrips.c).
ddsperf_pong=""

# ddsperf_pong_start DOMAIN SECONDS [PREFIX...]: a `ddsperf pong` on DOMAIN for SECONDS, started
# through PREFIX (e.g. chrt -f 10), bounded by timeout; waits half a second for it to start.
ddsperf_pong_start() {
  pong_domain=$1
  pong_seconds=$2
  shift 2
  "$@" timeout $((pong_seconds + 10)) ddsperf -i "$pong_domain" -D "$pong_seconds" pong >/dev/null 2>&1 &
  ddsperf_pong=$!
  sleep 0.5
}

ddsperf_pong_stop() {
  [ -n "$ddsperf_pong" ] || return 0
  kill "$ddsperf_pong" 2>/dev/null || true
  wait "$ddsperf_pong" 2>/dev/null || true
  ddsperf_pong=""
}
