# CPU hogs for the latency benchmarks (service_bench.sh, control_loop.sh): `. bench/lib/hogs.sh`.
# A hog is `sh -c 'while :; do :; done'`, each bounded by timeout in case the script is killed.
# The caller's cleanup calls stop_hogs.
hogs=""

start_hogs() {  # $1: how many, or "all" for one per core
  count=$1
  [ "$count" = all ] && count=$(nproc)
  hogs=""
  i=0
  while [ "$i" -lt "$count" ]; do
    timeout 3600 sh -c 'while :; do :; done' &
    hogs="$hogs $!"
    i=$((i + 1))
  done
}

stop_hogs() {
  for pid in $hogs; do kill "$pid" 2>/dev/null || true; done
  for pid in $hogs; do wait "$pid" 2>/dev/null || true; done
  hogs=""
}
