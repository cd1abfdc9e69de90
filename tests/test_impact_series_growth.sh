#!/bin/bash
# test_impact_series_growth.sh GRANWAVE SRCDIR: a layer impact's series grow as
# the run goes (layer_impact.c series_room), where they were reserved whole up
# front, ceil(t_max / dt_out) + 2 samples: on the 40-disc pile of `layer-make
# --n 40`, `layer-impact --gravity 0.5 --other-settling --t-max 40` reserved
# 2,000,002 samples (0.98 GB of address space at 12 rings) for a run that
# stops at 2.6 s (130,323 samples, max RSS 113 MB), and under ulimit -v 800000
# failed with "out of memory for 2000002 samples" (exit 1).
#  1 Under ulimit -v 800000 the run exits 0, its --json the unlimited run's
#    (wall_time_ms aside), and with --out its ledger.csv and crowns.csv the
#    unlimited run's, byte for byte.
#  2 The samples kept across the growths (the rings' four series moved up in
#    their one block at each): the first 4001 samples of ledger.csv and
#    crowns.csv (t <= 0.08 s) are those of the same run to --t-max 0.08, whose
#    4002 samples never grow; the last ledger row is at t_end.
#  3 A run whose series do not fit (--full --t-max 10, 500,002 samples, 244
#    MB, under ulimit -v 200000) still fails cleanly: exit 1, "out of memory"
#    on one line that names the command once (it said "granwave layer-impact:
#    layer-impact: out of memory" before), nothing on stdout and no ledger.csv or impact.json in --out (before: at
#    the start; now at the growth that does not fit).
# The memory-limited runs are skipped in a sanitizer build (its shadow memory
# lies beyond any ulimit -v). Checks that fail on the code before: see
# docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "$0")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
PY=/usr/bin/python3

cpu_run 120 "$GW" layer-make --n 40 --out s40 --quiet >/dev/null 2>&1 ||
    { ko "layer-make --n 40 (the pile the checks impact)"; test_summary test_impact_series_growth; exit; }

BASE=(layer-impact --sample s40 --gravity 0.5 --other-settling --quiet)
CASE=("${BASE[@]}" --t-max 40)
# norm FILE: the JSON of FILE without wall_time_ms, keys sorted
norm() { $PY -c "import json,sys; d=json.load(open(sys.argv[1])); d.pop('wall_time_ms',None); print(json.dumps(d,sort_keys=True))" "$1"; }

# the unlimited run, the reference (json on stdout, files in full/)
if cpu_run 120 "$GW" "${CASE[@]}" --json --out full >full.json 2>full.err; then
    ok "the case runs unlimited"
else
    ko "the case unlimited: exit $? ($(head -c 300 full.err))"
    test_summary test_impact_series_growth
    exit
fi
tend=$($PY -c "import json; print(repr(json.load(open('full.json'))['t_end']))")
rows=$(($(grep -vc '^#' full/ledger.csv) - 1))
# 2.6 s of 2e-5 s samples, far beyond the first room of 4096: the series grew
[ "$rows" -gt 100000 ] && [ "$rows" -lt 200000 ] && ok "the run took $rows samples (t_end $tend s)" ||
    ko "the run took $rows samples (t_end $tend s), expected 1e5 to 2e5"

# 2: the samples kept across the growths
if cpu_run 60 "$GW" "${BASE[@]}" --t-max 0.08 --out short >/dev/null 2>short.err; then
    for f in ledger.csv crowns.csv; do
        n=$(wc -l <"short/$f")
        if [ "$n" -gt 4000 ] && cmp -s <(sed -n "2,${n}p" "short/$f") <(sed -n "2,${n}p" "full/$f"); then
            ok "$f: the long run's rows to t = 0.08 s (grown 5 times) are the short run's (never grown)"
        else
            ko "$f: the long run's first rows differ from the run to --t-max 0.08 (or it has $n lines)"
        fi
    done
else
    ko "the case to --t-max 0.08: exit $? ($(head -c 300 short.err))"
fi
last=$(tail -1 full/ledger.csv | cut -d, -f1)
$PY -c "import sys; sys.exit(0 if abs(float('$last') - $tend) <= 1e-12 else 1)" &&
    ok "the last ledger row is at t_end ($last s)" || ko "the last ledger row is at $last s, t_end $tend s"

if sanitizer_build; then
    echo "SKIP: the memory-limited runs (a sanitizer build reserves its shadow memory beyond any ulimit -v)"
    test_summary test_impact_series_growth
    exit
fi
# limKB.sh ARGS...: the program under ulimit -v KB
for kb in 800000 200000; do
    printf '#!/bin/bash\nulimit -v %s || exit 9\nexec "%s" "$@"\n' "$kb" "$GW" >"lim$kb.sh"
    chmod +x "lim$kb.sh"
done

# 1: under ulimit -v 800000
if cpu_run 120 ./lim800000.sh "${CASE[@]}" --json >lim.json 2>lim.err; then
    [ "$(norm lim.json)" = "$(norm full.json)" ] && ok "under ulimit -v 800000: exit 0, the unlimited run's --json" ||
        ko "under ulimit -v 800000: exit 0 but its --json differs from the unlimited run's"
else
    ko "under ulimit -v 800000: exit $? ($(head -c 300 lim.err))"
fi
if cpu_run 120 ./lim800000.sh "${CASE[@]}" --json --out limo >limo.json 2>limo.err; then
    for f in ledger.csv crowns.csv; do
        cmp -s "limo/$f" <(sed "1s/--out full/--out limo/" "full/$f") &&
            ok "under ulimit -v 800000 with --out: $f is the unlimited run's" ||
            ko "under ulimit -v 800000 with --out: $f differs from the unlimited run's"
    done
else
    rc=$?
    for f in ledger.csv crowns.csv; do
        ko "under ulimit -v 800000 with --out, $f: exit $rc ($(head -c 300 limo.err))"
    done
fi

# 3: series that do not fit fail cleanly, at the growth
rm -rf nofit
cpu_run 120 ./lim200000.sh "${BASE[@]}" --t-max 10 --full --json --out nofit >nofit.json 2>nofit.err
rc=$?
if [ $rc -eq 1 ] && grep -q "^granwave layer-impact: out of memory" nofit.err &&
    ! grep -q "layer-impact: layer-impact" nofit.err && [ ! -s nofit.json ] &&
    [ ! -e nofit/ledger.csv ] && [ ! -e nofit/impact.json ]; then
    ok "500,002 samples under ulimit -v 200000: exit 1, out of memory said once, no results written"
else
    ko "500,002 samples under ulimit -v 200000: exit $rc ($(head -c 300 nofit.err); $(ls nofit 2>/dev/null | tr '\n' ' '))"
fi

test_summary test_impact_series_growth
