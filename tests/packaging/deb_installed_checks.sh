#!/usr/bin/env bash
# Part of ctest packaging.deb (deb_test.sh runs it under `unshare --mount --net --pid`): the .debs in
# DEB_DIR installed with dpkg at their real paths, as on a test cell's host, without touching this
# host. /usr, /etc and /var are overlays whose changes land in DEB_DIR/overlay and vanish with
# the mount namespace; /run is empty (no systemd to call); the network namespace has only
# loopback, so domain 0, the default of every program, is this test's alone.
# Then, with CYCLONEDDS_URI unset everywhere:
#   - every installed program prints the package's version;
#   - gearcoupling-service, started with its unit's command line as the unit's user, says it uses
#     the installed /etc/gearcoupling/cyclonedds.xml; `gearcoupling jam-angle --remote` and
#     Python's Client answer through it exactly as the core in process; so after a reload (SIGHUP),
#     which reads the installed configuration again;
#   - gearcoupling-monitor and gearcoupling-dashboard start from their units' command lines and
#     configuration; the dashboard's /metrics shows the service's instance;
#   - a find_package(gearcoupling) consumer and a pkg-config one build against /usr with
#     cyclonedds-dev removed (libgearcoupling-dev's dependencies are enough), and the first answers;
#   - the purge removes every file and the configuration.
#   deb_installed_checks.sh DEB_DIR SOURCE_DIR VERSION
set -euo pipefail
deb_dir=$1 source=$2 version=$3
pids=()
cleanup() {
  local pid
  for pid in "${pids[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*" >&2
  local log
  for log in "$deb_dir"/*.log; do [ -f "$log" ] && { echo "--- $log" >&2; tail -20 "$log" >&2; }; done
  exit 1
}

for dir in usr etc var; do
  mkdir -p "$deb_dir/overlay/$dir/upper" "$deb_dir/overlay/$dir/work"
  mount -t overlay overlay \
    -o "lowerdir=/$dir,upperdir=$deb_dir/overlay/$dir/upper,workdir=$deb_dir/overlay/$dir/work" "/$dir"
done
mount -t tmpfs tmpfs /run
ip link set lo up
unset CYCLONEDDS_URI GEARCOUPLING_CATALOG GEARCOUPLING_MODELS PYTHONPATH LD_LIBRARY_PATH

packages=(libgearcoupling0 libgearcoupling-dev python3-gearcoupling gearcoupling)
arch=$(dpkg --print-architecture)
debs=()
for package in "${packages[@]}"; do debs+=("$deb_dir/${package}_${version}_${arch}.deb"); done
DEBIAN_FRONTEND=noninteractive dpkg -i "${debs[@]}" >"$deb_dir/dpkg-install.log" 2>&1 ||
  fail "dpkg -i: $(tail -5 "$deb_dir/dpkg-install.log")"
for package in "${packages[@]}"; do
  [ "$(dpkg-query -W -f='${Status}' "$package")" = "install ok installed" ] || fail "$package is not installed"
done
getent passwd gearcoupling >/dev/null || fail "no system user gearcoupling"

# The programs, their units and configuration.
for program in gearcoupling gearcoupling-service gearcoupling-monitor gearcoupling-dashboard; do
  [ "$(command -v "$program")" = "/usr/bin/$program" ] || fail "$program is not /usr/bin/$program"
  [ "$("$program" --version)" = "$program $version" ] ||
    fail "$program --version: $("$program" --version 2>&1) (package $version)"
done
# The installed completion offers the installed bundled names after --coupling and --model.
completion=/usr/share/bash-completion/completions/gearcoupling
offered() { bash -c "source $completion && COMP_WORDS=(gearcoupling $1) && COMP_CWORD=3 && _gearcoupling && echo \${COMPREPLY[*]}"; }
[ "$(offered "jam-angle --coupling nrel_")" = "nrel_downwind nrel_upwind" ] ||
  fail "the completion after --coupling offers: $(offered "jam-angle --coupling nrel_")"
[ "$(offered "validate --model pap")" = "paper paper_downwind" ] ||
  fail "the completion after --model offers: $(offered "validate --model pap")"
for program in gearcoupling-service gearcoupling-monitor gearcoupling-dashboard; do
  unit=/lib/systemd/system/$program.service
  [ -f "$unit" ] || fail "no $unit"
  [ "$(dpkg -S "$unit" | cut -d: -f1)" = gearcoupling ] || fail "$unit is not gearcoupling's"
done
exec_start() { sed -n 's/^ExecStart=//p' "/lib/systemd/system/$1.service"; }
# setpriv execs the program: $! is its pid, and signals go to it.
as_unit_user=(setpriv --reuid=gearcoupling --regid=gearcoupling --init-groups --)

gearcoupling validate --model paper --data /usr/share/gearcoupling/recordings/paper_torque_ramp.csv \
  >"$deb_dir/validate.log" 2>&1 || fail "validate with the installed model and recording"

# The service, as its unit starts it.
read -r -a command <<<"$(exec_start gearcoupling-service)"
"${as_unit_user[@]}" "${command[@]}" 2>"$deb_dir/service.log" &
pids+=($!)
service=$!
installed="DDS configuration: file:///etc/gearcoupling/cyclonedds.xml (installed; CYCLONEDDS_URI unset)"
for _ in $(seq 100); do
  grep -q "gearcoupling-service instance" "$deb_dir/service.log" && break
  sleep 0.1
done
grep -qF "$installed" "$deb_dir/service.log" || fail "the service does not say it uses the installed configuration"
grep -q "catalogue_dir=/usr/share/gearcoupling/couplings " "$deb_dir/service.log" ||
  fail "the service does not serve the installed catalogue"

# The first remote call, from the shell and from Python.
local_answer=$(gearcoupling jam-angle --coupling nrel_downwind)
remote_call() {
  local remote
  remote=$(gearcoupling jam-angle --coupling nrel_downwind --remote --timeout-s 30 2>&1) ||
    fail "gearcoupling jam-angle --remote ($1): $remote"
  [ "$remote" = "$local_answer" ] || fail "remote ($1) and in-process answers differ: $remote / $local_answer"
  (cd / && /usr/bin/python3 -c '
import gearcoupling as gc
assert gc.__file__.startswith("/usr/lib/python3/dist-packages/"), gc.__file__
remote = gc.Client(timeout=30.0).jam_angle("nrel_downwind").angle_deg
local = gc.jam_angle("nrel_downwind").angle_deg
assert remote == local, (remote, local)
print("python: jam angle", remote, "deg through the service")
') || fail "Python Client ($1)"
}
remote_call "first call"
echo "$local_answer"
# A reload makes a new participant on a new domain, which reads the installed configuration again:
# here, edited to trace Cyclone's configuration to the service's log.
if grep -q "config: Domain/" "$deb_dir/service.log"; then fail "Cyclone traced before the edit"; fi
sed -i 's|<Domain id="any">|<Domain id="any"><Tracing><Verbosity>config</Verbosity><OutputFile>stderr</OutputFile></Tracing>|' \
  /etc/gearcoupling/cyclonedds.xml
kill -HUP "$service"
for _ in $(seq 100); do
  grep -q "reloaded: new participant" "$deb_dir/service.log" && break
  sleep 0.1
done
grep -q "reloaded: new participant" "$deb_dir/service.log" || fail "no reload on SIGHUP"
grep -q "config: Domain/Tracing/OutputFile/#text: stderr" "$deb_dir/service.log" ||
  fail "the reload did not read /etc/gearcoupling/cyclonedds.xml again"
sed -i 's|<Tracing><Verbosity>config</Verbosity><OutputFile>stderr</OutputFile></Tracing>||' \
  /etc/gearcoupling/cyclonedds.xml
remote_call "after SIGHUP"

# The monitor and the dashboard, as their units start them, with their configuration edited as
# an administrator would.
sed -i 's/^model = "paper"$/model = "paper_downwind"/' /etc/gearcoupling/monitor.conf
sed -i 's/^listen = "127.0.0.1:8080"$/listen = "127.0.0.1:8181"/' /etc/gearcoupling/dashboard.conf
# The unit's StateDirectory=gearcoupling, as systemd makes it: the audit trail's directory.
install -d -o gearcoupling -g gearcoupling -m 0750 /var/lib/gearcoupling
read -r -a command <<<"$(exec_start gearcoupling-monitor)"
STATE_DIRECTORY=/var/lib/gearcoupling "${as_unit_user[@]}" "${command[@]}" 2>"$deb_dir/monitor.log" &
pids+=($!)
read -r -a command <<<"$(exec_start gearcoupling-dashboard)"
"${as_unit_user[@]}" "${command[@]}" >"$deb_dir/dashboard.out" 2>"$deb_dir/dashboard.log" &
pids+=($!)
metrics=""
for _ in $(seq 150); do
  metrics=$(/usr/bin/python3 -c 'import urllib.request as u; print(u.urlopen("http://127.0.0.1:8181/metrics", timeout=5).read().decode())' 2>/dev/null) ||
    metrics=""
  [[ "$metrics" == *'gearcoupling_instance_up{'*'} 1'* ]] && break
  sleep 0.2
done
[[ "$metrics" == *'gearcoupling_instance_up{'*'} 1'* ]] ||
  fail "the dashboard (unit's command, /etc/gearcoupling/dashboard.conf) shows no live instance"
cat "$deb_dir/dashboard.out" "$deb_dir/dashboard.log" | grep -qF "$installed" || fail "the dashboard does not use the installed configuration"
grep -qF "$installed" "$deb_dir/monitor.log" || fail "the monitor does not use the installed configuration"
grep -q "on domain 0, model paper_downwind by default" "$deb_dir/monitor.log" || fail "the monitor did not read /etc/gearcoupling/monitor.conf"
grep -q "swap audit /var/lib/gearcoupling/swap_audit.log: 0 swaps loaded" "$deb_dir/monitor.log" ||
  fail "the monitor keeps no audit trail in its unit's StateDirectory"

# Building against the installed -dev package, without Cyclone's -dev package.
DEBIAN_FRONTEND=noninteractive dpkg -r --force-depends cyclonedds-dev >"$deb_dir/dpkg-remove.log" 2>&1 ||
  fail "removing cyclonedds-dev in the overlay"
cp -r "$source/tests/packaging/consumer" "$deb_dir/consumer" || fail "no consumer project in $source"
cmake -S "$deb_dir/consumer" -B "$deb_dir/consumer/build" -DCMAKE_BUILD_TYPE=Release \
  >"$deb_dir/consumer.log" 2>&1 || fail "find_package(gearcoupling) from /usr: $(tail -5 "$deb_dir/consumer.log")"
cmake --build "$deb_dir/consumer/build" >>"$deb_dir/consumer.log" 2>&1 || fail "the consumer does not build"
"$deb_dir/consumer/build/consumer" 0 >"$deb_dir/consumer.out" 2>&1 || fail "consumer: $(cat "$deb_dir/consumer.out")"
# shellcheck disable=SC2046  # pkg-config's output is a list of flags
g++ -std=c++20 -o "$deb_dir/pkg_config_physics" "$source/tests/packaging/pkg_config_physics.cc" \
  $(pkg-config --cflags --libs gearcoupling-physics) || fail "the pkg-config consumer does not build"
"$deb_dir/pkg_config_physics" >/dev/null || fail "the pkg-config consumer"

for pid in "${pids[@]}"; do kill -TERM "$pid"; done
for pid in "${pids[@]}"; do
  status=0
  wait "$pid" || status=$?
  [ "$status" -eq 0 ] || fail "a program started from its unit exited $status on SIGTERM"
done
pids=()

# Purge: nothing of the packages stays but the user (docs/deploy.md).
DEBIAN_FRONTEND=noninteractive dpkg --purge "${packages[@]}" >"$deb_dir/dpkg-purge.log" 2>&1 ||
  fail "dpkg --purge: $(tail -5 "$deb_dir/dpkg-purge.log")"
for path in /etc/gearcoupling /var/lib/gearcoupling /usr/bin/gearcoupling /usr/share/gearcoupling /usr/include/gearcoupling \
    /usr/lib/python3/dist-packages/gearcoupling /lib/systemd/system/gearcoupling-service.service; do
  [ ! -e "$path" ] || fail "$path is left after the purge"
done
if ls /usr/lib/*/libgearcoupling-* 2>/dev/null; then fail "libraries left after the purge"; fi
echo "installed, served the first remote call (CLI and Python, CYCLONEDDS_URI unset), built against, purged"
