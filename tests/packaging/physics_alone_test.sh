#!/usr/bin/env bash
# ctest packaging.physics_alone: `cmake --install` into a temporary prefix; the control program's
# project (tests/packaging/physics_consumer/, copied out of the tree) configured with
# find_package(gearcoupling), linking gearcoupling::physics alone, built against it; the link
# line names no other library of the project (gearcoupling::physics brings none: the toolchain's
# --as-needed alone would hide one), the program needs libgearcoupling-physics and no other
# (readelf -d: NEEDED), loads no libgearcoupling-diagnosis (ldd), and computes the paper's jam
# angle. No network, no service.
#   physics_alone_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
. "$(dirname "$0")/scratch.sh"
scratch gc_physics_alone

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
cp -r "$source/tests/packaging/physics_consumer" "$tmp/consumer"
cp "$source/tests/core/nrel_couplings.h" "$tmp/consumer/"   # the NREL couplings as value types
cmake -S "$tmp/consumer" -B "$tmp/consumer/build" -G "Unix Makefiles" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >"$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log"; fail "configure"; }
cmake --build "$tmp/consumer/build" -j 2 >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; fail "build"; }
program=$tmp/consumer/build/physics_consumer
link=$(cat "$tmp/consumer/build/CMakeFiles/physics_consumer.dir/link.txt")
grep -q 'libgearcoupling-physics\.so' <<<"$link" || fail "the physics is not on the link line: $link"
if grep -oE 'libgearcoupling-[a-z]+' <<<"$link" | grep -vx libgearcoupling-physics; then
  fail "gearcoupling::physics brings another library of the project onto the link line: $link"
fi

needed=$(readelf -d "$program" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
echo "NEEDED: $(echo $needed)"
grep -qx 'libgearcoupling-physics\.so\.0' <<<"$needed" || fail "the program does not need libgearcoupling-physics"
others=$(grep 'libgearcoupling-' <<<"$needed" | grep -vx 'libgearcoupling-physics\.so\.0') || true
[ -z "$others" ] || fail "the program needs $others besides the physics"
loaded=$(ldd "$program")
grep -q "libgearcoupling-physics\.so\.0 => $prefix/" <<<"$loaded" ||
  fail "the installed physics is not what loads: $loaded"
if grep -q 'libgearcoupling-diagnosis' <<<"$loaded"; then fail "the program loads the diagnosis: $loaded"; fi
# libgearcoupling-physics itself needs no other library of the project.
if readelf -d "$(grep -o "$prefix/[^ ]*libgearcoupling-physics\.so\.0" <<<"$loaded")" | grep 'NEEDED.*libgearcoupling-'; then
  fail "libgearcoupling-physics needs another library of the project"
fi
"$program" || fail "the physics consumer"
echo "PASS: a find_package(gearcoupling) program linked the physics alone and ran"
