#!/bin/bash
# refusal_lib.sh: sourced by the input-handling tests (test_cli_refusals.sh,
# test_hostile_chain.sh, test_hostile_layer.sh) after they set GW (the program),
# SRC (the source tree) and tmp (a scratch directory removed on exit). Gives the
# counters (test_lib.sh's) and the refusal check they share:
#   refused WHAT PATTERN CMD...: exit 2 within REFUSE_TIMEOUT seconds (20), exactly
#   one stderr line matching PATTERN, no sanitizer report, nothing printed on
#   stdout and nothing at $tmp/o (the --out the cases name): exits_refused's
#   checks, which tests with other leftovers to check call themselves.
#   runs_json WHAT FILE CMD...: exit 0 within 60 s, the JSON in FILE.
#   jq_py FILE EXPR: EXPR over the JSON d of FILE, printed (Debian's python3).
#   py_checks: the Python script on stdin run against this build's module and
#   library, each line it prints "PASS: ..." or "FAIL: ..." counted as a check;
#   skipped, saying so and setting py_skipped, in a sanitizer build.
#   sanitizer_build: true in a sanitizer build (GW_SANITIZE: the program linked
#   against ASan's or UBSan's runtime, or holding ASan's entry point, as a
#   static runtime would): the one test of it that the scripts share.
# the counters, ok and ko, and the run-control helpers: test_lib.sh
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"

# exits_refused WHAT PATTERN SECONDS CMD...: CMD (stdin /dev/null, its output
# in $tmp/stdout and $tmp/stderr) exits 2 within SECONDS, one stderr line
# matching PATTERN, no sanitizer report, nothing on stdout. A failed check is
# counted (ko) and returns 1; a pass counts nothing and returns 0, for the
# caller to check what CMD left behind and count the refusal.
# hostile_setup "$@": test_setup, SRC made absolute, the scratch directory
# entered and the sanitizer build's leak suppressions exported (as setup.sh
# test runs that build): the opening of the hostile passes' tests
hostile_setup() {
    test_setup "$@"
    SRC=$(cd "$SRC" && pwd)
    cd "$tmp" || exit 1
    export LSAN_OPTIONS="suppressions=$SRC/tests/lsan.supp:print_suppressions=0"
}

exits_refused() {
    local what=$1 pat=$2 secs=$3; shift 3
    timeout -s KILL "$secs" "$@" >"$tmp/stdout" 2>"$tmp/stderr" </dev/null
    local rc=$?
    if [ $rc -ne 2 ]; then ko "$what: exit $rc, expected 2 ($(head -c 300 "$tmp/stderr"))"; return 1; fi
    if [ "$(wc -l <"$tmp/stderr")" -ne 1 ]; then ko "$what: $(wc -l <"$tmp/stderr") stderr lines"; cat "$tmp/stderr"; return 1; fi
    if ! grep -qE -- "$pat" "$tmp/stderr"; then ko "$what: message does not match '$pat': $(cat "$tmp/stderr")"; return 1; fi
    if grep -qE 'Sanitizer|runtime error' "$tmp/stderr"; then ko "$what: sanitizer report"; return 1; fi
    if [ -s "$tmp/stdout" ]; then ko "$what: printed on stdout"; return 1; fi
    return 0
}

refused() {
    local what=$1 pat=$2; shift 2
    rm -rf "$tmp/o"
    exits_refused "$what" "$pat" "${REFUSE_TIMEOUT:-20}" "$GW" "$@" || return
    if [ -e "$tmp/o" ]; then ko "$what: wrote $tmp/o ($(ls "$tmp/o" 2>/dev/null | tr '\n' ' '))"; return; fi
    ok "$what"
}

runs_json() {
    local what=$1 out=$2; shift 2
    timeout -s KILL 60 "$GW" "$@" --json >"$out" 2>"$tmp/stderr" </dev/null
    local rc=$?
    if [ $rc -ne 0 ]; then ko "$what: exit $rc ($(head -c 300 "$tmp/stderr"))"; return 1; fi
    return 0
}
jq_py() { /usr/bin/python3 -c "import json,sys; d=json.load(open('$1')); print($2)"; }

sanitizer_build() {
    ldd "$GW" 2>/dev/null | grep -qE 'lib(a|ub)san' || grep -qa '__asan_init' "$GW" 2>/dev/null
}

py_checks() {
    # a sanitizer build's library needs its runtime loaded first, which Python's
    # interpreter is not built with: the checks are said to be skipped there
    if sanitizer_build; then
        cat >/dev/null
        echo "SKIP: the Python checks (a sanitizer build's library does not load into Python)"
        py_skipped=1
        return
    fi
    PYTHONPATH="$SRC/python" GRANWAVE_LIB="$(dirname "$GW")/lib" /usr/bin/python3 - >"$tmp/py.out" 2>&1
    local line
    while read -r line; do
        case $line in PASS:*) ok "${line#PASS: }" ;; FAIL:*) ko "${line#FAIL: }" ;; *) echo "$line" ;; esac
    done <"$tmp/py.out"
}
