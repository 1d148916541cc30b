# Sourced by the packaging tests that start a service: `scratch NAME` makes $tmp, a scratch
# directory removed on exit together with the service the test started ($service, its pid);
# `fail MESSAGE` stops the test and shows the service's log ($tmp/service.log) when there is one.
scratch() {
  tmp=$(mktemp -d "/tmp/$1.XXXXXX")
  service=""
  trap scratch_cleanup EXIT
}
scratch_cleanup() {
  if [ -n "$service" ]; then kill -KILL "$service" 2>/dev/null || true; fi
  rm -rf "$tmp"
}
fail() { echo "FAIL: $*" >&2; [ -f "$tmp/service.log" ] && cat "$tmp/service.log" >&2; exit 1; }
