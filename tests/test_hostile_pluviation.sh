#!/bin/bash
# test_hostile_pluviation.sh GRANWAVE SRCDIR: the thirteenth hostile pass, over
# `granwave layer-make` (the pluviation) and the samples it writes. Each check
# asserts behaviour (exit code, message, files, values); each failed on the
# binary before this pass unless marked "kept".
#  1 the default solver (rk4) made another sample at every --skin, a parameter
#    of the contact list only: --n 30 --t-max 0.4 gave four different files at
#    skins 0.01, 0.1, 1 and 1e6 m (the located rebuild roots put each skin on its
#    own time grid, and F_t of open contacts was zeroed only at stops). Now the
#    same particle lines at the four skins, for discs, frictionless discs, clumps
#    and a soft first phase; the runs rebuild the list 1 to 100 times, so the
#    rebuilds are exercised. verlet kept (made skin-independent in the eleventh
#    pass).
#  2 rk4 with a skin far below a step's motion (--skin 1e-6 m) ran more than
#    100 s for 0.4 s of 30 discs (a located rebuild root per particle and step);
#    now refused within seconds as verlet is (exit 2, nothing written, the skin
#    that would hold), and the suggested skin runs and gives the 0.1 m sample.
#  3 a --t-max that ends before the settling can be judged (the pile lands and
#    0.1 s pass) warned "E_k = 0 J still above --ke-threshold" (--t-max 1e-300:
#    false, the energy was below it); now the warning says that t-max ends
#    before the settling is judged and the JSON gives t_judge.
#  4 kept: pluviations run at once in threads (the Python module, which releases
#    the interpreter) give the samples the sequential runs give.
#  5 kept: a pluviation killed by SIGINT or SIGTERM leaves no sample and no
#    temporary behind. The signal lands after 1 s of the run's CPU (of about
#    6.4 s: past reading the options and placing the discs, in the settling)
#    and must stop it (exit 130, 143); it was sent 0.5 s of wall time in, which
#    under load could land before the run had started anything.
set -u
GW=$1
SRC=${2:-}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"

body() { grep -v '^#' "$1"; } # the particle lines and the header values, not the comments naming the skin

# 1 ----------------------------------------------------------------------------
skins="0.01 0.1 1 1e6"
same_at_skins() { # WHAT, then layer-make options
    local what=$1; shift
    local first="" diff=0 rb=""
    for s in $skins; do
        if ! "$GW" layer-make "$@" --skin "$s" --out "$tmp/s_$s.txt" --json >"$tmp/s_$s.json" 2>/dev/null; then
            ko "$what: layer-make --skin $s failed"; return
        fi
        rb="$rb $(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["rebuilds"])' "$tmp/s_$s.json")"
        if [ -z "$first" ]; then first=$s; elif ! cmp -s <(body "$tmp/s_$first.txt") <(body "$tmp/s_$s.txt"); then diff=1; fi
    done
    # the list is rebuilt more often at a smaller skin: the runs differ in their rebuilds, not in their samples
    set -- $rb
    if [ "$diff" -eq 0 ] && [ "$1" -gt "$4" ]; then
        ok "$what: the same sample at skins $skins (list rebuilds$rb)"
    else
        ko "$what: samples differ between skins ($diff) or rebuilds not exercised ($rb)"
    fi
}
same_at_skins "rk4 discs" --n 30 --t-max 0.4
same_at_skins "rk4 frictionless discs" --n 30 --t-max 0.4 --friction 0
same_at_skins "rk4 clumps" --clumps --n 12 --t-max 0.4
same_at_skins "rk4 soft phase (modulus-factor 0.01)" --n 30 --t-max 0.4 --modulus-factor 0.01
same_at_skins "kept: verlet discs" --n 30 --t-max 0.4 --solver verlet

# 2 ----------------------------------------------------------------------------
rm -f "$tmp/tiny.txt"
start=$(date +%s)
timeout -s KILL 60 "$GW" layer-make --n 30 --t-max 0.4 --skin 1e-6 --quiet --out "$tmp/tiny.txt" >"$tmp/stdout" 2>"$tmp/stderr"
rc=$? el=$(( $(date +%s) - start ))
sug=$(sed -n 's/.*raise --skin to \([0-9.e+-]*\) m or more.*/\1/p' "$tmp/stderr")
if [ $rc -eq 2 ] && [ "$el" -le 30 ] && [ ! -e "$tmp/tiny.txt" ] && [ "$(wc -l <"$tmp/stderr")" -eq 1 ] &&
   grep -q -- "--skin: 1e-06 m is too small" "$tmp/stderr" && [ -n "$sug" ]; then
    ok "rk4 --skin 1e-6: refused in ${el} s, nothing written, raise --skin to $sug"
else
    ko "rk4 --skin 1e-6: exit $rc after ${el} s ($(head -c 300 "$tmp/stderr"))"
fi
"$GW" layer-make --n 30 --t-max 0.4 --skin 0.1 --out "$tmp/ref.txt" >/dev/null 2>&1
if [ -n "$sug" ] && "$GW" layer-make --n 30 --t-max 0.4 --skin "$sug" --out "$tmp/sug.txt" >/dev/null 2>&1 &&
   cmp -s <(body "$tmp/sug.txt") <(body "$tmp/ref.txt"); then
    ok "rk4: the suggested skin $sug m runs and gives the 0.1 m skin's sample"
else
    ko "rk4: the suggested skin '$sug' does not run or gives another sample"
fi

# 3 ----------------------------------------------------------------------------
for tm in 1e-300 0.05; do
    rm -f "$tmp/u.txt"
    "$GW" layer-make --n 5 --t-max "$tm" --out "$tmp/u.txt" --quiet --json >"$tmp/u.json" 2>"$tmp/u.err"
    rc=$?
    if [ $rc -eq 0 ] && [ -s "$tmp/u.txt" ] && grep -q "converged 0" "$tmp/u.txt" && [ "$(wc -l <"$tmp/u.err")" -eq 1 ] &&
       grep -q "t-max = $tm s ends before the settling is judged" "$tmp/u.err" && ! grep -q "still above" "$tmp/u.err" &&
       /usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if d["converged"] is False and d["t_judge"] > float(sys.argv[2]) and d["t_judge"] >= 0.1 else 1)' "$tmp/u.json" "$tm"; then
        ok "--t-max $tm: exit 0, one warning that t-max ends before the settling is judged, t_judge in the JSON"
    else
        ko "--t-max $tm: exit $rc, warning '$(cat "$tmp/u.err")'"
    fi
done
# a t-max past the judge time that still does not settle keeps the energy warning
"$GW" layer-make --n 5 --t-max 0.3 --out "$tmp/u.txt" >/dev/null 2>"$tmp/u.err"
if [ $? -eq 0 ] && grep -q "still above --ke-threshold at t-max = 0.3 s" "$tmp/u.err"; then
    ok "kept: --t-max 0.3 unsettled: the energy warning"
else
    ko "--t-max 0.3 unsettled: '$(cat "$tmp/u.err")'"
fi

# 4 ----------------------------------------------------------------------------
lib=$(ls "$(dirname "$GW")"/lib/libgranwave.so* 2>/dev/null | head -1)
if [ -n "$lib" ] && ldd "$lib" 2>/dev/null | grep -q libasan; then
    lib="" # a sanitizer build's library cannot be loaded into Python without its runtime first
fi
if [ -n "$SRC" ] && [ -n "$lib" ] && /usr/bin/python3 -c 'import numpy' 2>/dev/null; then
    if GRANWAVE_LIB=$lib PYTHONPATH=$SRC/python timeout 300 /usr/bin/python3 - <<'PY'
import sys, threading
import numpy as np
import granwave
kw = dict(n=40, width_rm=16, t_max=0.3)
seeds = (1, 2, 3)
seq = [granwave.layer_make(seed=s, **kw) for s in seeds]
par = [None] * len(seeds)
def run(i, s):
    par[i] = granwave.layer_make(seed=s, **kw)
th = [threading.Thread(target=run, args=(i, s)) for i, s in enumerate(seeds)]
for t in th:
    t.start()
for t in th:
    t.join()
same = all(all(np.array_equal(a[k], b[k]) for k in ("x", "y", "r")) and a["ke_final"] == b["ke_final"]
           for a, b in zip(seq, par))
differ = not np.array_equal(seq[0]["x"], seq[1]["x"])
sys.exit(0 if same and differ else 1)
PY
    then ok "kept: three pluviations in threads give the sequential samples (and the seeds differ)"
    else ko "pluviations in threads differ from the sequential ones"
    fi
else
    echo "SKIP: threads (no /usr/bin/python3 with numpy, or no shared library next to $GW that Python can load)"
fi

# 5 ----------------------------------------------------------------------------
for sig in INT TERM; do
    mkdir -p "$tmp/k$sig"
    env --default-signal=INT "$GW" layer-make --n 300 --out "$tmp/k$sig/o.txt" >/dev/null 2>&1 & pid=$!
    wait_cpu $pid 1.0; kill -$sig $pid 2>/dev/null; wait $pid 2>/dev/null; rc=$?
    want=$([ $sig = INT ] && echo 130 || echo 143)
    if [ $rc -ne "$want" ]; then
        ko "layer-make sent SIG$sig after 1 s of CPU: exit $rc, not stopped by it ($want)"
    elif [ -z "$(ls -A "$tmp/k$sig")" ]; then
        ok "kept: layer-make stopped by SIG$sig mid-run (exit $rc) leaves nothing in the --out directory"
    else
        ko "layer-make stopped by SIG$sig left: $(ls -A "$tmp/k$sig" | tr '\n' ' ')"
    fi
done

# --- a sample saved with a UTF-8 byte-order mark (an editor's "save as UTF-8")
# was refused as "not a granwave layer sample"; it reads as the same sample
"$GW" layer-make --n 30 --out "$tmp/b0.txt" >/dev/null 2>&1 || ko "layer-make for the byte-order-mark check"
{ printf '\xEF\xBB\xBF'; cat "$tmp/b0.txt"; } >"$tmp/bom.txt"
"$GW" layer-impact --sample "$tmp/b0.txt" --vi 5 --t-max 0.01 --json 2>/dev/null | grep -v '"sample\|wall_time' >"$tmp/b0.json"
"$GW" layer-impact --sample "$tmp/bom.txt" --vi 5 --t-max 0.01 --json 2>"$tmp/stderr" | grep -v '"sample\|wall_time' >"$tmp/b1.json"
if [ -s "$tmp/b0.json" ] && cmp -s "$tmp/b0.json" "$tmp/b1.json"; then
    ok "a sample with a byte-order mark reads as the same sample (the same JSON but its name, hash and wall time)"
else
    ko "a sample with a byte-order mark: $(head -c 300 "$tmp/stderr")"
fi

echo "test_hostile_pluviation: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
