#!/bin/bash
# refusal_lib.sh: sourced by the input-handling tests (test_cli_refusals.sh,
# test_hostile_chain.sh, test_hostile_layer.sh) after they set GW (the program),
# SRC (the source tree) and tmp (a scratch directory removed on exit). Gives the
# counters (test_lib.sh's) and the refusal check they share:
#   refused WHAT PATTERN CMD...: exit 2 within REFUSE_TIMEOUT seconds of CPU
#   (20; cpu_run: the same work on a loaded machine, a hang caught by its wall
#   guard), exactly
#   one stderr line matching PATTERN, no sanitizer report, nothing printed on
#   stdout and nothing at $tmp/o (the --out the cases name): exits_refused's
#   checks, which tests with other leftovers to check call themselves.
#   runs_json WHAT FILE CMD...: exit 0 within 60 s of CPU, the JSON in FILE.
#   jq_py FILE EXPR: EXPR over the JSON d of FILE, printed (Debian's python3).
#   py_checks [N]: the Python script on stdin run against this build's module
#   and library, each line it prints "PASS: ..." or "FAIL: ..." counted as a
#   check; a script that ends with a status other than 0 (a traceback), or, N
#   given, prints other than N checks (it stopped, or the module did not
#   load), is a failed check too; skipped, saying so and setting py_skipped,
#   in a sanitizer build. The script starts with granwave and warnings
#   imported (a module that does not load: one FAIL line, the script ends)
#   and these helpers (py_prelude below):
#     check(COND, WHAT): prints "PASS: WHAT" or "FAIL: WHAT";
#     caught(FN, *ARGS, **KW): FN(*ARGS, **KW) with every warning recorded,
#       returns its result and the texts of its GranwaveWarnings;
#     refused(WHAT, NEEDLES, FN, *ARGS, **KW): FN(*ARGS, **KW) raises
#       GranwaveValueError whose text holds every string of NEEDLES (a check
#       either way: it ran, or raised something else, is a failed one);
#     warned(WHAT, NEEDLE, FN, *ARGS, **KW): FN(*ARGS, **KW) runs and one of
#       its GranwaveWarnings holds NEEDLE (a check either way); returns its
#       result (None when it raised).
#   pyenv CMD...: CMD run with this build's Python module and library
#   (PYTHONPATH, GRANWAVE_LIB), as py_checks runs its script.
#   make_sample FILE ARGS...: layer-make --out FILE ARGS (its output dropped);
#   a failure is a failed check that ends the test.
#   settling_sweep_ini FILE SAMPLE [LINES]: a layer sweep's configuration in
#   FILE, two cases (vi = 10, 20) on SAMPLE at t-max 0.002 s, LINES ("key =
#   value" lines) added to its [params]: the settling tests' sweep.
#   callgrind_edges CMD...: the program run as CMD under callgrind, its call
#   graph's call sites as lines "CALLER CALLEE COUNT" (each site's "calls="
#   count under its cfn= line, the caller the fn= line above it; "?" for a
#   name callgrind does not give); status 1 and nothing when valgrind could
#   not run it: the call-counting tests' (the settling check's, the weighing's).
#   sanitizer_build: true in a sanitizer build (GW_SANITIZE: the program linked
#   against ASan's or UBSan's runtime, or holding ASan's entry point, as a
#   static runtime would): the one test of it that the scripts share.
# the counters, ok and ko, and the run-control helpers: test_lib.sh
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"

# exits_refused WHAT PATTERN SECONDS CMD...: CMD (stdin /dev/null, its output
# in $tmp/stdout and $tmp/stderr) exits 2 within SECONDS, one stderr line
# matching PATTERN, no sanitizer report, nothing on stdout (SECONDS of CPU:
# cpu_run). A failed check is
# counted (ko) and returns 1; a pass counts nothing and returns 0, for the
# caller to check what CMD left behind and count the refusal.
# hostile_setup "$@": test_setup, SRC made absolute, the scratch directory
# entered and the sanitizer build's leak suppressions exported (as setup.sh
# test runs that build): the opening of the hostile passes' tests and of the
# others that work in the scratch directory
hostile_setup() {
    test_setup "$@"
    SRC=$(cd "$SRC" && pwd)
    cd "$tmp" || exit 1
    export LSAN_OPTIONS="suppressions=$SRC/tests/lsan.supp:print_suppressions=0"
}

exits_refused() {
    local what=$1 pat=$2 secs=$3; shift 3
    cpu_run "$secs" "$@" >"$tmp/stdout" 2>"$tmp/stderr" </dev/null
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

# runs_quiet WHAT ARGS...: the program with ARGS and --quiet exits 0 within 60 s of CPU
runs_quiet() {
    local what=$1
    shift
    cpu_run 60 "$GW" "$@" --quiet >/dev/null 2>"$tmp/stderr" </dev/null &&
        ok "$what" || ko "$what: exit $? ($(head -c 200 "$tmp/stderr"))"
}

runs_json() {
    local what=$1 out=$2; shift 2
    cpu_run 60 "$GW" "$@" --json >"$out" 2>"$tmp/stderr" </dev/null
    local rc=$?
    if [ $rc -ne 0 ]; then ko "$what: exit $rc ($(head -c 300 "$tmp/stderr"))"; return 1; fi
    return 0
}
jq_py() { /usr/bin/python3 -c "import json,sys; d=json.load(open('$1')); print($2)"; }

sanitizer_build() {
    ldd "$GW" 2>/dev/null | grep -qE 'lib(a|ub)san' || grep -qa '__asan_init' "$GW" 2>/dev/null
}

pyenv() { PYTHONPATH="$SRC/python" GRANWAVE_LIB="$(dirname "$GW")/lib" "$@"; }

# The helpers every py_checks script starts with (see the header).
py_prelude() {
    cat <<'EOF'
import sys, warnings
try:
    import granwave
except Exception as e:  # noqa: BLE001
    print("FAIL: Python: the module does not load: %s" % e)
    raise SystemExit
def check(cond, what):
    print(("PASS: " if cond else "FAIL: ") + what)
def caught(fn, *args, **kw):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = fn(*args, **kw)
    return r, [str(x.message) for x in w if issubclass(x.category, granwave.GranwaveWarning)]
def warned(what, needle, fn, *args, **kw):
    try:
        r, ws = caught(fn, *args, **kw)
    except Exception as e:  # noqa: BLE001
        print("FAIL: %s: raised %s: %s" % (what, type(e).__name__, str(e)[:160]))
        return None
    check(any(needle in m for m in ws), "%s: warned %s" % (what, [m[:100] for m in ws]))
    return r
def refused(what, needles, fn, *args, **kw):
    try:
        fn(*args, **kw)
        print("FAIL: %s: ran" % what)
    except granwave.GranwaveValueError as e:
        check(all(n in str(e) for n in needles), "%s: refused: %s" % (what, str(e)[:160]))
    except Exception as e:  # noqa: BLE001
        print("FAIL: %s: raised %s: %s" % (what, type(e).__name__, str(e)[:160]))
EOF
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
    { py_prelude; cat; } >"$tmp/py.in"
    # PY_TIMEOUT (seconds) given: the script killed after it (a hang is a failed check)
    if [ -n "${PY_TIMEOUT:-}" ]; then
        pyenv timeout -s KILL "$PY_TIMEOUT" /usr/bin/python3 "$tmp/py.in" >"$tmp/py.out" 2>&1
    else
        pyenv /usr/bin/python3 "$tmp/py.in" >"$tmp/py.out" 2>&1
    fi
    local rc=$? line n=0
    while read -r line; do
        case $line in
            PASS:*) ok "${line#PASS: }"; n=$((n+1)) ;;
            FAIL:*) ko "${line#FAIL: }"; n=$((n+1)) ;;
            *) echo "$line" ;;
        esac
    done <"$tmp/py.out"
    [ $rc -eq 0 ] || ko "the Python checks ended with status $rc${PY_TIMEOUT:+ (137: killed at $PY_TIMEOUT s)}: $(tail -1 "$tmp/py.out")"
    [ -z "${1:-}" ] || [ "$n" -eq "$1" ] || ko "the Python checks: $n of $1 ran"
}

make_sample() {
    local out=$1; shift
    "$GW" layer-make --out "$out" "$@" >/dev/null 2>&1 && return
    ko "layer-make --out $out $*"
    test_summary
    exit 1
}

# mpirun as root; have_mpi=1 when mpirun is here and the program links MPI
mpi_setup() {
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    have_mpi=0
    if command -v mpirun >/dev/null && ldd "$GW" 2>/dev/null | grep -q libmpi; then have_mpi=1; fi
}

# FILE: the sweep tests' chain grid, eight cases of about 0.1 to 0.3 s each
# (rk4, 60 to 90 beads)
chain_sweep8_ini() {
    printf '[sweep]\nmodel = chain\n[grid]\nn = 60, 70, 80, 90\nvimp = 0.1, 0.2\n[params]\nsolver = rk4\n' >"$1"
}

# the eight-case chain grid in $tmp/a.ini and its undisturbed table in $tmp/ref
# (one thread), which the sweep tests' disturbed runs are held to
chain_sweep8_reference() {
    chain_sweep8_ini "$tmp/a.ini"
    "$GW" sweep "$tmp/a.ini" --out "$tmp/ref" --quiet --jobs 1 || ko "reference sweep"
}

settling_sweep_ini() {
    printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = %s\nt-max = 0.002\n%s\n' "$2" "${3:-}" >"$1"
}

callgrind_edges() {
    rm -f "$tmp/cg.out"
    timeout -s KILL 300 valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" "$GW" "$@" \
        >/dev/null 2>"$tmp/cg.err" </dev/null || return 1
    /usr/bin/python3 - "$tmp/cg.out" <<'PY'
import re, sys
# a name is given at its first fn= or cfn= line, its id alone after that
names, fn, cfn = {}, "?", None
for line in open(sys.argv[1]):
    line = line.strip()
    m = re.match(r"(c?fn)=\((\d+)\)(?: (.*))?$", line)
    if m:
        if m.group(3):
            names[m.group(2)] = m.group(3).replace(" ", "_")
        name = names.get(m.group(2)) or "?"
        if m.group(1) == "fn":
            fn, cfn = name, None
        else:
            cfn = name
    elif cfn and line.startswith("calls="):
        print(fn, cfn, int(line.split("=")[1].split()[0]))
        cfn = None
PY
}
