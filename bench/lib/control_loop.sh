# The control loop and its ddsperf anchor, for bench/control_loop.sh and bench/stall_coincidence.sh:
# `. bench/lib/ddsperf.sh; . bench/lib/control_loop.sh`. The caller sets `build` (the build
# directory), `domain` (ddsperf's) and `sdomain` (the service's, where a gearcoupling-service
# runs). Every process is bounded in time (timeout). The caller may set `phase`: the control loop's
# ticks that many periods after ddsperf ping's ("free": wherever its start puts them; default 0.5).
# shellcheck shell=sh disable=SC2154 # build, domain and sdomain are the caller's
ddsperf_ping=""

ping_mode_of() {  # MODE: the ddsperf ping mode with the same wake-ups as the control loop's MODE
  case $1 in
    call_then) echo listener ;;
    call) echo waitset ;;
    *) echo "unknown control-loop mode \"$1\" (allowed: call_then, call)" >&2; return 2 ;;
  esac
}

# ddsperf_ping_start RATE MODE FILE SECONDS [PREFIX...]: `ddsperf ping RATE MODE` for SECONDS on
# `domain`, in the background, every round trip into FILE (bench/ddsperf_roundtrips.c,
# preloaded), its output into FILE.out, the time of its latest ping into FILE.ping_times (8 bytes:
# CLOCK_MONOTONIC ns).
ddsperf_ping_start() {
  ping_rate=$1
  ping_mode=$2
  ping_file=$3
  ping_seconds=$4
  shift 4
  rm -f "$ping_file.ping_times"
  GC_DDSPERF_ROUNDTRIPS="$ping_file" GC_DDSPERF_PING_TIMES="$ping_file.ping_times" \
    LD_PRELOAD="$build/bench/libgc_ddsperf_roundtrips.so" \
    "$@" timeout $((ping_seconds + 10)) ddsperf -i "$domain" -D "$ping_seconds" \
    ping "${ping_rate}Hz" "$ping_mode" >"$ping_file.out" 2>&1 &
  ddsperf_ping=$!
}

# ddsperf_ping_wait [TERM]: waits for the ping to end, first asking it to (SIGTERM: it ends as at
# the end of its -D and writes its round trips) if TERM is given.
ddsperf_ping_wait() {
  [ -n "$ddsperf_ping" ] || return 0
  if [ $# -gt 0 ]; then kill -TERM "$ddsperf_ping" 2>/dev/null || true; fi
  wait "$ddsperf_ping" 2>/dev/null || true
  ddsperf_ping=""
}

# ddsperf_drop_first_second FILE: the first second of a ping's round trips is discovery and the
# first pings' matching: dropped, as the control loop's warm-up is.
ddsperf_drop_first_second() {
  awk 'NR == 1 { start = $1 } $1 >= start + 1' "$1" >"$1.kept"
  mv "$1.kept" "$1"
}

# ddsperf_pair_start RATE MODE FILE SECONDS [PREFIX...]: a `ddsperf pong` on `domain` (outliving
# the ping by 3 s) and `ddsperf ping RATE MODE` against it for SECONDS (ddsperf_ping_start), in
# the background.
ddsperf_pair_start() {
  start_rate=$1
  start_mode=$2
  start_file=$3
  start_seconds=$4
  shift 4
  ddsperf_pong_start "$domain" $((start_seconds + 3)) "$@"
  ddsperf_ping_start "$start_rate" "$start_mode" "$start_file" "$start_seconds" "$@"
}

# ddsperf_pair_stop FILE [TERM]: waits for the ping (asking it to end first with TERM), stops the
# pong, and keeps FILE's round trips from the ping's second second on (an empty FILE where the
# ping failed: the caller says so).
ddsperf_pair_stop() {
  stop_file=$1
  shift
  ddsperf_ping_wait "$@"
  ddsperf_pong_stop
  touch "$stop_file"
  ddsperf_drop_first_second "$stop_file"
}

# service_loop RATE MODE FILE SECONDS PHASE_OF [PREFIX...]: gc_bench_control_loop at RATE with
# MODE for SECONDS against the service on `sdomain`, every round trip into FILE, its output into
# FILE.out; call() spins up to `spin_us` (default 0) on each reply before it sleeps. With PHASE_OF
# (a ddsperf ping's FILE.ping_times; "-" for none) and `phase` not "free", its ticks fall `phase`
# periods after that ping's.
service_loop() {
  loop_rate=$1
  loop_mode=$2
  loop_file=$3
  loop_seconds=$4
  loop_phase_of=$5
  shift 5
  set -- "$@" timeout $((loop_seconds + 60)) "$build/bench/gc_bench_control_loop" --domain "$sdomain" \
    --mode "$loop_mode" --rate-hz "$loop_rate" --seconds "$loop_seconds" --spin-us "${spin_us:-0}" \
    --out "$loop_file"
  if [ "$loop_phase_of" != - ] && [ "${phase:-0.5}" != free ]; then
    set -- "$@" --phase-of "$loop_phase_of" --phase "${phase:-0.5}"
  fi
  "$@" >"$loop_file.out" 2>&1 || true
}

# control_loop_pair RATE MODE SECONDS SERVICE_FILE DDSPERF_FILE [PREFIX...]: the control loop
# (MODE) and `ddsperf ping RATE` in the mode with the same wake-ups against a `ddsperf pong`, at
# the same time on their two domains, every process started through PREFIX, the loop's ticks
# `phase` periods after ping's (service_loop); both files then keep only the time both ran
# (ddsperf's first second dropped), about SECONDS.
control_loop_pair() {
  pair_rate=$1
  pair_mode=$2
  pair_seconds=$3
  pair_service=$4
  pair_ddsperf=$5
  shift 5
  ddsperf_pair_start "$pair_rate" "$(ping_mode_of "$pair_mode")" "$pair_ddsperf" $((pair_seconds + 30)) "$@"
  sleep 1  # ping's first second, dropped; the loop's discovery and warm-up follow it
  service_loop "$pair_rate" "$pair_mode" "$pair_service" "$pair_seconds" "$pair_ddsperf.ping_times" "$@"
  ddsperf_pair_stop "$pair_ddsperf" TERM
  touch "$pair_service"  # an empty file where the loop failed: the caller says so
  # The time both ran: from the later first send to the earlier last one.
  pair_window=$(awk 'FNR == 1 { if ($1 > b) b = $1 } { l[FILENAME] = $1 }
    END { e = ""; for (f in l) if (e == "" || l[f] < e) e = l[f]; print b, e }' \
    "$pair_service" "$pair_ddsperf")
  for pair_file in "$pair_service" "$pair_ddsperf"; do
    awk -v b="${pair_window% *}" -v e="${pair_window#* }" '$1 >= b && $1 <= e' "$pair_file" >"$pair_file.kept"
    mv "$pair_file.kept" "$pair_file"
  done
}
