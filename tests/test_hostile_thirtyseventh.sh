#!/bin/bash
# test_hostile_thirtyseventh.sh GRANWAVE SRCDIR: what the thirty-seventh hostile
# pass found, fixed at its root and asserted here.
#  1 A study's one-bead column undamped among damped ones. falcon, wavespeed
#    and softwall over sizes from 1 with kk or hc damping on a sheet's layer,
#    plastic or viscoelastic wall ran with exit 0: kk and hc leave such a wall
#    to its own law, so the one-bead column ran undamped while the others were
#    damped (single chain --n 1 with that is refused naming --damping since the
#    thirty-sixth pass: chain_damping_check). The studies now apply the same
#    rule to their smallest column (each wall of softwall --sheets): refused
#    naming --damping, nothing written, in the program and in Python; sizes
#    from 2, or a Hertz sheet, still run.
#  2 A standard descriptor closed by the caller. With 2>&- (and >&-) the first
#    file a run opened took descriptor 2: a sweep's journal took its progress
#    lines ("sweep: 3 cases, 0 already done, ..."), and the next run of that
#    sweep refused the journal as edited by hand (exit 2). Each closed standard
#    descriptor is now held by /dev/null opened read-only: the journal holds
#    its rows alone, and a lost stdout still ends the run with exit 1.
#  3 One pile under two names through zero-springs. A case under zero-springs
#    reads no springs, so a sample run so and its copy without the springs
#    section run the same impact; the sweep's check (which refuses one pile
#    under two names) hashed the springs anyway: such a grid ran every impact
#    twice with exit 0, and layer-stats refused its table. Refused naming both
#    files by sweep, sweep --check and Python's sweep; the same sample over
#    zero-springs = 0, 1 still runs.
#  4 softwall --sheets --restitution: nine walls, one constant, calibrated on
#    the bare sensor; kk then rebounds at 0.48 to 0.94 on the sheets for
#    E = 0.5, where the help promised "one bead on the wall rebounds with E".
#    The help now says so; the constant is the bare sensor's (chain's
#    calibration on the default wall at the study's speed).
#  5 layer-impact --x 1.2999999 (a block that does not fit in the box) was
#    refused "at x = 1.3 m", a value the user did not give (the thirty-sixth
#    pass's rounding onto a bound, in a message it did not reach), and
#    --rb-rm 4.0000001 on a box 8 R_m wide "a block of radius 4 R_m"; now
#    shown as given, in the program and a sweep's check.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 a study's one-bead column on a sheet that the damping leaves alone ---
STUDY='^granwave (falcon|wavespeed|softwall) --damping: has no effect on the study.s one-bead column \(n from 1\)'
refused "falcon --n 1:3 --damping kk on a brass layer: refused naming --damping, nothing written" \
    "$STUDY" falcon --n 1:3 --damping kk --gamma 1e5 --sheet brass --sheet-law layer --out o
refused "falcon --n 1:3 --damping hc --restitution 0.5 on brass under sheet-law material: refused" \
    "$STUDY" falcon --n 1:3 --damping hc --restitution 0.5 --sheet brass --sheet-law material --out o
refused "wavespeed --n 1:8 --damping kk on a brass layer: refused" \
    "$STUDY" wavespeed --n 1:8 --damping kk --gamma 1e5 --sheet brass --sheet-law layer --out o
refused "softwall --n 1:3 --damping kk on a brass layer: refused" \
    "$STUDY" softwall --n 1:3 --damping kk --gamma 1e5 --sheet brass --sheet-law layer --out o
refused "softwall --n 1:3 --sheets --sheet-law material --damping kk: refused naming the first such sheet" \
    "$STUDY against sheet brass" softwall --n 1:3 --sheets --sheet-law material --damping kk --gamma 1e5 --out o
# where every column has something to damp: still run
for args in "falcon --n 2:3 --damping kk --gamma 1e5 --sheet brass --sheet-law layer" \
    "softwall --n 1:3 --damping kk --gamma 1e5 --sheet brass --sheet-law hertz"; do
    # shellcheck disable=SC2086
    timeout -s KILL 60 "$GW" $args --quiet >/dev/null 2>"$tmp/stderr" </dev/null &&
        ok "$args: runs" || ko "$args: exit $? ($(head -c 200 "$tmp/stderr"))"
done
py_checks <<'EOF'
for fn, n in ((granwave.falcon, "1:3"), (granwave.wavespeed, "1:8"), (granwave.softwall, "1:3")):
    refused("Python %s n=%r damping='kk' on a brass layer" % (fn.__name__, n), ["damping", "one-bead column"],
            fn, n=n, damping="kk", gamma=1e5, sheet="brass", sheet_law="layer")
EOF

# --- 2 a standard descriptor closed by the caller ---
printf '[sweep]\nmodel = chain\nout = sw\n[grid]\nn = 1:3\n' >c.ini
timeout -s KILL 60 "$GW" sweep c.ini >&- 2>&- </dev/null
rc=$?
[ $rc -eq 0 ] && [ "$(journal_rows sw/journal.csv)" -eq 3 ] && ! grep -q 'sweep:' sw/journal.csv &&
    ok "sweep with stdout and stderr closed: exit 0, its journal holds its 3 rows alone" ||
    ko "sweep with stdout and stderr closed: exit $rc, journal: $(grep -v '^#' sw/journal.csv | head -c 300)"
timeout -s KILL 60 "$GW" sweep c.ini --quiet >/dev/null 2>"$tmp/stderr" </dev/null &&
    ok "the sweep run again reads that journal (nothing to run)" || ko "the sweep run again: exit $? ($(head -c 300 "$tmp/stderr"))"
rm -rf sw
timeout -s KILL 60 "$GW" sweep c.ini 2>&- >/dev/null </dev/null
! grep -q 'sweep:' sw/journal.csv && ok "sweep with stderr alone closed: no progress line in its journal" ||
    ko "sweep 2>&-: its journal took $(grep -c 'sweep:' sw/journal.csv) progress lines"
# stdout lost is still an error, stdin closed none
timeout -s KILL 60 "$GW" chain --json >&- 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc -eq 1 ] && grep -q '^granwave chain: stdout: write failed: Bad file descriptor' "$tmp/stderr" &&
    ok "chain --json with stdout closed: exit 1, 'stdout: write failed'" || ko "chain --json >&-: exit $rc ($(cat "$tmp/stderr"))"
rm -rf oc
timeout -s KILL 60 "$GW" chain --dt 1e-3 --out oc >/dev/null 2>&- <&-
rc=$?
[ $rc -eq 0 ] && [ -s oc/chain.json ] && ! grep -lq 'granwave chain: warning' oc/* &&
    ok "chain --out with stdin and stderr closed: exit 0, its warning in no file" || ko "chain --out 2>&- <&-: exit $rc"

# --- 3 zero-springs: a sample and its copy without springs are one pile ---
make_sample s.txt --n 20 --width-rm 8 --seed 2
grep -q '^springs [1-9]' s.txt && ok "layer-make's 20-disc sample carries springs" || ko "no springs in the sample"
sed -e "/^# lines after 'springs'/d" -e '/^springs /,$d' s.txt >bare.txt
zs_ini() { # FILE ZS [GRID LINE]
    printf '[sweep]\nmodel = layer\nout = o\n[grid]\n%s\n[params]\nt-max = 0.002\nzero-springs = %s\n' \
        "${3:-sample = s.txt, bare.txt}" "$2" >"$1"
}
zs_ini z1.ini 1
PILE="^granwave sweep: z1.ini: case 1: sample: '.*/s.txt' and '.*/bare.txt' hold the same pile .*zero-springs"
refused "sweep --check: s.txt and its copy without springs under zero-springs: one pile, refused" "$PILE" sweep z1.ini --check
refused "sweep: the same grid refused before any case, nothing written" "$PILE" sweep z1.ini --quiet
zs_ini z0.ini 0
rm -rf o # (a sweep let run above, on the code before, left its journal there)
timeout -s KILL 60 "$GW" sweep z0.ini --check >/dev/null 2>"$tmp/stderr" </dev/null &&
    ok "the two under zero-springs 0 (the springs read): two piles, valid" || ko "zero-springs 0: exit $? ($(cat "$tmp/stderr"))"
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nzero-springs = 0, 1\n[params]\nsample = s.txt\nt-max = 0.002\n' >z2.ini
timeout -s KILL 60 "$GW" sweep z2.ini --check >/dev/null 2>"$tmp/stderr" </dev/null &&
    ok "one sample over zero-springs = 0, 1: valid" || ko "one sample over zero-springs 0, 1: exit $? ($(cat "$tmp/stderr"))"
py_checks <<'EOF'
refused("Python sweep: s.txt and bare.txt under zero_springs=True", ["hold the same pile", "bare.txt"],
        granwave.sweep, "layer", {"sample": ["s.txt", "bare.txt"]}, zero_springs=True, t_max=0.002)
EOF

# --- 4 softwall --sheets --restitution: one constant, the bare sensor's ---
"$GW" softwall --help | grep -- '--restitution E' | grep -q 'with --sheets.*bare sensor' &&
    ok "softwall --help: --restitution says where --sheets calibrates" ||
    ko "softwall --help: $("$GW" softwall --help | grep -- '--restitution E')"
if runs_json "softwall --sheets --sheet-law hertz --damping kk --restitution 0.5" sw.json \
    softwall --n 1:3 --sheets --sheet-law hertz --damping kk --restitution 0.5 --quiet &&
    runs_json "chain at the study's speed" ch.json chain --damping kk --restitution 0.5 --vimp "$(jq_py sw.json "repr(d['v_imp'])")"; then
    g1=$(jq_py sw.json "repr(d['settings']['model']['gamma'])")
    g2=$(jq_py ch.json "repr(d['settings']['model']['gamma'])")
    /usr/bin/python3 -c "import sys; sys.exit(0 if abs($g1 - $g2) <= 1e-9 * $g2 else 1)" &&
        ok "softwall --sheets: gamma $g1 is chain's on the bare sensor ($g2)" || ko "softwall --sheets gamma $g1, chain $g2"
fi

# --- 5 x shown as given where the block does not fit ---
refused "layer-impact --x 1.2999999: the value shown as given" \
    "^granwave layer-impact --x: block of radius 0\.325 m at x = 1\.2999999 m from the centre does not fit" \
    layer-impact --sample s.txt --x 1.2999999 --out o
refused "layer-impact --rb-rm 4.0000001 (wider than the 8 R_m box): shown as given" \
    "^granwave layer-impact --rb-rm: a block of radius 4\.0000001 R_m" layer-impact --sample s.txt --rb-rm 4.0000001 --out o
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nx = 0, 1.2999999\n[params]\nsample = s.txt\n' >x.ini
refused "sweep --check, x = 1.2999999: shown as given" "^granwave sweep: x.ini: case 1: x: .* at x = 1\.2999999 m" \
    sweep x.ini --check

test_summary test_hostile_thirtyseventh
