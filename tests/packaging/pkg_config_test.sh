#!/usr/bin/env bash
# ctest packaging.pkg_config: `cmake --install` into a temporary prefix; a program using the core
# compiled and linked with nothing but `pkg-config --cflags --libs gearcoupling-core` from that
# prefix, and run; the client and codec modules resolve too.
#   pkg_config_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
tmp=$(mktemp -d /tmp/gc_pkg_config.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
libdir=$(dirname "$(find "$prefix" -name gearcoupling-core.pc)")/..
export PKG_CONFIG_PATH=$libdir/pkgconfig
# shellcheck disable=SC2046  # pkg-config's output is a list of flags
g++ -std=c++20 -o "$tmp/core_program" "$source/tests/packaging/pkg_config_core.cc" \
  $(pkg-config --cflags --libs gearcoupling-core)
LD_LIBRARY_PATH=$libdir "$tmp/core_program"
pkg-config --cflags --libs gearcoupling-client gearcoupling-codec >/dev/null
[ "$(pkg-config --modversion gearcoupling-core)" = "$(pkg-config --modversion gearcoupling-client)" ]
echo "PASS: pkg-config gearcoupling-core built and ran a program"
