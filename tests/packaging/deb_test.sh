#!/usr/bin/env bash
# ctest packaging.deb: cpack makes the .deb from this build; its control data (dependencies,
# conffiles, the maintainer script making the system user) and file list are checked; dpkg -x
# unpacks it into a scratch root, whose gearcoupling-service runs with the unpacked configuration
# (/etc/gearcoupling: loopback) on a domain of its own, finding the unpacked catalogue, and
# answers the unpacked CLI exactly as the CLI answers in process.
#   deb_test.sh BUILD_DIR
set -euo pipefail
build=$1
. "$(dirname "$0")/scratch.sh"
scratch gc_deb

cpack --config "$build/CPackConfig.cmake" -B "$tmp/cpack" >/dev/null
deb=$(echo "$tmp"/cpack/gearcoupling_*.deb)
[ -f "$deb" ] || fail "no .deb made"
dpkg-deb --info "$deb" >/dev/null

# Control data.
dpkg-deb -e "$deb" "$tmp/control"
depends=$(dpkg-deb -f "$deb" Depends)
for package in adduser libddsc0debian libprotobuf32 libspdlog1.10-fmt9 libfmt9 libstdc++6; do
  [[ ", $depends," == *", $package "* || ", $depends," == *", $package,"* ]] ||
    fail "Depends lacks $package: $depends"
done
[ "$(cat "$tmp/control/conffiles")" = "$(printf '/etc/gearcoupling/service.conf\n/etc/gearcoupling/cyclonedds.xml')" ] ||
  fail "conffiles: $(cat "$tmp/control/conffiles")"
grep -q "adduser --system" "$tmp/control/postinst" || fail "postinst makes no system user"
grep -q "^libgearcoupling-core 0 " "$tmp/control/shlibs" || fail "shlibs: $(cat "$tmp/control/shlibs")"

# Files.
root=$tmp/root
dpkg -x "$deb" "$root"
libdir=$(dirname "$(find "$root/usr/lib" -name libgearcoupling-core.so.0)")
for file in usr/bin/gearcoupling usr/bin/gearcoupling-service usr/bin/gearcoupling-monitor \
    usr/lib/systemd/system/gearcoupling-service.service \
    etc/gearcoupling/service.conf etc/gearcoupling/cyclonedds.xml \
    usr/share/gearcoupling/couplings/nrel_upwind.textproto \
    usr/share/gearcoupling/couplings/nrel_downwind.textproto \
    usr/share/gearcoupling/models/paper.textproto \
    usr/share/gearcoupling/deploy/cyclonedds-lan.example.xml \
    usr/share/gearcoupling/deploy/security/make-security.sh \
    usr/include/gearcoupling/clients/remote/client.h \
    usr/share/bash-completion/completions/gearcoupling \
    usr/include/gearcoupling/core/jam_angle.h usr/include/gearcoupling/idl/coupling.pb.h \
    usr/share/doc/gearcoupling/deploy.md; do
  [ -e "$root/$file" ] || fail "missing /$file"
done
# The client's header needs no Cyclone header and nothing idlc generated (docs/deploy.md).
[ ! -e "$root/usr/include/gearcoupling/gearcoupling.h" ] || fail "idlc's gearcoupling.h is packaged"
for name in core codec client; do
  [ "$(readlink "$libdir/libgearcoupling-$name.so.0")" = "libgearcoupling-$name.so.0.1.0" ] ||
    fail "libgearcoupling-$name.so.0 is not the versioned library"
  objdump -p "$libdir/libgearcoupling-$name.so.0" | grep -q "SONAME *libgearcoupling-$name.so.0\$" ||
    fail "libgearcoupling-$name: SONAME"
  [ -f "$libdir/pkgconfig/gearcoupling-$name.pc" ] || fail "no gearcoupling-$name.pc"
done
[ -f "$libdir/cmake/gearcoupling/gearcoupling-config.cmake" ] || fail "no CMake package"
if grep -rl "$build" "$libdir/cmake" "$libdir/pkgconfig"; then fail "build paths in the package"; fi

# The unit: the package's paths, a fixed system user (DDS Security's key must be readable by it,
# docs/security.md), hardening.
unit=$root/usr/lib/systemd/system/gearcoupling-service.service
for line in "ExecStart=/usr/bin/gearcoupling-service --config /etc/gearcoupling/service.conf" \
    "Environment=CYCLONEDDS_URI=file:///etc/gearcoupling/cyclonedds.xml" \
    "User=gearcoupling" "NoNewPrivileges=yes" "ProtectSystem=strict" "ProtectHome=yes" \
    "PrivateTmp=yes" "CapabilityBoundingSet=" \
    "RestrictAddressFamilies=AF_INET AF_INET6 AF_UNIX AF_NETLINK"; do
  grep -qxF "$line" "$unit" || fail "unit lacks: $line"
done
if grep -q "^DynamicUser" "$unit"; then fail "unit uses DynamicUser"; fi
# systemd's own reading of it (a copy whose ExecStart is the unpacked binary): no unknown key, no
# value it cannot parse.
if command -v systemd-analyze >/dev/null; then
  sed "s|/usr/bin/|$root/usr/bin/|" "$unit" >"$tmp/gearcoupling-service.service"
  verify=$(systemd-analyze verify "$tmp/gearcoupling-service.service" 2>&1) || true
  [ -z "$verify" ] || fail "systemd-analyze verify: $verify"
else
  echo "systemd-analyze not installed: the unit's syntax is not verified"
fi

# Run from the scratch root.
domain=$((216 + $$ % 15))  # 216-230: see find_package_test.sh
export CYCLONEDDS_URI=file://$root/etc/gearcoupling/cyclonedds.xml
unset GEARCOUPLING_CATALOG GEARCOUPLING_MODELS
"$root/usr/bin/gearcoupling-service" --config "$root/etc/gearcoupling/service.conf" \
  --domain "$domain" 2>"$tmp/service.log" &
service=$!
cli=$root/usr/bin/gearcoupling
remote=$("$cli" jam-angle --coupling nrel_downwind --remote --domain "$domain" --timeout-s 30) ||
  fail "remote jam-angle"
local=$("$cli" jam-angle --coupling nrel_downwind)
echo "$remote"
[ "$remote" = "$local" ] || fail "remote and in-process answers differ: $local"
grep -q "catalogue_dir=$root/usr/share/gearcoupling/couplings " "$tmp/service.log" ||
  fail "the service did not find the unpacked catalogue"
kill -TERM "$service"
status=0
wait "$service" || status=$?
service=""
[ "$status" -eq 0 ] || fail "gearcoupling-service exited $status on SIGTERM"

# The unpacked CLI finds the unpacked models and recordings too.
"$cli" validate --model paper \
  --data "$root/usr/share/gearcoupling/recordings/paper_torque_ramp.csv" >"$tmp/validate.out" ||
  fail "validate with the bundled model: $(cat "$tmp/validate.out")"
# The Python module, where Debian's python3 reads modules for /usr, using the unpacked libraries
# and data (built with GC_BUILD_PYTHON, docs/python.md).
if grep -q "^GC_BUILD_PYTHON:BOOL=ON" "$build/CMakeCache.txt"; then
  package=$root/usr/lib/python3/dist-packages/gearcoupling
  for file in __init__.py _results.py __init__.pyi py.typed; do
    [ -f "$package/$file" ] || fail "missing /usr/lib/python3/dist-packages/gearcoupling/$file"
  done
  ls "$package"/_gearcoupling.cpython-*.so >/dev/null || fail "no Python extension module"
  (cd "$tmp" && PYTHONPATH=$root/usr/lib/python3/dist-packages /usr/bin/python3 -c '
import sys, gearcoupling as gc
root = sys.argv[1]
assert gc.__file__.startswith(root), gc.__file__
assert str(gc.bundled_data_dir("couplings")) == root + "/usr/share/gearcoupling/couplings"
print("python:", gc.jam_angle("nrel_downwind").angle_deg, gc.Model("paper").effects)
' "$root") || fail "the unpacked Python module does not run"
fi
echo "PASS: the .deb unpacked and served"
