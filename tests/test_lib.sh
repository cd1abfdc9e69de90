#!/bin/bash
# test_lib.sh: sourced by the program's shell tests (and by refusal_lib.sh).
# Gives the counters and the run-control helpers they share:
#   ok WHAT / ko WHAT: a passed / failed check, printed and counted;
#   test_setup "$@": GW (the program, $1, made absolute: tests may cd), SRC
#   (the source tree, $2, else this file's parent), tmp (a scratch directory
#   removed on exit) and set -u;
#   test_summary [NAME]: prints the counts, returns 1 when a check failed.
# Runs that must be stopped mid-way synchronise on an event of the run, never
# on a wall-clock sleep (test_hardening's SIGINTs after 0.2 to 1.5 s came after
# its 0.28 s run had ended; under load a sleep can end before a run has begun):
#   journal_rows FILE: the rows of a sweep journal (0 when there is none);
#   wait_rows FILE N [SECONDS]: until FILE holds N rows (SECONDS, 120);
#   wait_cpu PID SECONDS: until PID has used SECONDS of CPU (user + system, all
#   threads): the same point of its work whatever the machine's load;
#   wait_file PID GLOB: until a file matching GLOB exists (polled every ms with
#   builtins: a write phase of 30 ms is not missed); 1 when PID ended first;
#   cpu_of CMD...: runs CMD (output dropped), prints the CPU seconds it used:
#   the reference for the points of wait_cpu on this machine;
#   stop_mid_sweep SIG DIR TOTAL CMD...: CMD (a sweep into DIR of TOTAL cases)
#   sent SIG once its journal holds a row; asserts nothing, sets rows and rc.
# A run bounded in time is bounded in CPU seconds, the same work whatever the
# machine's load (a wall-clock `timeout 3` was hit by a refusal of a few ms on a
# loaded machine, or let a run that should have been refused pass as "still
# running"):
#   cpu_run SECONDS CMD...: CMD with SECONDS of CPU (RLIMIT_CPU: killed at it,
#   exit 137), its status; a wall-clock guard of CPU_RUN_WALL seconds (300, or
#   10 SECONDS when more) against a run that hangs using no CPU (exit 137 too). No "Killed"
#   line: CMD's stderr is the caller's, the waiting shell's goes nowhere.
#   at_row K SH CMD...: CMD (a sweep, or mpirun running one) with SH, a sh
#   command, run right before the K-th row is appended to its journal (the
#   move shim, tests/move_shim.c; SH and what it starts run without it), the
#   sweep waiting for it: CMD's status. 77 and nothing run in a build without
#   the shim (the caller says SKIP). In a sanitizer build the sanitizer's
#   runtime is preloaded before the shim (sanitizer_runtime). A journal or directory disturbed "once the
#   first row shows" from the script raced the end of a sweep of a second or
#   two on a loaded machine; at a row it is mid-sweep on any.
#   at_row_fn K FN ARG CMD...: at_row, SH the script's shell function FN called
#   with ARG (in bash, with the script's functions and its variables tmp and d,
#   which the sh of the shim would not pass on as exported functions).
# A layer sample's discs read once for every test that checks them:
#   sample_discs FILE: "WIDTH RM N", then "x y r" for each disc;
#   discs_outside FILE: "N ROWS OUT", the discs reaching out of the box.
# A sweep stopped mid-way by a disturbance of its journal (at_row):
#   sweep_stopped WHAT RC ERR LINES PATTERN: exit 1, LINES lines, PATTERN;
#   kept_rows WHAT KEPT BEFORE TOTAL ERR: the journal kept aside, counted.
# A sweep made from its sections' lines and run quietly, one case at a time
# (test_sweep_warnings_table, test_no_effect_drag_sweep), in the current
# directory:
#   sweep_config NAME MODEL GRID PARAMS: NAME.ini of MODEL, GRID and PARAMS its
#   [grid] and [params] lines ("key = values", ';' between);
#   sweep_quiet NAME [FLAGS]: NAME.ini swept into NAME.out (--jobs 1 --quiet,
#   120 s of CPU), stderr in NAME.err; sets rc;
#   sweep_dashpot_config NAME [DAMPING]: NAME.ini of the chain sweep whose sensor
#   dashpot has no effect in 2 of 4 cases: n = 1, 3 by sensor-damping =
#   DAMPING (1e-12), 10 on a 1e-2 kg, 1e7 N/m sensor body at 0.3 m/s.
# A layer sweep of 2 x 3 cases (test_layer_sweep, test_hostile_sweeps):
#   layer_grid_ini FILE SAMPLE TMAX [LINE]: FILE of the layer model, rb-rm =
#   0.8, 1.5 by point = 0:2 (3 points at x = 0.1 m, 0.07 m apart) on SAMPLE to
#   t-max TMAX, and LINE last in [params] when given.
# A command's --json read back (test_wave_speed_dt_out, test_hostile_fortyeighth):
#   json_fields FILE FMT KEY...: the top-level KEYs of FILE's JSON object on one
#   line, blank-separated, each as Python's FMT % value ("%.0f", "%r"), "null"
#   for a null or a missing key;
#   json_warnings FILE [PREFIX]: the entries of its "warnings" that begin with
#   PREFIX (all when none is given), one line each.
# Background jobs of a script ignore SIGINT (bash sets it so): a run that is to
# see SIGINT is started under `env --default-signal=INT`.
fails=0; passes=0
ok() { echo "PASS: $1"; passes=$((passes+1)); }
ko() { echo "FAIL: $1"; fails=$((fails+1)); }

test_setup() {
    set -u
    case $1 in */*) GW=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") ;; *) GW=$1 ;; esac
    SRC=${2:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
}

# shim_path GIVEN NAME: the LD_PRELOAD library GIVEN (a test's argument), or
# the build's tests/libgw_NAME_shim.so beside GW, as an absolute path (tests
# cd into $tmp); status 1 when it is not there (not built here: SKIP)
shim_path() {
    local p=${1:-$(dirname "$GW")/tests/libgw_$2_shim.so}
    [ -f "$p" ] || return 1
    echo "$(cd "$(dirname "$p")" && pwd)/$(basename "$p")"
}

test_summary() {
    echo "${1:+$1: }$passes passed, $fails failed"
    [ "$fails" -eq 0 ]
}

journal_rows() {
    local n
    n=$(grep -vc '^#' "$1" 2>/dev/null)
    echo "${n:-0}"
}

# rows_once FILE: each case of FILE's rows at most once, their count printed
rows_once() {
    local n u
    n=$(journal_rows "$1")
    u=$(grep -v '^#' "$1" 2>/dev/null | cut -d, -f1 | sort -u | wc -l)
    echo "$n"
    [ "$n" -eq "$u" ]
}

wait_rows() {
    local end=$((SECONDS + ${3:-120}))
    while [ "$(journal_rows "$1")" -lt "$2" ]; do
        [ $SECONDS -lt $end ] || return 1
        sleep 0.01
    done
}

# cpu_ticks PID: user + system time of PID in clock ticks; fails when PID has
# ended (gone, or a zombie not yet waited for)
cpu_ticks() {
    local s
    s=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
    s=${s##*) }   # past "pid (comm) ": state is field 1, utime 12, stime 13
    set -- $s
    [ "$1" != Z ] || return 1
    echo $(( ${12} + ${13} ))
}

# running PID: PID has not ended (nor is a zombie); builtins only, no fork
running() {
    local s
    { read -r s <"/proc/$1/stat"; } 2>/dev/null && [[ $s != *") Z "* ]]
}

wait_file() {
    while running "$1"; do
        compgen -G "$2" >/dev/null && return 0
        sleep 0.001
    done
    return 1
}

wait_cpu() {
    local want t end=$((SECONDS + 300))
    want=$(awk -v s="$2" -v hz="$(getconf CLK_TCK)" 'BEGIN { printf "%d", s * hz + 0.5 }')
    while t=$(cpu_ticks "$1"); do
        [ "$t" -ge "$want" ] && return 0
        [ $SECONDS -lt $end ] || return 1
        sleep 0.01
    done
    return 1
}

# sanitizer_runtime: the AddressSanitizer runtime the program GW is linked
# against (ldd's path), or nothing: a preloaded shim in front of it is refused
# ("ASan runtime does not come first in initial library list"), so at_row
# preloads it first, the shim after it
sanitizer_runtime() {
    ldd "$GW" 2>/dev/null | awk '$1 ~ /^libasan\.so/ && $3 ~ /^\// {print $3; exit}'
}

# preload_list SHIM...: the LD_PRELOAD value that puts SHIMs in front of the
# program GW: the sanitizer's runtime first in a sanitizer build
preload_list() {
    local rt
    rt=$(sanitizer_runtime)
    echo "${rt:+$rt }$*"
}

at_row() {
    local k=$1 sh=$2 shim
    shift 2
    shim=$(shim_path "" move) || return 77
    GW_MOVE_AT=$k GW_MOVE_RUN="unset LD_PRELOAD GW_MOVE_AT GW_MOVE_RUN; $sh" LD_PRELOAD="$(preload_list "$shim")" "$@"
}

at_row_fn() {
    local k=$1 fn=$2 arg=$3
    shift 3
    { declare -f; declare -p tmp d journal_edit_py 2>/dev/null; } >"$tmp/at_row_fns.sh"
    at_row "$k" "bash -c '. \"\$0\"; $fn \"\$1\"' '$tmp/at_row_fns.sh' '$arg'" "$@"
}

cpu_run() {
    local secs=$1 wall=${CPU_RUN_WALL:-300}
    shift
    [ $((10 * secs)) -le "$wall" ] || wall=$((10 * secs))
    timeout -s KILL "$wall" bash -c 'ulimit -t "$0"; "$@" 2>&3 3>&-' "$secs" "$@" 3>&2 2>/dev/null
}

cpu_of() {
    ( "$@" >/dev/null 2>&1; times ) | tail -1 |
        awk '{ for (i = 1; i <= 2; i++) { split($i, a, "m"); t += a[1] * 60 + a[2] } } END { printf "%.3f\n", t }'
}

# stop_mid_sweep SIG DIR TOTAL CMD...: the caller asserts 1 <= rows < TOTAL and
# no DIR/results.csv (the signal landed mid-sweep). SIGKILL or SIGTERM to a
# sweep of the program: sent right before its second row (at_row), once. Else
# (SIGINT, mpirun, no shim) once its journal holds a row: a sweep that ended
# before the signal (rows = TOTAL, a table) is started again, three times at
# most; attempt says which one landed.
stop_mid_sweep() {
    local sig=$1 dir=$2 total=$3 pid
    shift 3
    # a signal other than SIGINT (which the sweep ignores while the shim's
    # command runs, as system(3) has it): sent by the sweep's own row (at_row),
    # mid-sweep on any machine; CMD a sweep, not mpirun (whose $PPID is not it)
    if [ "$sig" != INT ] && [ "$1" = "$GW" ]; then
        attempt=1
        rm -rf "$dir"
        at_row 2 "kill -$sig \$PPID" "$@" 2>/dev/null; rc=$?
        if [ $rc -ne 77 ]; then
            rows=$(journal_rows "$dir/journal.csv")
            [ ! -e "$dir/results.csv" ] && [ "$rows" -ge 1 ] && [ "$rows" -lt "$total" ]
            return
        fi
    fi
    for attempt in 1 2 3; do
        rm -rf "$dir"
        env --default-signal=INT "$@" & pid=$!
        wait_rows "$dir/journal.csv" 1
        kill -"$sig" $pid 2>/dev/null
        wait $pid 2>/dev/null; rc=$?
        rows=$(journal_rows "$dir/journal.csv")
        [ ! -e "$dir/results.csv" ] && [ "$rows" -ge 1 ] && [ "$rows" -lt "$total" ] && return 0
    done
    return 1
}

# sample_discs FILE: a layer sample's discs (the rows after its 'n' line, at
# most n, with 3 fields or a clump member's 4; the springs after them not
# read), as a first line "WIDTH RM N" and one "x y r" line each, the numbers
# as the file writes them (test_layer_make_column, _rest, _clump_column)
sample_discs() {
    awk 'NF == 0 || /^#/ { next }
         n == "" && $1 == "width" { w = $2 }
         n == "" && $1 == "rm" { rm = $2 }
         n == "" && $1 == "n" { n = $2; print w, rm, n; next }
         n != "" && $1 == "springs" { exit }
         n != "" && (NF == 3 || NF == 4) && k < n { print $1, $2, $3; k++ }' "$1"
}

# discs_outside FILE: "N ROWS OUT" of a layer sample: its n, its discs
# (sample_discs) and how many reach out of the box (its walls and floor) by
# more than 0.02 of their radius
discs_outside() {
    sample_discs "$1" | awk 'NR == 1 { w = $1; n = $3; next }
        { k++; if ($1 - $3 < -0.02 * $3 || $1 + $3 > w + 0.02 * $3 || $2 - $3 < -0.02 * $3) out++ }
        END { print n + 0, k + 0, out + 0 }'
}

# sweep_stopped WHAT RC ERR LINES PATTERN: a sweep stopped by a disturbance of
# its journal (test_hostile_sweeps38, 39): exit 1 and LINES lines on ERR (the
# block mpirun adds after them not counted), one matching PATTERN: one check
sweep_stopped() {
    local what=$1 rc=$2 err=$3 lines=$4 pattern=$5
    if [ "$rc" -eq 1 ] && [ "$(sed '/^-\{20,\}$/,$d' "$err" | wc -l)" -eq "$lines" ] && grep -q "$pattern" "$err"; then
        ok "$what: exit 1, one line: $(sed -n "${lines}p" "$err" | cut -c1-170)..."
    else
        ko "$what: journal disturbed mid-sweep: exit $rc: $(head -3 "$err")"
    fi
}

# kept_rows WHAT KEPT BEFORE TOTAL ERR: the journal the sweep kept aside
# (KEPT) holds each case once, more rows than BEFORE (the journal as it was
# disturbed) and fewer than TOTAL (no case handed out after), and the line on
# ERR counts them: one check, and a failure more when the line does not
kept_rows() {
    local what=$1 kept=$2 before=$3 total=$4 err=$5 n b
    b=$(journal_rows "$before")
    if n=$(rows_once "$kept") && [ "$n" -gt "$b" ] && [ "$n" -lt "$total" ]; then
        ok "$what: $(basename "$kept") holds $n rows, each case once, $b from before, no case handed out after"
    else
        ko "$what: the kept journal $kept: ${n:-none} rows ($b before)"
    fi
    grep -q "stopped taking cases after .*: $n of its $total cases are journaled there" "$err" ||
        ko "$what: the line does not count the $n kept rows"
}

# Edits of a sweep's journal DIR/journal.csv for at_row_fn, each leaving a copy
# of what it left in DIR.left (test_journal_window, test_hostile_sweeps39):
# journal_edit_row changes a digit of the first row in place, the file's length
# kept; journal_add_line appends a comment line; journal_cut cuts it to nothing.
# journal_held_writer DIR (started in the background before the sweep) opens
# the journal at once and makes journal_edit_row's edit through that one
# descriptor when journal_held_edit DIR (the at_row_fn function) asks, nothing
# else opening the file, which it holds open until DIR.end exists (60 s at
# most each wait).
journal_edit_py='import os, sys, time
def wait(f):
    for _ in range(1200):
        if os.path.exists(f):
            return
        time.sleep(0.05)
    sys.exit("no " + f)
d = sys.argv[2]
fd = os.open(d + "/journal.csv", os.O_RDWR)
if sys.argv[1] == "held":
    wait(d + ".go")
lines = os.pread(fd, 1 << 24, 0).split(b"\n")
for i, l in enumerate(lines):
    if l and not l.startswith(b"#"):
        j = l.index(b",") + 1
        lines[i] = l[:j] + (b"8" if l[j:j + 1] == b"7" else b"7") + l[j + 1:]
        break
os.pwrite(fd, b"\n".join(lines), 0)
with open(d + ".left", "wb") as f:
    f.write(os.pread(fd, 1 << 24, 0))
if sys.argv[1] == "held":
    open(d + ".done", "w").close()
    wait(d + ".end")
os.close(fd)'
journal_edit_row() { /usr/bin/python3 -c "$journal_edit_py" now "$1"; }
journal_held_writer() { /usr/bin/python3 -c "$journal_edit_py" held "$1"; }
journal_held_edit() {
    : >"$1.go"
    for _ in $(seq 1200); do [ -e "$1.done" ] && return 0; sleep 0.05; done
    return 1
}
sweep_config() {
    { echo "[sweep]"; echo "model = $2"; echo "[grid]"; tr ';' '\n' <<<"$3"
      echo "[params]"; tr ';' '\n' <<<"$4"; } >"$1.ini"
}

sweep_dashpot_config() {
    sweep_config "$1" chain "n = 1, 3;sensor-damping = ${2:-1e-12}, 10" \
        "sensor-mass = 1e-2;sensor-stiffness = 1e7;vimp = 0.3"
}

layer_grid_ini() {
    { printf '[sweep]\nmodel = layer\n[grid]\nrb-rm = 0.8, 1.5\npoint = 0:2\n[params]\nsample = %s\n' "$2"
      printf 'points = 3\nx = 0.1\nspacing = 0.07\nt-max = %s\n' "$3"
      [ -z "${4:-}" ] || echo "$4"; } >"$1"
}

sweep_quiet() {
    local name=$1
    shift
    cpu_run 120 "$GW" sweep "$name.ini" --out "$name.out" --jobs 1 --quiet "$@" >/dev/null 2>"$name.err"; rc=$?
}

journal_add_line() { echo "# a note" >>"$1/journal.csv"; cp "$1/journal.csv" "$1.left"; }
journal_cut() { : >"$1/journal.csv"; : >"$1.left"; }

json_fields() {
    /usr/bin/python3 - "$@" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
print(" ".join("null" if d.get(k) is None else sys.argv[2] % d[k] for k in sys.argv[3:]))
EOF
}

json_warnings() {
    /usr/bin/python3 - "$@" <<'EOF'
import json, sys
start = sys.argv[2] if len(sys.argv) > 2 else ""
for w in json.load(open(sys.argv[1]))["warnings"]:
    if w.startswith(start):
        print(w)
EOF
}
