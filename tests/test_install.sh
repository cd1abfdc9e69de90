#!/bin/bash
# test_install.sh BUILD_DIR SOURCE_DIR VERSION ABI: `cmake --install` into a temporary
# prefix, then build tests/install/colliding.c against the installed package
# three ways (pkg-config with the shared library, pkg-config --static with
# libgranwave.a, CMake find_package(granwave CONFIG)) and run each: a column
# collision checked against the closed form and the version (see colliding.c).
# Also: every installed header compiles on its own (so none includes a header
# that is not installed), the soname is the ABI number (libgranwave.so.ABI, the
# file libgranwave.so.ABI.VERSION), and the .pc and
# CMake package report the project version, and the installed Python module
# loads the installed library.
set -euo pipefail
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
version=$3
abi=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

p=$tmp/prefix
cmake --install "$build" --prefix "$p" > "$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }
for f in lib/libgranwave.so lib/libgranwave.a lib/pkgconfig/granwave.pc include/granwave/granwave.h \
         include/granwave/gw_version.h lib/cmake/granwave/granwaveConfig.cmake; do
    [ -e "$p/$f" ] || fail "not installed: $f"
done
[ -x "$p/bin/granwave" ] && grep -q "$version" <<<"$("$p/bin/granwave" version)" || fail "the program bin/granwave"
echo "PASS: library, headers, granwave.pc, the CMake package and the program installed"

soname=$(readelf -d "$p/lib/libgranwave.so" | sed -n 's/.*SONAME.*\[\(.*\)\]/\1/p')
[ "$soname" = "libgranwave.so.$abi" ] || fail "soname '$soname', expected libgranwave.so.$abi (GW_ABI_VERSION)"
[ -f "$p/lib/libgranwave.so.$abi.$version" ] || fail "no libgranwave.so.$abi.$version"
[ "$(readlink "$p/lib/libgranwave.so.$abi")" = "libgranwave.so.$abi.$version" ] || fail "libgranwave.so.$abi is no link to the file"
grep -q "^#define GW_ABI_VERSION $abi\$" "$p/include/granwave/gw_version.h" || fail "gw_version.h: no GW_ABI_VERSION $abi"
echo "PASS: soname $soname, file libgranwave.so.$abi.$version, GW_ABI_VERSION $abi"

inc=$p/include/granwave
for h in "$inc"/*.h; do
    printf '#include "%s"\nint gw_header_alone;\n' "$(basename "$h")" | cc -std=c11 -Wall -Wextra -Wpedantic -Werror -fsyntax-only \
        -I"$inc" -x c - || fail "installed header $(basename "$h") does not compile alone"
done
echo "PASS: $(ls "$inc" | wc -l) installed headers compile alone"

export PKG_CONFIG_PATH=$p/lib/pkgconfig
[ "$(pkg-config --modversion granwave)" = "$version" ] || fail "granwave.pc version $(pkg-config --modversion granwave)"
cflags=(-std=c11 -Wall -Wextra -Wpedantic -Werror)
# shellcheck disable=SC2046
cc "${cflags[@]}" "$src/tests/install/colliding.c" $(pkg-config --cflags --libs granwave) \
    -Wl,-rpath,"$p/lib" -o "$tmp/colliding_pc" || fail "build with pkg-config"
"$tmp/colliding_pc" "$version" || fail "colliding (pkg-config, shared)"
# ldd into a file, then grep: under pipefail, grep -q quitting at its match
# made ldd die of SIGPIPE and the pipeline fail (17 of 200 tries)
ldd "$tmp/colliding_pc" > "$tmp/ldd_pc"
grep -q "$p/lib/libgranwave.so" "$tmp/ldd_pc" || fail "colliding_pc does not load the installed library"
echo "PASS: pkg-config build against the shared library"

static_libs=$(pkg-config --static --libs granwave | sed 's/-lgranwave//')
# shellcheck disable=SC2046,SC2086
cc "${cflags[@]}" "$src/tests/install/colliding.c" $(pkg-config --cflags granwave) "$p/lib/libgranwave.a" \
    $static_libs -o "$tmp/colliding_static" || fail "build with pkg-config --static"
ldd "$tmp/colliding_static" > "$tmp/ldd_static" || true
grep -q libgranwave "$tmp/ldd_static" && fail "colliding_static loads libgranwave.so"
"$tmp/colliding_static" "$version" || fail "colliding (pkg-config, static)"
echo "PASS: pkg-config --static build against libgranwave.a"

cmake -S "$src/tests/install" -B "$tmp/b" -DCMAKE_PREFIX_PATH="$p" -DGW_EXPECT_VERSION="$version" \
    -DCMAKE_BUILD_TYPE=Release > "$tmp/cmake.log" || { cat "$tmp/cmake.log"; fail "find_package(granwave)"; }
cmake --build "$tmp/b" > "$tmp/build.log" || { cat "$tmp/build.log"; fail "build with find_package"; }
"$tmp/b/colliding" "$version" || fail "colliding (find_package)"
echo "PASS: find_package(granwave CONFIG) build"

# the Python module installed beside the library finds it without GRANWAVE_LIB
if /usr/bin/python3 -c "import numpy" 2>/dev/null; then
    pyout=$(cd "$tmp" && env -u GRANWAVE_LIB PYTHONPATH="$p/lib/python3/dist-packages" PYTHONDONTWRITEBYTECODE=1 \
        /usr/bin/python3 -c "
import granwave
r = granwave.chain(n=1, vimp=0.3)
print(granwave.version(), granwave.library_path, abs(r.f_max - r.f_max_1) / r.f_max_1)
") || fail "import the installed Python module"
    read -r pyver pylib pyrel <<< "$pyout"
    [ "$pyver" = "$version" ] || fail "Python module reports version $pyver"
    case "$pylib" in "$p"/lib/*) ;; *) fail "installed module loaded $pylib, not the installed library";; esac
    /usr/bin/python3 -c "import sys; sys.exit(0 if float('$pyrel') <= 1e-6 else 1)" || fail "Python F_max(1) rel error $pyrel"
    echo "PASS: installed Python module (library $pylib, F_max(1) rel error $pyrel)"
else
    echo "SKIP: /usr/bin/python3 without numpy: installed Python module not checked"
fi
