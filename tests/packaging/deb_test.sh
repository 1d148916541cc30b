#!/usr/bin/env bash
# ctest packaging.deb: the Debian packages of debian/ (libgearcoupling0, libgearcoupling-dev,
# python3-gearcoupling, gearcoupling) made from this build by dpkg-buildpackage (GC_BUILD_DIR:
# `cmake --install` of this build under /usr, no rebuild); lintian finds no error and no warning
# in them (overrides carry their reason in debian/*.lintian-overrides); their control data and
# file lists are checked; then deb_installed_checks.sh installs them with dpkg at their real
# paths inside private mount, network and PID namespaces (needs root, as CI has): the first remote
# call with CYCLONEDDS_URI unset, the units' command lines, building against -dev, the purge.
#   deb_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
. "$(dirname "$0")/scratch.sh"
scratch gc_deb

# dpkg-buildpackage writes beside debian/: a scratch copy of it, not the source tree.
mkdir "$tmp/src"
cp -r "$source/debian" "$tmp/src/debian"
# debian/rules packs only a build with Debian's hardening flags (-DGC_DPKG_BUILDFLAGS=ON); a test
# build without them is packed anyway, and its hardening is not checked.
hardened=0
grep -qiE '^GC_DPKG_BUILDFLAGS:BOOL=(ON|1|TRUE|YES|Y)$' "$build/CMakeCache.txt" && hardened=1
if [ "$hardened" = 0 ]; then
  echo "NOTE: $build was not configured with -DGC_DPKG_BUILDFLAGS=ON: packed with" \
       "GC_UNHARDENED_OK=1, the binaries' hardening not checked"
fi
(cd "$tmp/src" && GC_BUILD_DIR=$build GC_UNHARDENED_OK=$((1 - hardened)) \
   dpkg-buildpackage -b -uc -us >"$tmp/dpkg-buildpackage.log" 2>&1) ||
  { tail -30 "$tmp/dpkg-buildpackage.log" >&2; fail "dpkg-buildpackage"; }
version=$(dpkg-parsechangelog -l "$source/debian/changelog" -S Version)
arch=$(dpkg --print-architecture)
deb() { echo "$tmp/${1}_${version}_${arch}.deb"; }
packages=(libgearcoupling0 libgearcoupling-dev python3-gearcoupling gearcoupling)
for package in "${packages[@]}"; do
  [ -f "$(deb "$package")" ] || fail "no $package .deb"
done

# lintian on everything built (the .changes: the packages and the .buildinfo): no error, no
# warning. (As root it says that it would rather not be: that line is not a finding.)
# -I: the informational tags too, where the hardening ones are.
lintian -I --fail-on error,warning "$tmp"/gearcoupling_"$version"_"$arch".changes >"$tmp/lintian.out" 2>&1 ||
  { cat "$tmp/lintian.out" >&2; fail "lintian"; }
grep -v "running with root privileges" "$tmp/lintian.out" | sed 's/^/lintian: /' || true
if [ "$hardened" = 1 ] && grep -E "hardening-no-(bindnow|fortify-functions|relro)" "$tmp/lintian.out"; then
  fail "binaries of a build with -DGC_DPKG_BUILDFLAGS=ON lack hardening (lintian -I above)"
fi
if ls "$tmp"/*.ddeb "$tmp"/*-dbgsym_*.deb 2>/dev/null; then fail "-dbgsym packages of a build without debug information"; fi

# Control data. Each package's Depends: those dpkg-shlibdeps found, and the -dev packages of
# what the headers include (no Cyclone: client.h includes none of its headers).
depends() { dpkg-deb -f "$(deb "$1")" Depends; }
has() {  # has PACKAGE DEPENDENCY...
  local package=$1 dependency list
  list=", $(depends "$package"),"
  shift
  for dependency in "$@"; do
    [[ "$list" == *", $dependency "* || "$list" == *", $dependency,"* ]] ||
      fail "$package: Depends lacks $dependency: $(depends "$package")"
  done
}
has libgearcoupling0 libddsc0debian libprotobuf32 libstdc++6
has libgearcoupling-dev libgearcoupling0 libeigen3-dev libprotobuf-dev
[[ "$(depends libgearcoupling-dev)" == *"libgearcoupling0 (= $version)"* ]] ||
  fail "libgearcoupling-dev does not depend on its libgearcoupling0: $(depends libgearcoupling-dev)"
if [[ "$(depends libgearcoupling-dev)" == *cyclonedds* ]]; then fail "libgearcoupling-dev needs Cyclone"; fi
has python3-gearcoupling python3 python3-numpy libgearcoupling0
has gearcoupling adduser libgearcoupling0 libspdlog1.10-fmt9 libfmt9
for package in "${packages[@]}"; do dpkg-deb -e "$(deb "$package")" "$tmp/control-$package"; done
for library in physics diagnosis codec client; do
  grep -q "^libgearcoupling-$library 0 libgearcoupling0 (>= $version)" "$tmp/control-libgearcoupling0/shlibs" ||
    fail "shlibs: $(cat "$tmp/control-libgearcoupling0/shlibs")"
done
[ "$(sort "$tmp/control-gearcoupling/conffiles")" = "$(printf '/etc/gearcoupling/%s\n' \
    cyclonedds.xml dashboard.conf monitor.conf service.conf)" ] ||
  fail "conffiles: $(cat "$tmp/control-gearcoupling/conffiles")"
grep -q "adduser --system" "$tmp/control-gearcoupling/postinst" || fail "postinst makes no system user"
# The units are stopped on removal.
grep -q "deb-systemd-invoke stop 'gearcoupling-dashboard.service' 'gearcoupling-monitor.service' 'gearcoupling-service.service'" \
  "$tmp/control-gearcoupling/prerm" || fail "prerm does not stop the units"

# Files: each in its package.
contents() { dpkg-deb -c "$(deb "$1")" | awk '{print $6}' | sed 's|^\./|/|'; }
in_package() {  # in_package PACKAGE PATH-PATTERN...
  local package=$1 pattern list
  list=$(contents "$package")
  shift
  for pattern in "$@"; do
    grep -qxE "$pattern" <<<"$list" || fail "$package lacks $pattern"
  done
}
for library in physics diagnosis codec client; do
  in_package libgearcoupling0 "/usr/lib/[^/]+/libgearcoupling-$library\\.so\\.0\\.1\\.0"
  in_package libgearcoupling-dev "/usr/lib/[^/]+/libgearcoupling-$library\\.so" \
    "/usr/lib/[^/]+/pkgconfig/gearcoupling-$library\\.pc"
done
in_package libgearcoupling0 '/usr/share/doc/libgearcoupling0/copyright'
in_package libgearcoupling-dev '/usr/lib/[^/]+/pkgconfig/gearcoupling-core\.pc' \
  '/usr/include/gearcoupling/client/client\.h' '/usr/include/gearcoupling/core/jam_angle\.h' \
  '/usr/include/gearcoupling/diagnosis/diagnose\.h' \
  '/usr/include/gearcoupling/idl/coupling\.pb\.h' \
  '/usr/lib/[^/]+/cmake/gearcoupling/gearcoupling-config\.cmake'
in_package python3-gearcoupling '/usr/lib/python3/dist-packages/gearcoupling/__init__\.py' \
  '/usr/lib/python3/dist-packages/gearcoupling/_gearcoupling\.cpython-[0-9]+-[^/]+\.so'
in_package gearcoupling '/usr/bin/gearcoupling(-service|-monitor|-dashboard)?' \
  '/lib/systemd/system/gearcoupling-(service|monitor|dashboard)\.service' \
  '/etc/gearcoupling/(service|monitor|dashboard)\.conf' '/etc/gearcoupling/cyclonedds\.xml' \
  '/usr/share/gearcoupling/couplings/nrel_(up|down)wind\.textproto' \
  '/usr/share/gearcoupling/models/paper\.textproto' \
  '/usr/share/gearcoupling/deploy/cyclonedds-loopback-client\.xml' \
  '/usr/share/gearcoupling/deploy/security/make-security\.sh' \
  '/usr/share/bash-completion/completions/gearcoupling' '/usr/share/doc/gearcoupling/docs/deploy\.md'
# The client's headers need no Cyclone header and nothing idlc generated (docs/deploy.md).
if contents libgearcoupling-dev | grep -E '/gearcoupling\.h$|client_core\.h$'; then
  fail "libgearcoupling-dev ships a header of the client's DDS side"
fi
# The headers include, beyond the standard library and each other, only Eigen and protobuf:
# the -dev packages libgearcoupling-dev depends on.
dpkg -x "$(deb libgearcoupling-dev)" "$tmp/dev"
others=$(grep -rhoE '#include <[A-Za-z0-9_.]+/' "$tmp/dev/usr/include" | sort -u | grep -vE '<(Eigen|google)/$') || true
[ -z "$others" ] || fail "libgearcoupling-dev's headers include $others: its -dev package belongs in Depends"
# /usr/share/doc/gearcoupling: the README and the pages it links to (docs/*.md), nothing of the
# build (CMakeLists.txt, the tutorial's test helper); every link of the README to a file resolves.
docs=$(contents gearcoupling | grep '^/usr/share/doc/gearcoupling/' | grep -v '/$')
if grep -E 'CMakeLists\.txt$|\.py$' <<<"$docs"; then fail "/usr/share/doc/gearcoupling ships build files"; fi
dpkg -x "$(deb gearcoupling)" "$tmp/doc-check"
doc=$tmp/doc-check/usr/share/doc/gearcoupling
for link in $(grep -oE '\]\([^)#]+' "$doc/README.md" | sed 's/^](//' | grep -vE '^[a-z]+:' | sort -u); do
  [ -f "$doc/$link" ] || fail "the installed README links to $link, which is not installed"
done
# The man pages: help2man's sections and debian/man/*.h2m's FILES, ENVIRONMENT, EXAMPLES.
for program in gearcoupling gearcoupling-service gearcoupling-monitor gearcoupling-dashboard; do
  page=$tmp/doc-check/usr/share/man/man1/$program.1.gz
  for section in FILES ENVIRONMENT EXAMPLES; do
    zcat "$page" | grep -qx "\.SH $section" || fail "man page $program.1 has no $section section"
  done
done
# Each file in one package only.
duplicates=$(for package in "${packages[@]}"; do contents "$package" | grep -v '/$'; done | sort | uniq -d)
[ -z "$duplicates" ] || fail "files in two packages: $duplicates"

# The units: the package's paths, the fixed system user, hardening; systemd's own reading of each
# (a copy whose ExecStart is the unpacked binary): no unknown key, no value it cannot parse.
root=$tmp/root
dpkg -x "$(deb gearcoupling)" "$root"
for program in gearcoupling-service gearcoupling-monitor gearcoupling-dashboard; do
  unit=$root/lib/systemd/system/$program.service
  config=${program#gearcoupling-}
  for line in "ExecStart=/usr/bin/$program --config /etc/gearcoupling/$config.conf" \
      "User=gearcoupling" "NoNewPrivileges=yes" "ProtectSystem=strict" "ProtectHome=yes" \
      "PrivateTmp=yes" "CapabilityBoundingSet=" \
      "RestrictAddressFamilies=AF_INET AF_INET6 AF_UNIX AF_NETLINK"; do
    grep -qxF "$line" "$unit" || fail "$program.service lacks: $line"
  done
  if grep -q "^DynamicUser\|^Environment=CYCLONEDDS_URI" "$unit"; then
    fail "$program.service uses DynamicUser or sets CYCLONEDDS_URI (the programs find the installed file)"
  fi
  if command -v systemd-analyze >/dev/null; then
    sed "s|/usr/bin/|$root/usr/bin/|" "$unit" >"$tmp/$program.service"
    verify=$(systemd-analyze verify "$tmp/$program.service" 2>&1) || true
    [ -z "$verify" ] || fail "systemd-analyze verify $program.service: $verify"
  else
    echo "systemd-analyze not installed: the units' syntax is not verified"
  fi
done

# Installed for real, in namespaces of its own.
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP: installing the packages needs root (a private mount namespace with overlays)"
  exit 77
fi
# A PID namespace too: whatever the checks started dies with them, even if they fail midway.
unshare --mount --net --pid --fork --propagation private \
  bash "$(dirname "$0")/deb_installed_checks.sh" "$tmp" "$source" "$version" ||
  fail "installed packages (deb_installed_checks.sh)"
echo "PASS: the four .debs built, lintian-clean, installed, served, built against and purged"
