#!/bin/bash
# test_abi_loader.sh LIB GENERATED_DIR SOURCE_DIR ABI CC: what the soname
# libgranwave.so.ABI does for a program built against another ABI.
#  1. tests/abi/abi_caller.c built against these headers and LIB runs (its own
#     check of gw_abi_version() and of gw_err's size passes);
#  2. the same program built against headers of ABI+1 and a stand-in library of
#     that ABI (soname libgranwave.so.ABI+1) is refused by the dynamic linker
#     where only LIB is installed: exit 127, "libgranwave.so.ABI+1: cannot open
#     shared object file", nothing of main printed;
#  3. that program made to load LIB anyway (a libgranwave.so.ABI+1 link to it)
#     is refused by its own check: exit 2 naming both ABIs, nothing else;
#  4. a program linked as every build before the ABI number made (soname
#     libgranwave.so.0.1) is refused by the dynamic linker too.
set -u
lib=$1 gen=$2 src=$3 abi=$4 cc=$5
other=$((abi + 1))
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gw_abi_loader.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
# LIB alone in a directory, under its soname, as an install holds it (a build
# directory may keep links of earlier sonames)
libdir=$tmp/lib
mkdir -p "$libdir"
cp "$lib" "$libdir/" && ln -s "$(basename "$lib")" "$libdir/libgranwave.so.$abi" && ln -s "libgranwave.so.$abi" "$libdir/libgranwave.so"
inc=(-I"$gen" -I"$src/app/lib" -I"$src/common" -I"$src/common/solver" -I"$src/common/sweep"
     -I"$src/common/stats" -I"$src/chain" -I"$src/layer")
needed() { readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(libgranwave[^]]*\)\]/\1/p'; }

# 1. this ABI
"$cc" -std=c11 "${inc[@]}" "$src/tests/abi/abi_caller.c" -L"$libdir" -lgranwave -o "$tmp/same" \
  || { echo "FAIL: abi_caller does not build against these headers"; exit 1; }
[ "$(needed "$tmp/same")" = "libgranwave.so.$abi" ] || fail "abi_caller needs '$(needed "$tmp/same")', not libgranwave.so.$abi"
out=$(LD_LIBRARY_PATH="$libdir" "$tmp/same" 2>"$tmp/err"); rc=$?
[ $rc -eq 0 ] && [ "$out" = "ran ABI $abi" ] || fail "abi_caller with its own ABI: exit $rc, '$out', $(cat "$tmp/err")"

# 2. built for ABI+1 (its headers and a stand-in library of that soname)
mkdir -p "$tmp/other/include" "$tmp/other/lib"
sed "s/^#define GW_ABI_VERSION .*/#define GW_ABI_VERSION $other/" "$gen/gw_version.h" > "$tmp/other/include/gw_version.h"
grep -q "^#define GW_ABI_VERSION $other\$" "$tmp/other/include/gw_version.h" || fail "no GW_ABI_VERSION in $gen/gw_version.h"
cat > "$tmp/other/stub.c" <<STUB
#include <stddef.h>
int gw_abi_version(void) { return $other; }
size_t gw_struct_size(const char *name) { (void)name; return 512; }
const char *gw_version(void) { return "0.0.0"; }
STUB
"$cc" -shared -fPIC -Wl,-soname,libgranwave.so.$other -o "$tmp/other/lib/libgranwave.so.$other" "$tmp/other/stub.c" \
  && ln -s "libgranwave.so.$other" "$tmp/other/lib/libgranwave.so" || { echo "FAIL: the stand-in library does not build"; exit 1; }
"$cc" -std=c11 -I"$tmp/other/include" "${inc[@]}" "$src/tests/abi/abi_caller.c" -L"$tmp/other/lib" -lgranwave \
  -o "$tmp/other_prog" || { echo "FAIL: abi_caller does not build against ABI $other"; exit 1; }
[ "$(needed "$tmp/other_prog")" = "libgranwave.so.$other" ] || fail "the ABI $other program needs '$(needed "$tmp/other_prog")'"
LD_LIBRARY_PATH="$tmp/other/lib" "$tmp/other_prog" > "$tmp/out" 2>&1
[ "$(cat "$tmp/out")" = "ran ABI $other" ] || fail "the ABI $other program with its own library: $(cat "$tmp/out")"
LD_LIBRARY_PATH="$libdir" "$tmp/other_prog" > "$tmp/out" 2> "$tmp/err"; rc=$?
[ $rc -eq 127 ] || fail "the ABI $other program with LIB: exit $rc, expected 127 (the dynamic linker's refusal)"
grep -q "libgranwave.so.$other: cannot open shared object file" "$tmp/err" \
  || fail "the dynamic linker's message: $(cat "$tmp/err")"
[ ! -s "$tmp/out" ] || fail "the refused program printed: $(cat "$tmp/out")"
echo "refused by the dynamic linker: $(head -1 "$tmp/err")"

# 3. ... made to load LIB anyway: its own check refuses
mkdir -p "$tmp/forced"
ln -s "$libdir/libgranwave.so.$abi" "$tmp/forced/libgranwave.so.$other"
LD_LIBRARY_PATH="$tmp/forced" "$tmp/other_prog" > "$tmp/out" 2> "$tmp/err"; rc=$?
[ $rc -eq 2 ] || fail "the ABI $other program forced onto LIB: exit $rc, expected 2"
[ "$(cat "$tmp/err")" = "abi_caller: libgranwave has ABI $abi, this program was compiled for ABI $other" ] \
  || fail "its check's message: $(cat "$tmp/err")"
[ ! -s "$tmp/out" ] || fail "the refused program printed: $(cat "$tmp/out")"
echo "refused by its check: $(cat "$tmp/err")"

# 4. a program linked before the ABI number (soname libgranwave.so.0.1)
mkdir -p "$tmp/old"
printf 'const char *gw_version(void) { return "0.1.0"; }\n' > "$tmp/old/stub.c"
printf 'const char *gw_version(void);\n#include <stdio.h>\nint main(void) { puts(gw_version()); return 0; }\n' \
  > "$tmp/old/prog.c"
"$cc" -shared -fPIC -Wl,-soname,libgranwave.so.0.1 -o "$tmp/old/libgranwave.so" "$tmp/old/stub.c" &&
  "$cc" "$tmp/old/prog.c" -L"$tmp/old" -lgranwave -o "$tmp/old/prog" || { echo "FAIL: the 0.1 program does not build"; exit 1; }
LD_LIBRARY_PATH="$libdir" "$tmp/old/prog" > "$tmp/out" 2> "$tmp/err"; rc=$?
[ $rc -eq 127 ] && grep -q "libgranwave.so.0.1: cannot open shared object file" "$tmp/err" && [ ! -s "$tmp/out" ] \
  || fail "a program of soname 0.1 with LIB: exit $rc, $(cat "$tmp/out" "$tmp/err")"

[ $fails -eq 0 ] || { echo "test_abi_loader: $fails failure(s)"; exit 1; }
echo "PASS: test_abi_loader (ABI $abi; a program of ABI $other and one of soname 0.1 refused)"
