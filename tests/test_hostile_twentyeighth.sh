#!/bin/bash
# test_hostile_twentyeighth.sh GRANWAVE SRCDIR: what the twenty-eighth hostile
# pass (every command's flags in combination, --out placement, message
# strictness) found, each fixed at its root and asserted here.
#  1 An --out directory whose path fits PATH_MAX but whose files, under the
#    temporary names they are written as first (NAME.tmp.HOST.PID.XXXXXX), do
#    not: the run did all its work, then failed at mkstemp (exit 1, "granwave
#    chain --out: hhh...h" cut before any reason), leaving the directories it
#    had made, empty (sweep: a journal in them; and at 4075 characters sweep
#    was refused yet left them). Every writing command now refuses it before
#    the run (gw_out_names_check: exit 2, one line naming --out and PATH_MAX,
#    nothing made); a path a little shorter still runs.
#  2 A message longer than the library's 512 bytes was cut at its end: a
#    value or a path of 4,000 characters pushed the reason out ("dispersion
#    --wisdom: 'hhh...", not "is not FFTW wisdom"). gw_err_set now keeps the
#    start (what it names) and the end (the reason), " ... " between, cut
#    between UTF-8 characters.
#  3 --dt above a --dt-max given (chain, drop, falcon, softwall, wavespeed,
#    sweeps): every step is at most dt-max, so the run was dt-max's byte for
#    byte under every solver, exit 0, the settings recording the dt given.
#    Refused now (exit 2 naming --dt, nothing written).
#  4 layer-impact --exact (rk4) with --dt above --dt-out: rk4 lands on every
#    sample, so no step was longer than dt-out (--dt 1e-4, 1e-3 and 1e-2 gave
#    the same e_n and ledger to the last digit) while the settings recorded
#    the dt given. Refused then, naming --dt; --dt at most dt-out still runs.
#    Since session 46 rk4 reads the samples between its steps, and a --dt
#    above --dt-out runs at that step, the outcome the same --dt's at a
#    --dt-out at least dt, bit for bit.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1

"$GW" layer-make --n 30 --width-rm 12 --seed 3 --t-max 1 --out s.txt >/dev/null 2>&1 || ko "layer-make of the test sample"
/usr/bin/python3 -c "import sys; sys.path.insert(0, '$SRC/tests'); import synthetic_tables as s; s.write_bouncing_diagram('r.csv')" ||
    ko "the synthetic layer-stats table"
printf '[sweep]\nmodel = chain\nout = %s/unused\n[grid]\nn = 1:2\n[params]\nsolver = rk4\n' "$tmp" >sw.ini

# a relative path of L characters in components of 200 (cwd is $tmp: the
# length the kernel sees is L)
long_path() { /usr/bin/python3 -c "
L = $1; part = 'h' * 200
p = '/'.join([part] * (L // 201)); p += '/' + 'h' * (L - len(p) - 1)
print(p[:L])"; }

# --- 1 a path whose files' temporaries exceed PATH_MAX ---
# 4070 + '/' + the shortest first name (11) + the shortest temporary suffix
# (".tmp.H.P.XXXXXX", 15) is past 4095 on any host; the directory itself fits
p=$(long_path 4070)
for args in "chain --n 2" "drop --t-max 2e-4" "falcon --n 1:2 --heights none --quiet" \
    "wavespeed --n 5:8 --vimp 0.3 --quiet" "softwall --n 1:3 --kwall 1e9 --quiet" \
    "dispersion --n 32 --t-samples 64" "layer-impact --sample s.txt --t-max 0.01" "layer-stats r.csv" \
    "sweep sw.ini --quiet"; do
    rm -rf hhh*
    # shellcheck disable=SC2086
    exits_refused "1 ${args%% *} --out (4070 characters)" "${args%% *} --out: .*PATH_MAX" 60 "$GW" $args --out "$p" ||
        continue
    if ls -d hhh* >/dev/null 2>&1; then ko "1 ${args%% *}: refused but made the directories"; continue; fi
    ok "1 ${args%% *} --out of 4070 characters: exit 2 before the run, the reason said, nothing made"
done
rm -rf hhh*
p=$(long_path 4000) # + 21 + 44 at most: fits
if timeout -s KILL 60 "$GW" chain --n 2 --out "$p" >/dev/null 2>"$tmp/stderr" && [ -s "$p/chain_wall_force.csv" ]; then
    ok "1 chain --out of 4000 characters still runs and writes"
else
    ko "1 chain --out of 4000 characters: $(head -c 300 "$tmp/stderr")"
fi
rm -rf hhh*

# --- 2 a long message keeps its reason, one line of UTF-8 ---
# msg_ends WHAT PATTERN CMD...: exit 2, one stderr line, valid UTF-8, ending in PATTERN
msg_ends() {
    local what=$1 pat=$2; shift 2
    exits_refused "2 $what" "$pat" 60 "$@" || return
    if ! /usr/bin/python3 -c "import sys; open(sys.argv[1], 'rb').read().decode('utf-8')" "$tmp/stderr" 2>/dev/null; then
        ko "2 $what: the message is not UTF-8"; return
    fi
    ok "2 $what: one line, its reason kept"
}
p=$(long_path 3990)
mkdir -p "${p%/*}" && printf 'not wisdom\n' >"$p"
msg_ends "dispersion --wisdom (a 3990-character path to another file)" "not FFTW wisdom.*$" \
    "$GW" dispersion --n 32 --t-samples 64 --wisdom "$p"
[ "$(cat "$p")" = "not wisdom" ] || ko "2 the file behind --wisdom was changed"
rm -rf hhh*
msg_ends "chain --material (3000 two-byte characters)" "\\(steel brass aluminium glass pmma pvc\\)$" \
    "$GW" chain --material "$(printf '\303\251%.0s' $(seq 3000))"
msg_ends "chain --n (a value of 100000 digits and a letter)" "is not an integer \\(give an integer in \\[1, [0-9]+\\]\\)$" \
    "$GW" chain --n "$(head -c 100000 /dev/zero | tr '\0' 7)x"

# --- 3 --dt above a --dt-max given ---
for args in "chain --n 3" "drop --n 2 --t-max 2e-4" "falcon --n 1:2 --heights none --quiet" \
    "softwall --n 1:3 --kwall 1e9 --quiet" "wavespeed --n 5:8 --vimp 0.3 --quiet" "chain --n 3 --solver rk4" \
    "chain --n 3 --solver arkode"; do
    # shellcheck disable=SC2086
    refused "3 ${args} --dt 1e-6 --dt-max 1e-7" "${args%% *} --dt: 1e-06 s is above dt-max" \
        $args --dt 1e-6 --dt-max 1e-7 --out "$tmp/o"
done
printf '[sweep]\nmodel = chain\nout = %s/o\n[grid]\nn = 1:2\n[params]\ndt = 1e-6\ndt-max = 1e-7\n' "$tmp" >dtm.ini
refused "3 sweep --check with dt above dt-max" "dt: 1e-06 s is above dt-max" sweep dtm.ini --check
refused "3 sweep with dt above dt-max" "dt: 1e-06 s is above dt-max" sweep dtm.ini --quiet
if runs_json "chain --dt 1e-7 --dt-max 1e-7" d1.json chain --n 3 --dt 1e-7 --dt-max 1e-7 &&
    [ "$(jq_py d1.json "d['settings']['solver']['dt'], d['settings']['solver']['dt_max']")" = "1e-07 1e-07" ]; then
    ok "3 --dt equal to --dt-max still runs and is recorded"
else
    ko "3 chain --dt 1e-7 --dt-max 1e-7"
fi

# --- 4 layer-impact --exact with --dt above --dt-out ---
# refused from the twenty-eighth pass to session 46; rk4 now reads the samples
# between its steps (a step of rk4 from the start of the step that holds
# one, made aside), so the step given is taken and recorded, and the outcome
# is the same --dt's at a --dt-out at least dt, bit for bit
if runs_json "layer-impact --exact --dt 2e-5" e1.json layer-impact --sample s.txt --exact --dt 2e-5 --t-max 0.01 &&
    runs_json "layer-impact --exact --dt 1e-4 --dt-out 1e-4" e2.json layer-impact --sample s.txt --exact --dt 1e-4 \
        --dt-out 1e-4 --t-max 0.01 &&
    [ "$(jq_py e1.json "d['settings']['solver']['dt']")" = 2e-05 ] &&
    [ "$(jq_py e2.json "d['settings']['solver']['dt']")" = 0.0001 ]; then
    ok "4 --exact with dt at most dt-out still runs, the step recorded"
else
    ko "4 layer-impact --exact with dt <= dt-out"
fi
# outcome FILE: the outcome (repr) and the step the settings record
outcome() { jq_py "$1" "[repr(d.get(k)) for k in ('e_n_first', 'penetration', 't_end', 'steps', 'energy_error')] + [d['settings']['solver']['dt']]"; }
if runs_json "4 layer-impact --exact --dt 1e-4 at the default dt-out 2e-5" e3.json layer-impact --sample s.txt --exact \
    --dt 1e-4 --t-max 0.01; then
    [ "$(outcome e3.json)" = "$(outcome e2.json)" ] &&
        ok "4 --exact --dt 1e-4 above dt-out 2e-5 runs: its step recorded, the outcome at dt-out 1e-4 ($(outcome e3.json))" ||
        ko "4 --exact --dt 1e-4 at dt-out 2e-5: $(outcome e3.json) against $(outcome e2.json) at dt-out 1e-4"
fi
if runs_json "4 layer-impact --solver rk4 --dt 3e-5 (dt-out 2e-5)" r1.json layer-impact --sample s.txt --solver rk4 \
    --dt 3e-5 --t-max 0.01 &&
    runs_json "4 layer-impact --solver rk4 --dt 3e-5 --dt-out 6e-5" r2.json layer-impact --sample s.txt --solver rk4 \
        --dt 3e-5 --dt-out 6e-5 --t-max 0.01; then
    [ "$(outcome r1.json)" = "$(outcome r2.json)" ] &&
        ok "4 --solver rk4 --dt 3e-5 above dt-out 2e-5 runs, the outcome at dt-out 6e-5 ($(outcome r1.json))" ||
        ko "4 --solver rk4 --dt 3e-5 at dt-out 2e-5: $(outcome r1.json) against $(outcome r2.json) at 6e-5"
fi

test_summary test_hostile_twentyeighth
