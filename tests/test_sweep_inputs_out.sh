#!/bin/bash
# test_sweep_inputs_out.sh GRANWAVE SRCDIR: a sweep whose input (its config
# file, or a layer sample it names) is one of its outputs in DIR (journal.csv,
# results.csv), by name or through a link, is refused before any work, under
# --check too (gw_sweep_out_inputs_check: the twenty-first hostile pass).
# Before, `granwave sweep D/results.csv --out D` ran, exit 0, and its table
# replaced the config; D/results.csv a symbolic link to the config D/c.ini
# wrote the table into c.ini; a config D/journal.csv was refused as "not a
# granwave sweep journal ...; remove it", and `--check` said "is valid" for a
# sample D/results.csv that the run then refused. Each refusal: exit 2, one
# stderr line naming the input and the output it would be, the input unchanged,
# no journal made. What is legitimate still runs (a config in DIR under
# another name, a config called results.csv elsewhere).
# 6 of the 9 checks fail on the code before (the three that pass: the run over
# the sample, which the journal's check refused after every case was checked,
# and the two legitimate runs).
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1

cfg='[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\nsolver = rk4\n'

# refused_input WHAT INPUT DIR PATTERN ARGS...: granwave ARGS refused
# (exits_refused), INPUT unchanged (against INPUT.orig), no DIR/journal.csv
refused_input() {
    local what=$1 input=$2 dir=$3 pat=$4; shift 4
    exits_refused "$what" "$pat" 20 "$GW" "$@" || return
    if ! cmp -s "$input" "$input.orig"; then ko "$what: $input was changed"; return; fi
    if [ -e "$dir/journal.csv" ] && ! cmp -s "$dir/journal.csv" "$input.orig"; then ko "$what: a journal was made"; return; fi
    ok "$what"
}

# 1 the config is DIR/results.csv, --out DIR
mkdir d1; printf "$cfg" >d1/results.csv; cp d1/results.csv d1/results.csv.orig
refused_input "config DIR/results.csv with --out DIR" d1/results.csv d1 \
    "^granwave sweep CONFIG: 'd1/results.csv' is the file this run writes as d1/results.csv" \
    sweep d1/results.csv --out d1 --quiet
# 2 the same under --check (it said "is valid")
refused_input "the same under --check" d1/results.csv d1 "sweep CONFIG: .*writes as d1/results.csv" \
    sweep d1/results.csv --out d1 --check
# 3 the output directory from the config's own [sweep] out
# (absolute: the same whether [sweep] out is taken from the working directory or the config's)
mkdir d3; printf '[sweep]\nmodel = chain\nout = %s/d3\n[grid]\nn = 1:2\n' "$tmp" >d3/results.csv
cp d3/results.csv d3/results.csv.orig
refused_input "config DIR/results.csv with [sweep] out = DIR" d3/results.csv d3 "sweep CONFIG: .*d3/results.csv" \
    sweep d3/results.csv --quiet
# 4 the config is DIR/journal.csv ("not a granwave sweep journal; remove it" before)
mkdir d4; printf "$cfg" >d4/journal.csv; cp d4/journal.csv d4/journal.csv.orig
refused_input "config DIR/journal.csv" d4/journal.csv d4 "sweep CONFIG: 'd4/journal.csv' is the file this run writes as d4/journal.csv" \
    sweep d4/journal.csv --out d4 --quiet
# 5 DIR/results.csv a symbolic link to the config DIR/c.ini (the table was written into c.ini)
mkdir d5; printf "$cfg" >d5/c.ini; cp d5/c.ini d5/c.ini.orig; ln -s c.ini d5/results.csv
refused_input "DIR/results.csv a link to the config" d5/c.ini d5 "sweep CONFIG: 'd5/c.ini' is the file this run writes as d5/results.csv" \
    sweep d5/c.ini --out d5 --quiet
# 6 a layer sample DIR/results.csv under --check (the run refused it; --check said valid)
mkdir d6
printf 'granwave-layer-sample 1\nwidth 20\nrm 0.325\nvolume_ratio 1\nn 1\n10 0.325 0.325\n' >d6/results.csv
cp d6/results.csv d6/results.csv.orig
printf '[sweep]\nmodel = layer\n[grid]\nvi = 5\n[params]\nsample = %s/d6/results.csv\nt-max = 0.002\n' "$tmp" >s6.ini
refused_input "sample DIR/results.csv under --check" d6/results.csv d6 "^granwave sweep: '.*d6/results.csv' is the file this run writes as d6/results.csv" \
    sweep s6.ini --out d6 --check
# 7 the same run (refused before too, after every case was checked)
refused_input "sample DIR/results.csv" d6/results.csv d6 "^granwave sweep: '.*d6/results.csv' is the file" \
    sweep s6.ini --out d6 --quiet

# 8 legitimate: the config in DIR under another name
mkdir d8; printf "$cfg" >d8/c.ini; cp d8/c.ini c8.orig
if timeout 60 "$GW" sweep d8/c.ini --out d8 --quiet 2>err.txt && cmp -s d8/c.ini c8.orig && [ -s d8/results.csv ] &&
    [ "$(grep -vc '^#' d8/results.csv)" -eq 3 ]; then
    ok "a config in DIR under another name runs"
else
    ko "a config in DIR under another name: $(cat err.txt)"
fi
# 9 legitimate: a config called results.csv elsewhere
mkdir c9; printf "$cfg" >c9/results.csv; cp c9/results.csv c9.orig
if timeout 60 "$GW" sweep c9/results.csv --out d9 --quiet 2>err.txt && cmp -s c9/results.csv c9.orig &&
    [ -s d9/results.csv ]; then
    ok "a config called results.csv in another directory runs"
else
    ko "a config called results.csv elsewhere: $(cat err.txt)"
fi

test_summary test_sweep_inputs_out
