#!/bin/bash
# test_hostile_twentysixth.sh GRANWAVE SRCDIR: what the twenty-sixth hostile
# pass (every command's flags, their forms and their outputs) found, each fixed
# at its root and asserted here.
#  1 An output file of --out DIR that was not a regular file was replaced or
#    failed the run after its work. A symbolic link DIR/chain.json to a FIFO
#    or a device was written through: the rename put a regular file in place
#    of the FIFO or the device node (a character device 1,3 made with mknod,
#    a /dev/null of the test's own, became a regular file), exit 0; a FIFO at
#    DIR/chain.json was replaced the
#    same way; a directory there failed the run after its work (exit 1,
#    "write failed: Is a directory"); a link there to nothing failed after
#    the work too. The atomic write now refuses a target that is not a regular
#    file (gw_io_write_target), and every command checks the files it writes
#    into DIR before the run (gw_out_names_check): exit 2, one line naming
#    --out and the file, the FIFO still a FIFO, nothing written.
#  2 An option given as the value of the one before it was taken as that
#    value: `chain --out --json` made a directory named "--json" and printed
#    no JSON (exit 0), `sweep CONFIG --out --check` ran the whole sweep into
#    a directory "--check" instead of checking it, `layer-make --out --json`
#    pluviated for seconds into a file "--json"; others were refused for a
#    reason beside the point (`--sample --json`: "cannot open"). A value that
#    is one of the command's options is now refused (exit 2, naming the
#    flag); --out=--json still means that name, and a negative number is
#    still a value.
#  3 `--help=1` was refused as "unknown option '--help'"; it is now "takes no
#    value" (the exit code was already 2).
#  4 One path for two outputs: `dispersion --wisdom W --out W` (or --out
#    W/sub) made W the output directory, then could not save the wisdom
#    there ("Is a directory (not saved)", exit 0). A wisdom file still to
#    make that is the --out directory or one above it is now refused before
#    the run (exit 2, nothing made), by the check that already refused it as
#    one of the files in DIR (gw_outset_check_input).
#  4b A wisdom file inside an --out still to make (`--wisdom od/w --out od`,
#    od not there) was refused as "directory 'od' of 'od/w': No such file or
#    directory" (session 44), though the run makes od before it saves the
#    wisdom: it is now taken (checked as a name in the directory the run
#    makes), the run writes od's files and od/w, and the next run reads it; a
#    wisdom path under od/sub (never made) or in a directory that exists
#    nowhere stays refused, so does od/dispersion.json (one of the run's own
#    files: the check of the run's files knows them by the directory's inode,
#    which od still to make has not), and a run refused for another input
#    makes nothing.
#  5 A file of DIR that this user cannot replace: another user's file in a
#    sticky directory (/tmp). The rename failed after the run ("write failed:
#    Operation not permitted", exit 1), and the set's other files were placed
#    already (chain.h5, chain_beads.csv beside the old chain.json); layer-make
#    pluviated first. Refused before the run now (exit 2, nothing placed).
#    Needs root to make the other user's file and setpriv to run as nobody;
#    said skipped otherwise.
#  6 `layer-impact --full --until rebound` ran to t-max, --until without
#    effect, exit 0 (only --until verdict was refused with --full): the
#    until row now starts "not given", and with --full it is refused at
#    either value (exit 2 naming --until, nothing in --out); --until rebound
#    alone runs as the default.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
test_setup "$@"
PY=/usr/bin/python3
cd "$tmp" || exit 1

"$GW" layer-make --n 30 --width-rm 12 --seed 3 --t-max 1 --out s.txt >/dev/null 2>&1 || ko "layer-make of the test sample"
$PY -c "import sys; sys.path.insert(0, '$SRC/tests'); import synthetic_tables as s; s.write_bouncing_diagram('r.csv')" ||
    ko "the synthetic layer-stats table"
printf '[sweep]\nmodel = chain\nout = %s/unused\n[grid]\nn = 1:2\n' "$tmp" >sw.ini

# --- 1 the files of --out DIR that are not regular files ---
mkfifo fifo
dev=""
if mknod dev c 1 3 2>/dev/null; then dev=$tmp/dev; fi # a /dev/null of our own (root only)

# out_kind WHAT KIND FILE CMD...: DIR o holding FILE as KIND (link-fifo,
# link-dev, fifo, dir, dangling): exit 2 before the run naming --out and the
# file, the FIFO and the device unchanged, nothing else in o
out_kind() {
    local what=$1 kind=$2 file=$3; shift 3
    rm -rf o; mkdir o
    case $kind in
        link-fifo) ln -s "$tmp/fifo" "o/$file" ;;
        link-dev) ln -s "$dev" "o/$file" ;;
        fifo) mkfifo "o/$file" ;;
        dir) mkdir "o/$file" ;;
        dangling) ln -s "$tmp/nowhere" "o/$file" ;;
    esac
    exits_refused "$what ($kind o/$file)" "--out: 'o/$file'" 60 "$GW" "$@" || return
    local left
    left=$(ls -A o)
    if [ "$left" != "$file" ]; then ko "$what ($kind): wrote into o: $left"; return; fi
    if [ ! -p fifo ]; then ko "$what ($kind): the FIFO behind the link was replaced"; rm -f fifo; mkfifo fifo; return; fi
    if [ -n "$dev" ] && [ ! -c "$dev" ]; then ko "$what ($kind): the device behind the link was replaced"; rm -f dev; mknod dev c 1 3; return; fi
    case $kind in fifo) [ -p "o/$file" ] || { ko "$what: the FIFO o/$file was replaced"; return; } ;; esac
    ok "$what ($kind o/$file): exit 2 before the run, nothing replaced"
}

out_kind "chain" link-fifo chain.json chain --n 2 --out o
out_kind "chain" fifo chain.json chain --n 2 --out o
out_kind "chain" dir chain.json chain --n 2 --out o
out_kind "chain" dangling chain_beads.csv chain --n 2 --out o
[ -n "$dev" ] && out_kind "chain" link-dev chain.json chain --n 2 --out o
out_kind "drop" link-fifo drop_peaks.csv drop --t-max 1e-3 --out o
out_kind "softwall" link-fifo softwall.json softwall --n 1:3 --quiet --out o
out_kind "falcon" link-fifo falcon_runs.csv falcon --n 1:2 --heights none --quiet --out o
out_kind "wavespeed" link-fifo wavespeed.json wavespeed --n 5:8 --vimp 0.3 --quiet --out o
out_kind "dispersion" link-fifo dispersion_power.csv dispersion --n 64 --t-samples 256 --out o
out_kind "layer-impact" link-fifo impact.json layer-impact --sample s.txt --t-max 0.02 --out o
out_kind "layer-impact" dir snapshot_0.vtk layer-impact --sample s.txt --t-max 0.02 --out o
out_kind "layer-stats" link-fifo diagram.csv layer-stats r.csv --out o
out_kind "sweep" link-fifo results.csv sweep sw.ini --out o
out_kind "sweep --check" link-fifo results.csv sweep sw.ini --out o --check

# a link to a regular file is still written through, the link kept
rm -rf o; mkdir o; : >target.json; ln -s "$tmp/target.json" o/chain.json
if "$GW" chain --n 2 --out o >/dev/null 2>"$tmp/err" && [ -L o/chain.json ] && [ -s target.json ] &&
    $PY -c "import json; json.load(open('target.json'))"; then
    ok "chain --out: a link to a regular file still written through, the link kept"
else
    ko "chain --out through a link to a regular file: $(head -c 300 "$tmp/err")"
fi

# --- 2 an option taken as the value of the option before it ---
refused_opt() { # WHAT FLAG CMD...: exit 2 naming FLAG, no directory or file of the option's name
    local what=$1 flag=$2; shift 2
    rm -rf -- o --json --out --n
    exits_refused "$what" "--$flag: needs a value" 20 "$GW" "$@" || return
    if compgen -G "./--*" >/dev/null; then ko "$what: made $(ls -d -- ./--*)"; return; fi
    ok "$what: exit 2 naming --$flag, nothing made"
}
refused_opt "chain --out --json" out chain --n 2 --out --json
refused_opt "layer-impact --sample --json" sample layer-impact --sample --json
refused_opt "layer-make --out --json" out layer-make --n 20 --out --json
refused_opt "dispersion --wisdom --out DIR" wisdom dispersion --n 64 --t-samples 256 --wisdom --out o
refused_opt "layer-stats --out --json" out layer-stats r.csv --out --json
refused_opt "sweep --out --check" out sweep sw.ini --out --check
refused_opt "chain --material -h" material chain --material -h
rm -rf -- --json
if "$GW" chain --n 2 --out=--json >/dev/null 2>"$tmp/err" && [ -s ./--json/chain.json ]; then
    ok "chain --out=--json: a directory of that name, as asked"
else
    ko "chain --out=--json: $(head -c 300 "$tmp/err")"
fi
rm -rf -- --json
exits_refused "chain --vimp -0.3" "--vimp: -0.3 is outside" 20 "$GW" chain --vimp -0.3 &&
    ok "chain --vimp -0.3: a negative number still a value (refused by its range)"

# --- 3 --help=1 ---
exits_refused "chain --help=1" "option '--help' takes no value" 20 "$GW" chain --help=1 &&
    ok "chain --help=1: --help takes no value"

# --- 4 the wisdom file and the --out directory one path ---
for pair in "w1 w1" "w2 ./w2/sub" "./w3 $tmp/w3/"; do
    set -- $pair
    rm -rf w1 w2 w3
    exits_refused "dispersion --wisdom $1 --out $2" "dispersion --wisdom: '$1' is (the|a) directory" 20 \
        "$GW" dispersion --n 64 --t-samples 256 --wisdom "$1" --out "$2" || continue
    if [ -e w1 ] || [ -e w2 ] || [ -e w3 ]; then ko "dispersion --wisdom $1 --out $2: made $(ls -d w1 w2 w3 2>/dev/null)"; continue; fi
    ok "dispersion --wisdom $1 --out $2: exit 2 before the run, nothing made"
done
rm -rf w4 w4.wisdom
if "$GW" dispersion --n 64 --t-samples 256 --wisdom w4.wisdom --quiet --out w4 >/dev/null 2>"$tmp/err" && [ -d w4 ] &&
    head -c 7 w4.wisdom | grep -q '(fftw-3' && [ ! -s "$tmp/err" ]; then
    ok "dispersion --wisdom w4.wisdom --out w4: both written"
else
    ko "dispersion --wisdom w4.wisdom --out w4: $(head -c 300 "$tmp/err")"
fi

# --- 4b a wisdom file inside the --out directory still to make ---
rm -rf od
if "$GW" dispersion --n 64 --t-samples 64 --wisdom od/w --out od --quiet >/dev/null 2>"$tmp/err" &&
    [ -s od/dispersion.json ] && [ -s od/dispersion_ridge.csv ] && head -c 7 od/w | grep -q '(fftw-3'; then
    ok "dispersion --wisdom od/w --out od (od still to make): runs, od's files and the wisdom written"
else
    ko "dispersion --wisdom od/w --out od: $(head -c 300 "$tmp/err")"
fi
if "$GW" dispersion --n 64 --t-samples 64 --wisdom od/w --out od --quiet >/dev/null 2>"$tmp/err" &&
    [ "$(jq_py od/dispersion.json "d['settings']['spectrum']['fftw_wisdom_fnv1a64'] is not None")" = True ]; then
    ok "dispersion --wisdom od/w --out od again: the wisdom the first run saved is read"
else
    ko "dispersion --wisdom od/w --out od again: $(head -c 300 "$tmp/err")"
fi
rm -rf od od2
if "$GW" dispersion --n 64 --t-samples 64 --wisdom ./od2//w --out od2/ --quiet >/dev/null 2>"$tmp/err" &&
    head -c 7 od2/w | grep -q '(fftw-3' && [ -s od2/dispersion.json ]; then
    ok "dispersion --wisdom ./od2//w --out od2/: the same directory spelled otherwise, taken"
else
    ko "dispersion --wisdom ./od2//w --out od2/: $(head -c 300 "$tmp/err")"
fi
# wisdom_refused WHAT PATTERN ARGS...: exit 2 naming --wisdom, od and nod not made
wisdom_refused() {
    local what=$1 pat=$2; shift 2
    rm -rf od nod
    exits_refused "$what" "$pat" 20 "$GW" dispersion --t-samples 64 "$@" || return
    if [ -e od ] || [ -e nod ]; then ko "$what: made $(ls -d od nod 2>/dev/null)"; return; fi
    ok "$what: exit 2, nothing made"
}
wisdom_refused "dispersion --wisdom od/dispersion.json --out od (od still to make)" \
    "dispersion --wisdom: 'od/dispersion.json' is the file this run writes as od/dispersion.json" \
    --n 64 --wisdom od/dispersion.json --out od
wisdom_refused "dispersion --wisdom od/sub/w --out od (od/sub never made)" \
    "dispersion --wisdom: directory 'od/sub' of 'od/sub/w': No such file" --n 64 --wisdom od/sub/w --out od
wisdom_refused "dispersion --wisdom nod/w --out od (nod exists nowhere)" \
    "dispersion --wisdom: directory 'nod' of 'nod/w': No such file" --n 64 --wisdom nod/w --out od
wisdom_refused "dispersion --n 7 --wisdom od/w --out od (refused for --n)" "dispersion --n: 7 is outside" \
    --n 7 --wisdom od/w --out od

# --- 6 --until given with --full, whatever its value ---
REFUSE_TIMEOUT=60 refused "layer-impact --full --until rebound" "layer-impact --until: rebound has no effect with full" \
    layer-impact --sample s.txt --t-max 0.02 --full --until rebound --out "$tmp/o"
if runs_json "layer-impact --until rebound" u1.json layer-impact --sample s.txt --t-max 0.4 --until rebound &&
    runs_json "layer-impact (default until)" u0.json layer-impact --sample s.txt --t-max 0.4 &&
    [ "$(jq_py u1.json "d['e_n'], d['t_f'], d['settings']['until']")" = "$(jq_py u0.json "d['e_n'], d['t_f'], d['settings']['until']")" ] &&
    [ "$(jq_py u0.json "d['e_n'] is not None")" = True ]; then
    ok "layer-impact --until rebound alone: the default run's e_n and T_f"
else
    ko "layer-impact --until rebound alone differs from the default run"
fi

# --- 5 another user's file in a sticky directory ---
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null &&
    setpriv --reuid=65534 --regid=65534 --clear-groups test -x "$GW" 2>/dev/null; then
    chmod 711 "$tmp"
    mkdir st && chmod 1777 st && : >st/chain.json && : >st/s.txt
    for args in "chain --n 2 --out st" "layer-make --n 20 --t-max 0.05 --out st/s.txt"; do
        # shellcheck disable=SC2086
        exits_refused "as nobody: $args" "belongs to another user in the sticky directory" 60 \
            setpriv --reuid=65534 --regid=65534 --clear-groups "$GW" $args ||
            continue
        left=$(ls -A st | tr '\n' ' ')
        if [ "$left" != "chain.json s.txt " ] || [ -s st/chain.json ] || [ -s st/s.txt ]; then
            ko "as nobody: $args: st holds $left"; continue
        fi
        ok "as nobody: $args: exit 2 before the run, nothing placed"
    done
else
    echo "SKIP: another user's file in a sticky directory (needs root and setpriv, the program reachable as nobody)"
fi

test_summary test_hostile_twentysixth
