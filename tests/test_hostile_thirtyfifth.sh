#!/bin/bash
# test_hostile_thirtyfifth.sh GRANWAVE SRCDIR: what the thirty-fifth hostile
# pass found, fixed at its root and asserted here.
#  1 A pile written before it settled. layer-make writes a pile cut by its
#    t-max with 'converged 0' in its settled line and one warning, and exits 0;
#    layer-impact, sweeps and Python then ran on that file with exit 0 and
#    nothing said. The file keeps positions, not velocities: the run starts the
#    pile at rest where it was moving, grains in the air among them (the 8-disc
#    pile below, cut at 0.2 s, is wholly in the air: floor load 0). The default
#    impact gave e_n 0.258 against 0.083 on the same pile settled, penetration
#    0.227 m against 0.013 (the 40-disc pile of seed 1 cut at 0.3 s: e_n 0.476
#    against 0.149, penetration 0.625 m). It now warns (a warning, as
#    layer-make's own exit is 0): stderr, impact.json's warnings, the CSV
#    headers, a sweep's settling_warning column (counted by the check pass and
#    by layer-stats), Python's GranwaveWarning; text and HDF5 samples, the
#    program's and the library's settled lines.
#  2 Impact points at one block position. A layer sweep with points > 1 and
#    spacing = 0 ran the same impact once per point, and layer-stats counted
#    them as that many points (n 4, spreads 0.000); so did a spacing below the
#    rounding of the block's position (1e-300 m). Refused by sweep, sweep
#    --check and Python's sweep, naming spacing, nothing written.
#  3 layer-stats took a settling_warning cell of 7, 0.5 or nan (a sweep writes
#    0 or 1) and counted the row as without warning; refused, as bounced is.
#  4 The sphere mass law with union clumps (layer-impact --mass-law sphere on a
#    sample of union clumps, layer-make with both) was refused without naming
#    an option ("clump mass 'union' needs the disc mass law ..."), in Python
#    too; it now names --mass-law (Python: mass_law).
#  5 layer-stats' warnings (rows on such a pile among them) were on stderr
#    alone: its --json and boundary_fit.json now list them ("warnings"), as
#    Python's result and layer-impact's JSON do.
#  6 A sweep writes settled_load_ratio inf for a case without gravity (q =
#    W_settled / W_impact; other-settling on a pile touching no floor), and
#    layer-stats refused that table: "'inf' is not a value a sweep writes".
#  7 A chain sweep said nothing of cases that did not end (held on the wall
#    by gravity: a row of nan; cut at t-max: the values there), where cli.md
#    says chain sweeps warn and `granwave chain` warns of each; Python's sweep
#    issued none of the sweep's warnings (a dt above the step taken, layer
#    cases on a sample settled otherwise or not settled, these). One line now
#    counts such cases, and Python issues every line as a GranwaveWarning.
#  8 (left by the pass, closed by the lead) falcon, wavespeed and softwall
#    listed --radii in their help as "per-bead radii, m" and refused it with
#    "per-bead radii need a fixed N", also at --n 3:3: their help now says a
#    study does not take it, and the refusal (exit 2, one line, nothing
#    written) says why and names granwave chain.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

h5=0
"$GW" version --json | grep -q '"hdf5":[[:space:]]*"' && h5=1

# --- 1 a pile written before it settled ---
# the same 8 discs settled (2.74 s) and cut at t-max 0.2 s (in the air)
"$GW" layer-make --n 8 --width-rm 6 --seed 1 --out settled.txt >/dev/null 2>&1
"$GW" layer-make --n 8 --width-rm 6 --seed 1 --t-max 0.2 --out cut.txt >/dev/null 2>&1
grep -q 'converged 1' settled.txt && grep -q 'converged 0' cut.txt ||
    ko "set-up: layer-make's piles are not as expected ($(grep -h '# settled' settled.txt cut.txt | cut -c1-60))"
[ $h5 = 1 ] && "$GW" layer-make --n 8 --width-rm 6 --seed 1 --t-max 0.2 --out cut.h5 >/dev/null 2>&1

WARN='the sample did not settle \(its settled line says converged 0'
# unsettled NAME FILE: layer-impact on FILE runs (exit 0), says it once on
# stderr, and records it in --json's and impact.json's warnings and in the
# ledger's header
unsettled() {
    rm -rf o
    timeout -s KILL 60 "$GW" layer-impact --sample "$2" --json --out o >i.json 2>"$tmp/stderr" </dev/null
    local rc=$? n
    n=$(grep -cE "^granwave layer-impact: warning: $WARN" "$tmp/stderr")
    if [ $rc -eq 0 ] && [ "$n" -eq 1 ] &&
        [ "$(jq_py i.json "sum('did not settle' in w for w in d['warnings'])")" = 1 ] &&
        [ "$(jq_py o/impact.json "sum('did not settle' in w for w in d['warnings'])")" = 1 ] &&
        grep -q '^#.*warning: the sample did not settle' o/ledger.csv; then
        ok "$1: runs with one warning that the pile did not settle (stderr, --json, impact.json, ledger.csv)"
    else
        ko "$1: exit $rc, $n warning lines, warnings $(jq_py i.json "d['warnings']" 2>/dev/null | head -c 200)"
    fi
}
unsettled "layer-impact on a pile cut at t-max 0.2 s (text)" cut.txt
if [ $h5 = 1 ]; then
    unsettled "layer-impact on a pile cut at t-max 0.2 s (HDF5)" cut.h5
else
    echo "SKIP: HDF5 (this build has none)"
fi

# the pile settled: nothing said, and the same pile's numbers as before
if runs_json "layer-impact on the settled pile" s.json layer-impact --sample settled.txt --quiet; then  # (warnings kept)
    [ ! -s "$tmp/stderr" ] && [ "$(jq_py s.json "d['warnings'] == []")" = True ] &&
        ok "layer-impact on the settled pile: no warning" || ko "layer-impact on the settled pile: $(head -c 300 "$tmp/stderr")"
fi

# with another material too: both said, in one warning line
timeout -s KILL 60 "$GW" layer-impact --sample cut.txt --density 2500 --quiet --json >i.json 2>"$tmp/stderr" </dev/null
rc=$?
# (the run's other lines, such as the crowns' since session 46, are not the settling's)
[ $rc -eq 0 ] && [ "$(grep -c "settled" "$tmp/stderr")" -eq 1 ] &&
    grep -qE "warning: the sample settled with density 2650 .*; $WARN" "$tmp/stderr" &&
    ok "layer-impact on the cut pile at density 2500: one warning line with the material and the settling" ||
    ko "layer-impact on the cut pile at density 2500: exit $rc, $(cat "$tmp/stderr")"

# a sweep: the check pass counts the cases, each row says settling_warning 1
# (0 on the settled pile), and layer-stats counts them
printf '[sweep]\nmodel = layer\nout = sw\n[grid]\nsample = cut.txt, settled.txt\npoint = 0:1\n[params]\npoints = 2\nspacing = 0.3\nvi = 5\nt-max = 0.01\n' >sw.ini
timeout -s KILL 120 "$GW" sweep sw.ini --quiet >/dev/null 2>"$tmp/stderr" </dev/null
rc=$?
col=$(/usr/bin/python3 -c "
import csv
rows = list(csv.DictReader(l for l in open('sw/results.csv') if not l.startswith('#')))
print(' '.join(r['settling_warning'] for r in rows))" 2>/dev/null)
[ $rc -eq 0 ] && [ "$col" = "1 1 0 0" ] &&
    grep -q "warning: 2 of 4 cases run on a sample settled under another material or not settled" "$tmp/stderr" &&
    ok "sweep over the cut and the settled pile: settling_warning 1 1 0 0, the check pass counts 2 of 4" ||
    ko "sweep over the cut and the settled pile: exit $rc, settling_warning '$col', $(head -c 300 "$tmp/stderr")"
timeout -s KILL 60 "$GW" layer-stats sw/results.csv --json --out st >st.json 2>"$tmp/stderr" </dev/null
rc=$?
# (since session 46 the sweep's own line, repeated, says it once: not layer-stats' line beside it)
[ $rc -eq 0 ] && grep -q "warning: .*2 of 4 cases run on a sample settled under another material or not settled" \
    "$tmp/stderr" && ! grep -q "rows ran on a sample" "$tmp/stderr" &&
    ok "layer-stats counts the 2 rows on the cut pile" || ko "layer-stats: exit $rc, $(head -c 300 "$tmp/stderr")"
# its warnings in --json and boundary_fit.json, as Python's result and
# layer-impact's JSON carry theirs (they were on stderr alone)
if [ $rc -eq 0 ]; then
    /usr/bin/python3 - "$tmp/stderr" >chk.txt 2>&1 <<'EOF'
import json, sys
said = [l.split(": warning: ", 1)[1].rstrip("\n") for l in open(sys.argv[1]) if ": warning: " in l]
j, b = json.load(open("st.json")), json.load(open("st/boundary_fit.json"))
print(len(said) >= 2 and j.get("warnings") == said and b.get("warnings") == said)
EOF
    [ "$(cat chk.txt)" = True ] && ok "layer-stats --json and boundary_fit.json list the warnings stderr gives" ||
        ko "layer-stats --json and boundary_fit.json: warnings $(jq_py st.json "d.get('warnings')" | head -c 200)"
fi

# Python: the program's file, and one the library writes (layer_make out=)
py_checks <<'EOF'
import warnings, granwave
for f in ("cut.txt", "lib_cut.txt"):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        if f == "lib_cut.txt":
            granwave.layer_make(n=8, width_rm=6, seed=1, t_max=0.2, out=f)
            w.clear()
        r = granwave.layer_impact(sample=f)
    said = [str(x.message) for x in w if x.category is granwave.GranwaveWarning and "did not settle" in str(x.message)]
    ok = len(said) == 1 and sum("did not settle" in t for t in r["warnings"]) == 1
    print(("PASS: " if ok else "FAIL: ") + "Python layer_impact on %s: one GranwaveWarning that the pile did not "
          "settle, in the result's warnings too (%d)" % (f, len(said)))
EOF

# --- 2 impact points at one block position ---
for sp in 0 1e-300; do
    printf '[sweep]\nmodel = layer\nout = o\n[grid]\npoint = 0:3\n[params]\nsample = settled.txt\npoints = 4\nspacing = %s\nvi = 5\nt-max = 0.01\n' "$sp" >p.ini
    refused "sweep --check, spacing $sp with 4 points: refused naming spacing" \
        "^granwave sweep: p.ini: case 0: spacing: $sp m puts impact points 0 and 1 of 4 at one block position" sweep p.ini --check
    refused "sweep, spacing $sp with 4 points: refused naming spacing, nothing written" \
        "^granwave sweep: p.ini: case 0: spacing: $sp m puts impact points 0 and 1 of 4 at one block position" sweep p.ini --quiet
done
# points that do move the block still run
printf '[sweep]\nmodel = layer\nout = o\n[grid]\npoint = 0:3\n[params]\nsample = settled.txt\npoints = 4\nspacing = 1e-6\nvi = 5\nt-max = 0.01\n' >p.ini
rm -rf o # a journal the code before wrote there would be another sweep's
timeout -s KILL 60 "$GW" sweep p.ini --check >/dev/null 2>&1 </dev/null && ok "sweep --check, spacing 1e-6 with 4 points: valid" ||
    ko "sweep --check, spacing 1e-6 with 4 points: exit $?"
py_checks <<'EOF'
import granwave
try:
    granwave.sweep(model="layer", grid={"point": "0:3"}, sample="settled.txt", points=4, spacing=0, vi=5, t_max=0.01)
    print("FAIL: Python sweep with spacing 0 over 4 points ran")
except granwave.GranwaveValueError as e:
    print(("PASS: " if "spacing" in str(e) else "FAIL: ") + "Python sweep, spacing 0 over 4 points: "
          "GranwaveValueError naming spacing (%s)" % str(e)[:80])
EOF

# --- 3 layer-stats: settling_warning is 0 or 1 ---
if [ -f sw/results.csv ]; then
    for v in 7 0.5 nan; do
        /usr/bin/python3 - "$v" <<'EOF'
import sys
lines = open("sw/results.csv").read().split("\n")
h = next(i for i, l in enumerate(lines) if l.startswith("case,"))
k = lines[h].split(",").index("settling_warning")
row = lines[h + 1].split(",")
row[k] = sys.argv[1]
lines[h + 1] = ",".join(row)
open("edited.csv", "w").write("\n".join(lines))
EOF
        refused "layer-stats: a settling_warning of $v refused naming the column" \
            "^granwave layer-stats: edited.csv:[0-9]+: column settling_warning: '$v' is not 0 or 1" layer-stats edited.csv --out o
    done
fi

# --- 4 the sphere mass law with union clumps: refused naming the option ---
"$GW" layer-make --clumps --n 6 --width-rm 12 --clump-mass union --t-max 0.2 --out union.txt >/dev/null 2>&1
refused "layer-impact --mass-law sphere on a sample of union clumps: refused naming --mass-law" \
    "^granwave layer-impact --mass-law: sphere with clump mass 'union'" layer-impact --sample union.txt --mass-law sphere --out o
refused "layer-make --clumps --mass-law sphere --clump-mass union: refused naming --mass-law" \
    "^granwave layer-make --mass-law: sphere with clump mass 'union'" layer-make --clumps --n 3 --mass-law sphere --clump-mass union --out o
py_checks <<'EOF'
import granwave
try:
    granwave.layer_impact(sample="union.txt", mass_law="sphere")
    print("FAIL: Python layer_impact mass_law='sphere' on union clumps ran")
except granwave.GranwaveValueError as e:
    print(("PASS: " if str(e).startswith("layer_impact: mass_law: ") else "FAIL: ") + "Python layer_impact "
          "mass_law='sphere' on union clumps: GranwaveValueError naming mass_law (%s)" % str(e)[:70])
EOF

# --- 6 a table whose settled_load_ratio is inf, as a sweep writes it ---
# the cut pile touches nothing (floor load 0): hit without gravity, with
# other-settling, it runs, q = W_settled / W_impact = inf, and the sweep writes
# 'inf' into its table, which layer-stats refused as no value a sweep writes
printf '[sweep]\nmodel = layer\nout = g0\n[grid]\nvi = 5, 6\n[params]\nsample = cut.txt\ngravity = 0\nother-settling = 1\nt-max = 0.01\n' >g0.ini
timeout -s KILL 120 "$GW" sweep g0.ini --quiet >/dev/null 2>&1 </dev/null
rc=$?
# (the rows end with slump_ke and crowns_nulled since session 46)
if [ $rc -eq 0 ] && grep -q ',inf,1,0,nan,[0-9]*,[0-9a-f]*,[0-9a-f]*$' g0/results.csv; then
    timeout -s KILL 60 "$GW" layer-stats g0/results.csv --json >g0.json 2>"$tmp/stderr" </dev/null
    rc=$?
    [ $rc -eq 0 ] && grep -q "2 of 2 cases run on a sample settled" "$tmp/stderr" &&
        ok "layer-stats reads the sweep's table of q = inf (no gravity) and counts its rows" ||
        ko "layer-stats on the sweep's table of q = inf: exit $rc, $(head -c 300 "$tmp/stderr")"
    sed 's/,inf,1,0,\(nan,[0-9]*,[0-9a-f]*,[0-9a-f]*\)$/,-inf,1,0,\1/' g0/results.csv >neg.csv
    refused "layer-stats: a settled_load_ratio of -inf still refused" \
        "^granwave layer-stats: neg.csv:[0-9]+: column settled_load_ratio: '-inf' is not a value a sweep writes" layer-stats neg.csv --out o
else
    ko "a sweep without gravity on the cut pile (other-settling): exit $rc, rows $(grep -vc '^#' g0/results.csv 2>/dev/null)"
fi

# --- 7 a sweep's warnings: chain cases that did not end, Python's sweep ---
# held on the wall by gravity (its row nan) or cut at t-max (its values those
# at t-max): the row says converged 0, and the sweep now says so in one line
printf '[sweep]\nmodel = chain\nout = ch\n[grid]\nn = 6:7\n[params]\nt-max = 1.94e-4\n' >ch.ini
timeout -s KILL 60 "$GW" sweep ch.ini --quiet >/dev/null 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc -eq 0 ] && [ "$(grep -c warning "$tmp/stderr")" -eq 1 ] &&
    grep -q "^granwave sweep: warning: 1 of 2 cases did not end their collision (column converged = 0; the first, case 1)" "$tmp/stderr" &&
    [ "$(awk -F, '/^#/ { next } !c { for (i = 1; i <= NF; i++) if ($i == "converged") c = i; next }
                   $1 == 1 && $2 == 7 { print $c }' ch/results.csv)" = 0 ] &&
    ok "chain sweep with n 7 cut at t-max: one warning line, 1 of 2 cases (case 1, converged 0 in its row)" ||
    ko "chain sweep with n 7 cut at t-max: exit $rc, $(head -c 300 "$tmp/stderr")"
printf '[sweep]\nmodel = chain\nout = hd\n[grid]\nn = 2:3\n[params]\ngravity = 1e3\nvimp = 0.01\n' >hd.ini
timeout -s KILL 60 "$GW" sweep hd.ini --quiet >/dev/null 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc -eq 0 ] && grep -q "^granwave sweep: warning: 2 of 2 cases did not end their collision" "$tmp/stderr" &&
    ok "chain sweep of columns gravity holds on the wall: the warning cli.md promises, 2 of 2" ||
    ko "chain sweep of held columns: exit $rc, $(head -c 300 "$tmp/stderr")"
printf '[sweep]\nmodel = chain\nout = cl\n[grid]\nn = 1:2\n' >cl.ini
timeout -s KILL 60 "$GW" sweep cl.ini --quiet >/dev/null 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc -eq 0 ] && [ ! -s "$tmp/stderr" ] && ok "chain sweep whose cases end: no warning" ||
    ko "chain sweep whose cases end: exit $rc, $(head -c 300 "$tmp/stderr")"
# Python's sweep: the lines the program prints, as GranwaveWarning and in the
# result's warnings (it issued none: not the dt, the settling, nor these)
py_checks <<'EOF'
import warnings, granwave
def said(**kw):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = granwave.sweep(jobs=1, **kw)
    return [str(x.message) for x in w if x.category is granwave.GranwaveWarning], r
for what, kw, text in (
        ("chain cases held by gravity", dict(model="chain", grid={"n": [2, 3]}, gravity=1e3, vimp=0.01),
         "sweep: 2 of 2 cases did not end their collision"),
        ("a chain dt above the step taken", dict(model="chain", grid={"n": [2, 3]}, dt=1e-3),
         "sweep: dt 0.001 s is above the longest step that 2 of 2 cases take"),
        ("layer cases on the cut pile", dict(model="layer", grid={"point": "0:1"}, sample="cut.txt", points=2,
                                             spacing=0.3, vi=5, t_max=0.01),
         "sweep: 2 of 2 cases run on a sample settled under another material or not settled")):
    got, r = said(**kw)
    # (the settling's line once; a layer case cut inside its first impact also
    # says its crowns were cut, since session 46: another line)
    mine = [g for g in got if g.startswith(text)]
    ok = (len(mine) == 1 and len(got) == len(r.get("warnings", [])) and
          [g[len("sweep: "):] for g in got] == r.get("warnings"))
    print(("PASS: " if ok else "FAIL: ") + "Python sweep, %s: one GranwaveWarning and the result's warnings (%s)"
          % (what, got[:1]))
got, r = said(model="chain", grid={"n": [1, 2]})
print(("PASS: " if not got and r.get("warnings") == [] else "FAIL: ") + "Python sweep whose cases end: no warning, an empty list of warnings")
EOF

# 8: --radii in the studies
for cmd in falcon wavespeed softwall; do
    if "$GW" "$cmd" --help 2>&1 | grep -E -- '^  --radii ' | grep -q 'not taken by a study'; then
        ok "$cmd --help: --radii said not taken by a study"
    else
        ko "$cmd --help: $("$GW" "$cmd" --help 2>&1 | grep -E -- '^  --radii ')"
    fi
    refused "$cmd --n 3:3 --radii: refused, saying why" \
        "^granwave $cmd --radii: a study runs columns of several sizes N .* use granwave chain\$" \
        "$cmd" --n 3:3 --radii 4e-3,4e-3,4e-3 --out "$tmp/o"
done

test_summary test_hostile_thirtyfifth
