#!/usr/bin/env bash
# ctest packaging.programs: what every installed program answers before it joins DDS (no network
# used). Each prints "<program> <project version>" for --version; the monitor and the dashboard
# read their flags from --config FILE (TOML, as /etc/gearcoupling/monitor.conf and
# dashboard.conf): a value out of range there, a name that is no flag and a missing file are
# each refused with exit 2 and a message naming it.
#   programs_test.sh BUILD_DIR SOURCE_DIR VERSION
set -euo pipefail
build=$1 source=$2 version=$3
. "$(dirname "$0")/scratch.sh"
scratch gc_programs

declare -A binary=(
  [gearcoupling]=clients/cli/gearcoupling [gearcoupling-service]=service/gearcoupling-service
  [gearcoupling-monitor]=monitor/gearcoupling-monitor
  [gearcoupling-dashboard]=clients/dashboard/gearcoupling-dashboard)
for program in "${!binary[@]}"; do
  out=$("$build/${binary[$program]}" --version) || fail "$program --version exited $?"
  [ "$out" = "$program $version" ] || fail "$program --version: \"$out\", not \"$program $version\""
done

refused() {  # refused PROGRAM EXPECTED-MESSAGE FILE-CONTENT
  local program=$1 expected=$2 status=0
  printf '%s\n' "$3" >"$tmp/$program.conf"
  "$build/${binary[$program]}" --config "$tmp/$program.conf" >"$tmp/out" 2>&1 || status=$?
  [ "$status" -eq 2 ] || fail "$program --config with \"$3\": exit $status, not 2: $(cat "$tmp/out")"
  grep -qF -- "$expected" "$tmp/out" || fail "$program --config with \"$3\": $(cat "$tmp/out")"
}
refused gearcoupling-monitor "--window-s: Value -1 not in range" "window-s = -1"
refused gearcoupling-monitor "windoww" "windoww = 3"
refused gearcoupling-dashboard "--update-hz: Value 99 not in range 1 to 10" "update-hz = 99"
refused gearcoupling-dashboard "lisen" 'lisen = "127.0.0.1:8080"'
# An operator dashboard names the person applying proposals (issue 39): --operator, else refused.
refused gearcoupling-dashboard "--operator: required" 'operator-cells = ["dyno1"]'
refused gearcoupling-dashboard "--operator: 'a;b' is not an operator name" $'operator-cells = ["dyno1"]\noperator = "a;b"'
status=0
"$build/${binary[gearcoupling-monitor]}" --config "$tmp/none.conf" >"$tmp/out" 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -qF "$tmp/none.conf" "$tmp/out" || fail "a missing --config file: exit $status: $(cat "$tmp/out")"
# The files shipped in /etc/gearcoupling name only flags the programs have.
for program in monitor dashboard; do
  for name in $(sed -n 's/^#\? \?\([a-z-]*\) = .*/\1/p' "$source/deploy/$program.conf"); do
    "$build/${binary[gearcoupling-$program]}" --help | grep -q -- "--$name" ||
      fail "deploy/$program.conf sets $name, which gearcoupling-$program has not"
  done
done
echo "PASS: four programs print version $version; --config files read, bad ones refused"
