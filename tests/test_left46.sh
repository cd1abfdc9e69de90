#!/bin/bash
# test_left46.sh GRANWAVE SRCDIR: what the forty-sixth pass left, through the
# program and Python (test_library_left46 calls the library).
#  1 wavespeed --n 5:9 printed "period: not measured (at some speed no column
#    of 10 beads or more shows two wall-force maxima)" beside the warning
#    that the period is read on columns of 10 beads or more and the longest
#    has 9: two reasons, the text's wrong (no column of 10 was run). Under
#    gravity (--n 5:12 --vimp 0.01 --gravity 1e3, every column held) it
#    printed "period: undecided (columns held by gravity)" while the JSON's
#    period was null with no warning naming it. Now the text says the period
#    is n/a and that the warning says why, once (stderr, and the JSON's
#    warnings), the held columns' warning names the period among what they
#    leave undecided, and the text's C2 is the JSON's where it is measured
#    (the control: --n 8:12, C2 = P v^(1/5) / (m/k)^(2/5), F.15).
#  2 An HDF5 sample of an HDF5 signature and 8 MiB of written zeros (no
#    hole), and a sample layer-make wrote with 8 MiB of written zeros after
#    its end, were hashed whole before the HDF5 library refused them (or read
#    them): layer-impact and sweep --check now refuse each at its superblock
#    (exit 2, one line naming the file, nothing written). Controls: the
#    sample, its copy by cp --sparse=always, and the sample with 64 KiB of
#    written zeros after its end run.
#  3 Python: wavespeed under gravity warns of the period; layer_impact on
#    the sample with 8 MiB of zeros after it is refused naming its superblock,
#    having read under 1 MiB (/proc/self/io: the hash read all 8 MiB).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 wavespeed's period: the text, the JSON and the warning agree ---
# jq_py with os imported (the warnings compared with texts in the environment)
jq_os() { /usr/bin/python3 -c "import json, os; d = json.load(open('$1')); print($2)"; }
ws() { timeout -s KILL 60 "$GW" wavespeed "$@" --quiet --jobs 1 </dev/null; }
na="  period: n/a (period, c2 and beta_period null: the warning says why); "
if ws --n 5:9 --vimp 0.3,0.5 >t1.txt 2>e1.txt && ws --n 5:9 --vimp 0.3,0.5 --json >j1.json 2>/dev/null; then
    grep -qF -- "$na" t1.txt && ! grep -qE 'maxima|10 beads|held' t1.txt &&
        ok "1 wavespeed --n 5:9: the text says the period is n/a, the reason left to the warning" ||
        ko "1 wavespeed --n 5:9: $(grep period t1.txt)"
    [ "$(grep -c 'warning: the wall-force period is not measured' e1.txt)" = 1 ] &&
        grep -q "read on columns of 10 beads or more, and the longest here has 9" e1.txt &&
        ok "1 wavespeed --n 5:9: one warning says why (the longest column has 9 beads)" ||
        ko "1 wavespeed --n 5:9: stderr $(cat e1.txt)"
    # the JSON: null where the text says n/a, its one warning the stderr's
    W=$(sed -n 's/^granwave wavespeed: warning: //p' e1.txt) && export W
    [ "$(jq_os j1.json "d['period'], d['c2'], d['beta_period'], d['warnings'] == [os.environ['W']]")" = \
        "[None, None] None None True" ] &&
        ok "1 wavespeed --n 5:9 --json: period, c2, beta_period null, the warning the text's" ||
        ko "1 wavespeed --n 5:9 --json: $(jq_py j1.json "d['period'], d['c2'], d['warnings']")"
else
    ko "1 wavespeed --n 5:9: exit $? ($(head -c 300 e1.txt))"
fi
if ws --n 5:12 --vimp 0.01 --gravity 1e3 >t2.txt 2>e2.txt &&
    ws --n 5:12 --vimp 0.01 --gravity 1e3 --json >j2.json 2>/dev/null; then
    grep -qF -- "$na" t2.txt && ! grep -q 'period: undecided' t2.txt &&
        ok "1 wavespeed under gravity 1e3: the text's period n/a, the reason left to the warning" ||
        ko "1 wavespeed under gravity 1e3: $(grep period t2.txt)"
    N="the wall-force period at v_imp = 0.01 m/s (no decided column of 10 beads or more showed two maxima)"
    export N
    [ "$(jq_os j2.json "d['period'], d['c2'], d['n_held'] > 0, sum(os.environ['N'] in w for w in d['warnings'])")" = \
        "[None] None True 1" ] && grep -qF "$N" e2.txt &&
        ok "1 wavespeed under gravity 1e3: period null, the held columns' warning names it (stderr, --json)" ||
        ko "1 wavespeed under gravity 1e3: $(jq_py j2.json "d['period'], d['c2'], d['warnings']")"
else
    ko "1 wavespeed under gravity 1e3: exit $? ($(head -c 300 e2.txt))"
fi
# the control: the period measured, the text's C2 the JSON's, which is F.15's
# C2 = P v^(1/5) / (m/k)^(2/5) of the period measured, and no warning
if ws --n 8:12 --vimp 0.3 >t3.txt 2>e3.txt && ws --n 8:12 --vimp 0.3 --json >j3.json 2>/dev/null; then
    c2=$(sed -n 's/^  period: C2 \([0-9.]*\), beta not fitted; .*/\1/p' t3.txt)
    f15="d['period'][0] * 0.3 ** 0.2 / (d['settings']['model']['mass'] / d['settings']['model']['k']) ** 0.4"
    [ -n "$c2" ] && [ ! -s e3.txt ] &&
        [ "$(jq_py j3.json "abs(d['c2'] - $f15) < 1e-9 * d['c2'], '%.4f' % d['c2'], d['warnings']")" = \
            "True $c2 []" ] &&
        ok "1 wavespeed --n 8:12 (control): C2 $c2 in the text, the JSON's, P v^(1/5) / (m/k)^(2/5), no warning" ||
        ko "1 wavespeed --n 8:12 (control): '$c2' $(jq_py j3.json "d['c2'], d['period'], d['warnings']") $(cat e3.txt)"
else
    ko "1 wavespeed --n 8:12: exit $? ($(head -c 300 e3.txt))"
fi

# --- 2 HDF5 samples of written zeros refused at their superblock ---
sweep_ini() { printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = %s\nt-max = 0.002\n' "$1" >"$2"; }
if ! "$GW" version --json 2>/dev/null | grep -q hdf5; then
    echo "SKIP: parts 2 and 3 need an HDF5 build"
else
    make_sample s.h5 --n 40 --width-rm 12 --seed 1
    size=$(stat -c %s s.h5)
    printf '\211HDF\r\n\032\n' >sig.h5
    head -c 8388608 /dev/zero >>sig.h5
    cp s.h5 zeros.h5
    head -c 8388608 /dev/zero >>zeros.h5
    cp --sparse=always s.h5 sparse.h5
    cp s.h5 few.h5
    head -c 65536 /dev/zero >>few.h5
    for f in s sparse few; do
        sweep_ini $f.h5 $f.ini
        timeout -s KILL 60 "$GW" layer-impact --sample $f.h5 --t-max 0.002 --out o$f >/dev/null 2>"$tmp/stderr" \
            </dev/null && timeout -s KILL 60 "$GW" sweep $f.ini --check --out w$f >/dev/null 2>>"$tmp/stderr" </dev/null &&
            ok "2 layer-impact and sweep --check take $f.h5 (a control)" ||
            ko "2 $f.h5 refused: $(head -c 300 "$tmp/stderr")"
    done
    v0="HDF5 file without metadata checksums \\(superblock version 0\\): not a sample granwave wrote"
    after="$((size + 8388608)) bytes, but its HDF5 superblock says the file ends at byte $size, and 8388608 bytes follow it: not a sample granwave wrote"
    refused "2 layer-impact: an HDF5 signature and 8 MiB of written zeros" \
        "^granwave layer-impact: sample 'sig\\.h5': $v0" layer-impact --sample sig.h5 --out o
    refused "2 layer-impact: a sample and 8 MiB of written zeros after it" \
        "^granwave layer-impact: sample 'zeros\\.h5': $after" layer-impact --sample zeros.h5 --out o
    sweep_ini zeros.h5 zeros.ini
    refused "2 sweep --check: a sample and 8 MiB of written zeros after it" \
        "^granwave sweep: zeros\\.ini: \\[params\\] sample '[^']*zeros\\.h5': $after" sweep zeros.ini --check --out o

    # --- 3 Python ---
    py_checks 3 <<EOF
$(py_prelude)
r = warned("Python wavespeed under gravity 1e3", "the wall-force period at v_imp = 0.01 m/s",
           granwave.wavespeed, n=(5, 12), vimp=[0.01], gravity=1e3, jobs=1)
def rchar():
    with open("/proc/self/io") as f:
        return next(int(l.split()[1]) for l in f if l.startswith("rchar:"))
r0 = rchar()
refused("Python layer_impact on a sample and 8 MiB of written zeros after it",
        ["zeros.h5", "its HDF5 superblock says the file ends at byte $size"], granwave.layer_impact, sample="zeros.h5",
        t_max=0.002)
got = rchar() - r0
check(got < 1 << 20, "Python layer_impact: refused before it was hashed (%d bytes read)" % got)
EOF
fi
test_summary test_left46
