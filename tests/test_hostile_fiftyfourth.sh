#!/bin/bash
# test_hostile_fiftyfourth.sh GRANWAVE SRCDIR: what the fifty-fourth hostile
# pass found, fixed at its root and asserted here.
#  1 A sweep config's line that is neither a key = value nor a [section]
#    header. The config reader notes such a line's error and reads on, and
#    the first message a later line gave came out under the bad line's
#    number: 'n 3' on line 5 and 'vimp = abc' on line 6 was
#    "s.ini:5: [grid] vimp: 'abc' is not a number"; 'bogus' on line 4 and
#    'foo = 1' on line 8 was "s.ini:4: 'foo' is not an option of model
#    chain"; alone it was "s.ini:5: syntax error". The line scan before the
#    reader (gw_sweep_config.c) now refuses the line itself, quoting it:
#    "s.ini:5: 'n 3' is neither a key = value nor a [section] header" (the
#    run, --check, a config given as text).
#  2 A key above the first section header was "unknown section []"; it is
#    now "'n' before any section header: a config opens with [sweep]".
#    Controls: 'n: 3' (the reader's other separator) and a [grid] list over
#    an indented line run.
#  3 A sample whose header porosity its particles cannot give. The porosity
#    check (layer_sample_check.c) reads the window x in [0.1, 0.9] W, y in
#    [0.1, 0.8] h, h the pile's top, and passed any header value when the
#    window held no disc (meant for a pile of one or two discs, whose
#    header layer-make leaves without a porosity, or wrote 1): one disc of
#    a made 10-disc pile lifted to y = 50 m or 1e5 m (the window's h with
#    it) ran as the settled pile (exit 0), where 5 m was refused as a header
#    not these particles'. An empty window now passes a header of 1 (or
#    none) only. Controls: the made pile and the lifted one without its
#    porosity line run.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 a line that is neither a key = value nor a section header ---
printf '[sweep]\nmodel = chain\nout = o\n[grid]\nn 3\nvimp = abc\n' >a.ini
refused "sweep: 'n 3' on line 5 before a bad vimp on line 6: line 5 named for itself" \
    "^granwave sweep: a\\.ini:5: 'n 3' is neither a key = value nor a \\[section\\] header$" sweep a.ini
refused "sweep --check: the same" \
    "^granwave sweep: a\\.ini:5: 'n 3' is neither a key = value nor a \\[section\\] header$" sweep a.ini --check
printf '[sweep]\nmodel = chain\nout = o\nbogus\n[grid]\nn = 3\n[params]\nfoo = 1\n' >b.ini
refused "sweep: 'bogus' on line 4, an unknown key on line 8: line 4 named for itself" \
    "^granwave sweep: b\\.ini:4: 'bogus' is neither a key = value nor a \\[section\\] header$" sweep b.ini
printf '[sweep]\nmodel = chain\nout = o\n[grid]\nn 3\nvimp = 0.2\n' >c.ini
refused "sweep: 'n 3' alone: named, not 'syntax error'" \
    "^granwave sweep: c\\.ini:5: 'n 3' is neither a key = value nor a \\[section\\] header$" sweep c.ini
printf '\xff\xfe[sweep]\nmodel = chain\nout = o\n[grid]\nn = 3\n' >d.ini
refused "sweep: a UTF-16 mark before [sweep]: line 1 named" \
    "^granwave sweep: d\\.ini:1: '.*\\[sweep\\]' is neither a key = value nor a \\[section\\] header \\(a config opens with \\[sweep\\]\\)$" \
    sweep d.ini

# --- 2 a key above the first section header ---
printf 'n = 3\n[sweep]\nmodel = chain\nout = o\n[grid]\nn = 3\n' >e.ini
refused "sweep: a key before any section header" \
    "^granwave sweep: e\\.ini:1: 'n' before any section header: a config opens with \\[sweep\\]" sweep e.ini

# controls: the reader's ':' separator and a list over an indented line run
printf '[sweep]\nmodel = chain\nout = o1\n[grid]\nn: 3\n[params]\nt-max = 0.01\n' >f.ini
printf '[sweep]\nmodel = chain\nout = o2\n[grid]\nn = 3,\n  4\n[params]\nt-max = 0.01\n' >g.ini
for f in f g; do
    if cpu_run 60 "$GW" sweep $f.ini --quiet --jobs 1 >/dev/null 2>"$tmp/stderr"; then
        ok "control: $f.ini runs"
    else
        ko "control: $f.ini: exit $? ($(head -c 200 "$tmp/stderr"))"
    fi
done
[ "$(grep -vc '^#' o2/results.csv)" = 3 ] && ok "control: the indented list's two cases" ||
    ko "control: o2/results.csv: $(grep -vc '^#' o2/results.csv) lines"

# --- 3 a sample whose porosity its particles cannot give ---
make_sample s10.txt --n 10
# line 14: the first particle (x y r)
for y in 50 1e5; do
    awk -v y="$y" 'NR == 14 { $2 = y } { print }' s10.txt >lift.txt
    refused "layer-impact: one disc lifted to y = $y m: the header's porosity is not these particles'" \
        "^granwave layer-impact: sample 'lift\\.txt': line 10: header 'porosity': 0\\.[0-9]+, but its particles and width leave the window .* without a disc: the header is not these particles'" \
        layer-impact --sample lift.txt --t-max 0.002 --out o
done
awk 'NR == 14 { $2 = 5 } { print }' s10.txt >lift.txt
refused "layer-impact: lifted to y = 5 m: refused (a guard)" \
    "^granwave layer-impact: sample 'lift\\.txt': line 10: header 'porosity': .* but its particles and width give" \
    layer-impact --sample lift.txt --t-max 0.002 --out o
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nvi = 10, 20\n[params]\nsample = lift50.txt\nt-max = 0.002\n' >l.ini
awk 'NR == 14 { $2 = 50 } { print }' s10.txt >lift50.txt
refused "sweep: a layer case over the lifted pile" "lift50\\.txt.*without a disc: the header is not these particles'" sweep l.ini
awk 'NR == 14 { $2 = 50 } { print }' s10.txt | grep -v '^porosity ' >noporo.txt
for f in s10.txt noporo.txt; do
    if cpu_run 60 "$GW" layer-impact --sample $f --t-max 0.002 --quiet >/dev/null 2>"$tmp/stderr"; then
        ok "control: $f runs"
    else
        ko "control: $f: exit $? ($(head -c 200 "$tmp/stderr"))"
    fi
done

test_summary test_hostile_fiftyfourth
