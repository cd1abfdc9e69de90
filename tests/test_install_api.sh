#!/bin/bash
# test_install_api.sh BUILD_DIR SOURCE_DIR VERSION: the installed library as a
# third party sees it (docs/library.md "The contract of every call"). Into a
# temporary prefix (cmake --install), then:
#  1. every installed header compiles alone as C11 and as C++17 (-Wall -Wextra
#     -pedantic -Werror), from the prefix only;
#  2. granwave.h defines no macro outside GW_ (min, max, PI, ...): the macros
#     it adds to those of its own includes (<stddef.h>, <stdio.h>, cJSON) all
#     start with GW_ (or are its guard GRANWAVE_H);
#  3. libgranwave.so exports exactly the functions and variables the installed
#     headers declare: nothing without the gw_ prefix, no internal gw_ helper
#     (nm -D --defined-only against the declarations);
#  4. a C++17 program (tests/install/cxx) links and runs, with pkg-config and
#     with find_package(granwave); without extern "C" it did not link;
#  5. tests/test_hostile_api.c, built as an outside C11 program against the
#     installed headers and library (pkg-config), passes;
#  7. docs/library.md's C examples, as written: each block wrapped in a main
#     (its #include lines and a leading function at file scope; err and rc
#     declared when the block uses them without declaring them) compiles with
#     -Wall -Wextra -Werror against the install and runs with rc == GW_OK
#     (the progress example's callback left its ctx unused: -Wunused-parameter);
#  6. libgranwave.a defines as global exactly the symbols libgranwave.so
#     exports, each once (its internal helpers are local: before, 433 globals
#     where the .so exports 342), and tests/install/own_names.c, which defines
#     its own chain_blown_up, chain_steps_check, gw_sun_rhs and layer_snapshot,
#     links statically against it and runs N = 1 against F.13 (before: multiple
#     definition of chain_blown_up).
set -euo pipefail
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
version=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

p=$tmp/prefix
cmake --install "$build" --prefix "$p" > "$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }
inc=$p/include/granwave
export PKG_CONFIG_PATH=$p/lib/pkgconfig
cxx=${CXX:-g++}
command -v "$cxx" > /dev/null || cxx=c++

# 1. each header alone, C11 and C++17
n=0
for h in "$inc"/*.h; do
    b=$(basename "$h")
    printf '#include <%s>\nint gw_header_alone;\n' "$b" | cc -std=c11 -Wall -Wextra -pedantic -Werror -fsyntax-only \
        -I"$inc" -x c - || fail "$b does not compile alone as C11"
    printf '#include <%s>\nint gw_header_alone;\n' "$b" | "$cxx" -std=c++17 -Wall -Wextra -pedantic -Werror \
        -fsyntax-only -I"$inc" -x c++ - || fail "$b does not compile alone as C++17"
    n=$((n + 1))
done
echo "PASS: $n installed headers compile alone as C11 and C++17 (-Wall -Wextra -pedantic -Werror)"

# 2. the macros granwave.h adds
printf '#include <stddef.h>\n#include <stdio.h>\n#include <cjson/cJSON.h>\n' | cc -std=c11 -dM -E -x c - | sort > "$tmp/m0"
printf '#include <granwave.h>\n' | cc -std=c11 -dM -E -I"$inc" -x c - | sort > "$tmp/m1"
added=$(comm -13 "$tmp/m0" "$tmp/m1" | awk '{print $2}' | sed 's/(.*//' | sort -u)
[ -n "$added" ] || fail "no macros seen from granwave.h (the check is broken)"
bad=$(echo "$added" | grep -vE '^(GW_[A-Z0-9_]+|GRANWAVE_H)$' || true)
[ -z "$bad" ] || fail "granwave.h defines macros outside GW_: $(echo $bad)"
echo "PASS: granwave.h adds $(echo "$added" | wc -l) macros, all GW_"

# 3. exported symbols against the headers' declarations
lib=$p/lib/libgranwave.so
nm -D --defined-only "$lib" | awk '{print $3}' | sort -u > "$tmp/exported"
{
    grep -hE '^[a-z][^;(]*[ *]gw_[a-z0-9_]+\(' "$inc"/*.h | grep -vE '^(static|typedef|extern "C")' |
        sed -E 's/^[^(]*[ *](gw_[a-z0-9_]+)\(.*/\1/'
    grep -hE '^extern [^"]' "$inc"/*.h | sed -E 's/.*[ *](gw_[a-z0-9_]+)(\[\])?;.*/\1/'
} | sort -u > "$tmp/declared"
[ "$(wc -l < "$tmp/declared")" -gt 300 ] || fail "only $(wc -l < "$tmp/declared") declarations found (the check is broken)"
leaked=$(comm -23 "$tmp/exported" "$tmp/declared")
[ -z "$leaked" ] || fail "exported but declared in no installed header ($(echo "$leaked" | wc -l)): $(echo $leaked | cut -c1-400)"
missing=$(comm -13 "$tmp/exported" "$tmp/declared")
[ -z "$missing" ] || fail "declared but not exported: $(echo $missing | cut -c1-400)"
echo "PASS: libgranwave.so exports exactly the $(wc -l < "$tmp/exported") symbols its headers declare"

# 4. a C++17 program, pkg-config and find_package
# shellcheck disable=SC2046
"$cxx" -std=c++17 -Wall -Wextra -pedantic -Werror "$src/tests/install/cxx/api_cxx.cpp" \
    $(pkg-config --cflags --libs granwave) -Wl,-rpath,"$p/lib" -o "$tmp/api_cxx" || fail "C++17 build with pkg-config"
"$tmp/api_cxx" "$version" > "$tmp/cxx.log" || { cat "$tmp/cxx.log"; fail "api_cxx (pkg-config)"; }
cmake -S "$src/tests/install/cxx" -B "$tmp/bx" -DCMAKE_PREFIX_PATH="$p" -DGW_EXPECT_VERSION="$version" \
    -DCMAKE_BUILD_TYPE=Release > "$tmp/cmake.log" || { cat "$tmp/cmake.log"; fail "C++ find_package(granwave)"; }
cmake --build "$tmp/bx" > "$tmp/build.log" || { cat "$tmp/build.log"; fail "C++17 build with find_package"; }
"$tmp/bx/api_cxx" "$version" > "$tmp/cxx.log" || { cat "$tmp/cxx.log"; fail "api_cxx (find_package)"; }
echo "PASS: a C++17 program links and runs (pkg-config and find_package): $(grep -c PASS "$tmp/cxx.log") checks"

# 5. the hostile C caller, as an outside program
# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -pedantic -Werror "$src/tests/test_hostile_api.c" $(pkg-config --cflags --libs granwave) \
    -lpthread -Wl,-rpath,"$p/lib" -o "$tmp/hostile" || fail "test_hostile_api.c against the installed library"
"$tmp/hostile" > "$tmp/hostile.log" || { cat "$tmp/hostile.log"; fail "test_hostile_api against the installed library"; }
echo "PASS: test_hostile_api against the installed library: $(tail -1 "$tmp/hostile.log")"

# 7. library.md's C examples as a reader copies them (run before 6, which
# needs nothing from here)
/usr/bin/python3 - "$src/docs/library.md" "$tmp" <<'PY' || fail "extracting library.md's C examples"
import re, sys
text = open(sys.argv[1]).read()
blocks = re.findall(r"```c\n(.*?)```", text, re.S)
assert len(blocks) >= 3, f"only {len(blocks)} C blocks in library.md"
for i, b in enumerate(blocks):
    lines = b.splitlines()
    top = [l for l in lines if l.startswith("#include")]
    body = [l for l in lines if not l.startswith("#include")]
    if body and body[0].startswith("static "):  # a function first: at file scope up to its closing brace
        end = body.index("}") + 1
        top += body[:end]
        body = body[end:]
    decl = []
    if re.search(r"\berr\b", b) and not re.search(r"gw_err err\b", b):
        decl.append("gw_err err = {{0}};")
    if re.search(r"\brc\b", b) and not re.search(r"int rc\b", b):
        decl.append("int rc = GW_OK;")
    src = ["#include <stdio.h>", "#include <granwave.h>"] + top + ["int main(void)", "{"] + decl + body
    src += ["return rc != GW_OK;" if re.search(r"\brc\b", b) else "return 0;", "}"]
    open(f"{sys.argv[2]}/doc_example_{i}.c", "w").write("\n".join(src) + "\n")
PY
ndoc=0
for f in "$tmp"/doc_example_*.c; do
    # shellcheck disable=SC2046
    cc -std=c11 -Wall -Wextra -Werror "$f" $(pkg-config --cflags --libs granwave) -Wl,-rpath,"$p/lib" -o "${f%.c}" \
        > "${f%.c}.log" 2>&1 || { cat "$f" "${f%.c}.log"; fail "library.md's example $(basename "$f") does not compile warning-free"; }
    "${f%.c}" > "${f%.c}.out" 2>&1 || { cat "$f" "${f%.c}.out"; fail "library.md's example $(basename "$f") does not run to GW_OK"; }
    ndoc=$((ndoc + 1))
done
echo "PASS: library.md's $ndoc C examples compile with -Wall -Wextra -Werror and run to GW_OK"

# 6. the static archive: the same global symbols as the shared library, and a
# program with its own functions under the library's internal names
nm --defined-only --extern-only "$p/lib/libgranwave.a" | awk 'NF == 3 {print $3}' | sort > "$tmp/a_all"
[ "$(wc -l < "$tmp/a_all")" -gt 300 ] || fail "only $(wc -l < "$tmp/a_all") global symbols in libgranwave.a (the check is broken)"
twice=$(uniq -d "$tmp/a_all")
[ -z "$twice" ] || fail "defined by several members of libgranwave.a: $(tr '\n' ' ' <<< "$twice" | cut -c1-400)"
leaked=$(comm -23 "$tmp/a_all" "$tmp/exported")
[ -z "$leaked" ] || fail "global in libgranwave.a but not exported by libgranwave.so ($(echo "$leaked" | wc -l)): $(tr '\n' ' ' <<< "$leaked" | cut -c1-400)"
missing=$(comm -13 "$tmp/a_all" "$tmp/exported")
[ -z "$missing" ] || fail "exported by libgranwave.so but not global in libgranwave.a: $(tr '\n' ' ' <<< "$missing" | cut -c1-400)"
echo "PASS: libgranwave.a defines as global exactly the $(wc -l < "$tmp/a_all") symbols libgranwave.so exports"
static_libs=$(pkg-config --static --libs granwave | sed 's/-lgranwave//')
# shellcheck disable=SC2046,SC2086
cc -std=c11 -Wall -Wextra -pedantic -Werror "$src/tests/install/own_names.c" $(pkg-config --cflags granwave) \
    "$p/lib/libgranwave.a" $static_libs -o "$tmp/own_names" || fail "own_names.c (the library's internal names) against libgranwave.a"
"$tmp/own_names" > "$tmp/own.log" || { cat "$tmp/own.log"; fail "own_names against libgranwave.a"; }
echo "PASS: a program with its own chain_blown_up, chain_steps_check, gw_sun_rhs, layer_snapshot links libgranwave.a statically: $(grep -c PASS "$tmp/own.log") checks"
