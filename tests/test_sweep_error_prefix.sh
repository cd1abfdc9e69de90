#!/bin/bash
# test_sweep_error_prefix.sh GRANWAVE SRCDIR: every refusal of `granwave sweep`
# is one line that starts with the command's name, whatever the config and
# --out are called (issue 18, the thirtieth hostile pass). The command printed
# a library message as it was when it started with "sweep" (taking it for one
# that names the command, "sweep: ..." or "sweep --jobs: ..."), so a config
# named sweep.ini or under sweeps/, and an output directory sweep_out, lost
# it: "granwave sweep.ini:3: unknown key ...", "granwave
# sweep_out/journal.csv: ...". Each case: exit 2, one stderr line matching
# '^granwave sweep(: | --| CONFIG: )' and naming the file, nothing written.
# 8 checks; on the code before, 4 fail (the config named sweep.ini twice,
# sweeps/a.ini, the journal in sweep_out); the messages that name the command
# themselves (a missing config, --jobs -1, a table's place) pass there.
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

# refused WHAT NAME ARGS...: exit 2, one line starting with the command's
# name and holding NAME, no stdout, nothing made under a directory "new"
refused() {
    local what=$1 name=$2
    shift 2
    timeout 60 "$GW" sweep "$@" >out.txt 2>err.txt </dev/null
    local rc=$? lines
    lines=$(wc -l <err.txt)
    if [ $rc -eq 2 ] && [ "$lines" -eq 1 ] && grep -Eq '^granwave sweep(: | --| CONFIG: )' err.txt &&
        grep -qF -- "$name" err.txt && [ ! -s out.txt ] && [ ! -e new ]; then
        ok "$what: $(cut -c1-150 err.txt)"
    else
        ko "$what: exit $rc, $lines lines: $(head -c 300 err.txt)"
    fi
}

printf '[sweep]\nmodel = chain\njobs = 2\n[grid]\nn = 1:2\n' >sweep.ini
refused "an unknown key in sweep.ini" "sweep.ini:3" sweep.ini --out new
printf '[grid]\nn = 1:2\n' >sweep.ini
refused "no model in sweep.ini" "sweep.ini" sweep.ini --out new
mkdir sweeps && printf '[sweep]\nmodel = chain\njobs = 2\n[grid]\nn = 1:2\n' >sweeps/a.ini
refused "an unknown key in sweeps/a.ini" "sweeps/a.ini:3" sweeps/a.ini --out new
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\nvimp = 0.2\n' >a.ini
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\nvimp = 0.3\n' >b.ini
"$GW" sweep a.ini --out sweep_out --quiet >/dev/null 2>&1 || ko "the sweep into sweep_out"
cp sweep_out/journal.csv j.orig
refused "another config's journal in sweep_out" "sweep_out" b.ini --out sweep_out --quiet
cmp -s sweep_out/journal.csv j.orig && ok "  its journal left as it was" || ko "  its journal changed"
# kept: messages that name the command themselves, printed as they are
refused "a missing config (kept)" "missing.ini" missing.ini --out new
refused "--jobs -1 (kept)" "--jobs" a.ini --out new --jobs -1
mkdir -p t/results.csv
refused "a directory in the table's place (kept)" "t/results.csv" a.ini --out t --quiet

test_summary test_sweep_error_prefix
