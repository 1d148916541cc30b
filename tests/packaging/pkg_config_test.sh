#!/usr/bin/env bash
# ctest packaging.pkg_config: `cmake --install` into a temporary prefix; every installed .pc
# passes `pkg-config --validate`, names only pkg-config modules that exist, and gives normalised
# paths under the prefix (no "..": the prefix is written at install time) and no Cyclone flag (the
# headers include none); a program using the physics and one using the client are compiled and
# linked with nothing but `pkg-config --cflags --libs` from that prefix, and run (the client's on
# a domain with no service, with CYCLONEDDS_URI unset: its timeout names the configuration the
# installed library found). gearcoupling-core (the physics with the diagnosis, their name before
# issue 41) builds the physics program too, and the headers' old paths still compile. The
# installed CMake package has no configure-time residue such as `if(ON)`.
#   pkg_config_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
. "$(dirname "$0")/scratch.sh"
scratch gc_pkg_config

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
pcdir=$(dirname "$(find "$prefix" -name gearcoupling-physics.pc)")
libdir=$(cd "$pcdir/.." && pwd)
export PKG_CONFIG_PATH=$pcdir
modules=(gearcoupling-physics gearcoupling-diagnosis gearcoupling-core gearcoupling-codec)
[ -f "$pcdir/gearcoupling-client.pc" ] && modules+=(gearcoupling-client)
for module in "${modules[@]}"; do
  pkg-config --validate "$module" || fail "pkg-config --validate $module"
  flags=$(pkg-config --cflags --libs "$module") || fail "pkg-config --cflags --libs $module"
  [[ "$flags" != *"/.."* && "$flags" != *"//"* ]] || fail "$module: unnormalised path in: $flags"
  [[ "$flags" == *"-I$prefix/include/gearcoupling"* && "$flags" == *"-L$libdir "* ]] ||
    fail "$module: flags not under the prefix $prefix: $flags"
  [[ "$flags" != *ddsc* && "$flags" != *DDS_* ]] || fail "$module leaks Cyclone's flags: $flags"
done
for module in "${modules[@]}"; do
  [ "$(pkg-config --modversion "$module")" = "$(pkg-config --modversion gearcoupling-physics)" ] ||
    fail "$module's version is not gearcoupling-physics'"
done
if grep -rnE '^\s*if\((ON|OFF|TRUE|FALSE|YES|NO|[01])\)' "$libdir/cmake/gearcoupling"; then
  fail "the installed CMake package tests a constant"
fi

# shellcheck disable=SC2046  # pkg-config's output is a list of flags
for module in gearcoupling-physics gearcoupling-core; do
  g++ -std=c++20 -o "$tmp/physics_program" "$source/tests/packaging/pkg_config_physics.cc" \
    $(pkg-config --cflags --libs "$module") || fail "the physics program does not build with $module"
  LD_LIBRARY_PATH=$libdir "$tmp/physics_program" || fail "the physics program built with $module"
done
[[ "$(pkg-config --libs gearcoupling-physics)" != *diagnosis* ]] ||
  fail "gearcoupling-physics brings the diagnosis: $(pkg-config --libs gearcoupling-physics)"
old_paths='#include "core/diagnosis/diagnose.h"
#include "core/validation/error_bins.h"
#include "core/synthesis/synthesize.h"'
[ -f "$pcdir/gearcoupling-client.pc" ] && old_paths+=$'\n#include "clients/remote/client.h"'
# shellcheck disable=SC2046
g++ -std=c++20 -fsyntax-only -x c++ - $(pkg-config --cflags gearcoupling-core) <<<"$old_paths" ||
  fail "the headers' paths before issue 41 do not compile"
if [ -f "$pcdir/gearcoupling-client.pc" ]; then
  # shellcheck disable=SC2046
  g++ -std=c++20 -o "$tmp/client_program" "$source/tests/packaging/pkg_config_client.cc" \
    $(pkg-config --cflags --libs gearcoupling-client) || fail "the client program does not build"
  # Domains 216-230: apart from tests/service's 1-200 and packaging.find_package's 201-215.
  (unset CYCLONEDDS_URI && LD_LIBRARY_PATH=$libdir "$tmp/client_program" $((216 + $$ % 15)) \
    "file://$prefix/etc/gearcoupling/cyclonedds.xml") || fail "the client program"
fi
echo "PASS: pkg-config: valid modules, a physics and a client program built with them and run"
