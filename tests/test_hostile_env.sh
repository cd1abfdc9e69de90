#!/bin/bash
# test_hostile_env.sh GRANWAVE SRCDIR: the thirteenth hostile pass, over the
# process environment of the program (the Python module's in
# tests/python/test_hostile_env.py). Each check asserts behaviour (exit code,
# message, file modes, what exists); each failed on the binary before this pass
# unless marked "kept".
#  1 granwave --help, help and --version into /dev/full or a closed stdout
#    exited 0; now exit 1 with "stdout: write failed".
#  2 past a file-size limit (ulimit -f, SIGXFSZ at its default) the program was
#    killed (exit 153) and left its temporary; now exit 1 naming the file
#    ("File too large"), no temporary left.
#  3 files were 0644 whatever the umask: under umask 077 a run's files were
#    world-readable. Now 0666 less the umask (0600 under 077, 0664 under 002;
#    directories 0777 less the umask: 0775 under 002, was 0755).
#  4 a replaced file took 0644 too; it keeps its own mode now (as a shell's >).
#  5 an --out directory to make under a umask that leaves no write permission
#    (777, as a user) gave exit 1 and an unusable empty directory left; now
#    exit 2 before the run, one line naming the umask, nothing made.
#  6 the header's command line joined arguments with blanks (--out 'a b' read
#    back as two arguments; a newline in a path split the line): shell-quoted
#    now, and eval gives the arguments back.
#  8 under ulimit -s 64 layer-impact --out died of a stack overflow (SIGSEGV,
#    exit 139); a stack limit below 256 KiB is refused at start now (exit 2,
#    one line), and the same run works at 256 KiB.
#  7 kept: the program reads numbers and writes files the same in a
#    decimal-comma locale (LC_ALL=de_DE.UTF-8), byte for byte.
set -u
GW=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
mode() { stat -c %a "$1"; }

# 1 stdout that cannot be written
for args in "--help" "help" "--version" "version"; do
    # shellcheck disable=SC2086
    "$GW" $args >/dev/full 2>"$tmp/e"; rc=$?
    if [ $rc -eq 1 ] && grep -q 'stdout: write failed: No space left on device' "$tmp/e"; then ok "1 $args > /dev/full: exit 1"
    else ko "1 $args > /dev/full: exit $rc, $(cat "$tmp/e")"; fi
done
"$GW" --version >&- 2>"$tmp/e"; rc=$?
[ $rc -eq 1 ] && grep -q 'stdout: write failed' "$tmp/e" && ok "1 --version with stdout closed: exit 1" ||
    ko "1 --version with stdout closed: exit $rc"

# 2 a file-size limit with SIGXFSZ at its default disposition
d=$tmp/fs
(trap - XFSZ; ulimit -f 8; exec "$GW" chain --n 3 --out "$d") >/dev/null 2>"$tmp/e"; rc=$?
if [ $rc -eq 1 ] && grep -q 'chain_wall_force.csv: write failed: File too large' "$tmp/e" &&
    [ -z "$(ls -A "$d" 2>/dev/null)" ]; then ok "2 ulimit -f 8: exit 1, no temporary"
else ko "2 ulimit -f 8: exit $rc, $(cat "$tmp/e"), left: $(ls -A "$d" 2>/dev/null | tr '\n' ' ')"; fi

# 3 the umask
(umask 077; exec "$GW" chain --n 3 --out "$tmp/u77") >/dev/null 2>&1
(umask 077; exec "$GW" layer-make --n 20 --width-rm 10 --seed 1 --out "$tmp/u77s.txt") >/dev/null 2>&1
modes=$(for f in "$tmp"/u77/* "$tmp/u77s.txt"; do mode "$f"; done | sort -u | tr '\n' ' ')
if [ "$(mode "$tmp/u77")" = 700 ] && [ "$modes" = "600 " ] && [ "$(ls "$tmp/u77" | wc -l)" -ge 4 ]; then
    ok "3 umask 077: directory 700, files 600"
else ko "3 umask 077: directory $(mode "$tmp/u77"), files $modes"; fi
printf '[sweep]\nmodel = chain\nout = %s\n[grid]\nn = 2:3\n' "$tmp/sw" >"$tmp/s.ini"
(umask 077; exec "$GW" sweep "$tmp/s.ini" --quiet) >/dev/null 2>&1
[ "$(mode "$tmp/sw/results.csv")" = 600 ] && [ "$(mode "$tmp/sw/journal.csv")" = 600 ] &&
    ok "3 umask 077: sweep table and journal 600" ||
    ko "3 umask 077: sweep table $(mode "$tmp/sw/results.csv"), journal $(mode "$tmp/sw/journal.csv")"
(umask 002; exec "$GW" chain --n 3 --out "$tmp/u02") >/dev/null 2>&1
[ "$(mode "$tmp/u02")" = 775 ] && [ "$(mode "$tmp/u02/chain.json")" = 664 ] &&
    ok "3 umask 002: directory 775, files 664" ||
    ko "3 umask 002: directory $(mode "$tmp/u02"), chain.json $(mode "$tmp/u02/chain.json")"

# 4 a replaced file keeps its mode
chmod 600 "$tmp/u02/chain.json"; chmod 640 "$tmp/u02/chain_beads.csv"
(umask 022; exec "$GW" chain --n 4 --out "$tmp/u02") >/dev/null 2>&1
[ "$(mode "$tmp/u02/chain.json")" = 600 ] && [ "$(mode "$tmp/u02/chain_beads.csv")" = 640 ] &&
    grep -q '"n":	4' "$tmp/u02/chain.json" && ok "4 replaced files keep 600 and 640" ||
    ko "4 replaced files: $(mode "$tmp/u02/chain.json") $(mode "$tmp/u02/chain_beads.csv")"

# 5 umask 777 as a user (root writes anyway: only checked when this runs as root)
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null && id nobody >/dev/null 2>&1; then
    as_nobody() { setpriv --reuid=nobody --regid="$(id -g nobody)" --clear-groups "$@"; }
    chmod 755 "$tmp"; mkdir "$tmp/nb"; chmod 777 "$tmp/nb"
    for c in "chain --n 3 --out $tmp/nb/o/x" "sweep $tmp/s.ini --quiet --out $tmp/nb/o"; do
        # shellcheck disable=SC2086
        as_nobody sh -c 'umask 777; exec "$@"' sh "$GW" $c >"$tmp/o5" 2>"$tmp/e"; rc=$?
        if [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/e")" -eq 1 ] && grep -q 'umask 0777' "$tmp/e" && [ ! -e "$tmp/nb/o" ]; then
            ok "5 umask 777: ${c%% *} refused, nothing made"
        else ko "5 umask 777: ${c%% *}: exit $rc, $(cat "$tmp/e"), left: $(ls -A "$tmp/nb")"; fi
        rm -rf "$tmp/nb/o" 2>/dev/null || { chmod -R u+rwx "$tmp/nb/o"; rm -rf "$tmp/nb/o"; }
    done
    chmod 700 "$tmp"
else
    echo "SKIP: 5 needs root and setpriv to run as nobody"
fi

# 6 the command line in the headers, as a shell reads it back
for name in "a b" $'nl\nx' "it's" "-lead" "é ✓"; do
    d="$tmp/q/$name"
    mkdir -p "$d" # made here: a name to make with a newline is refused (session 42)
    "$GW" chain --n 2 --out "$d" >/dev/null 2>&1
    line=$(grep -m1 -h '^# command: ' "$d/chain_wall_force.csv" 2>/dev/null | sed 's/^# command: //')
    lines=$(grep -c '^# ' "$d/chain_wall_force.csv" 2>/dev/null)
    eval "got=( $line )" 2>/dev/null
    if [ "${#got[@]}" -eq 6 ] && [ "${got[5]}" = "$d" ] && [ "$lines" -eq 4 ]; then ok "6 command line with '$name' reads back"
    else ko "6 command line with '$name': '$line' (${#got[@]} words, $lines comment lines)"; fi
done

# 7 kept: a decimal-comma locale (made with localedef when not installed)
loc=""
for l in de_DE.UTF-8 de_DE.utf8 fr_FR.UTF-8 fr_FR.utf8; do locale -a 2>/dev/null | grep -qx "$l" && loc=$l && break; done
if [ -z "$loc" ] && command -v localedef >/dev/null && mkdir -p "$tmp/loc" && localedef -i de_DE -f UTF-8 "$tmp/loc/de_DE.UTF-8" >/dev/null 2>&1; then
    loc=de_DE.UTF-8; export LOCPATH=$tmp/loc
fi
if [ -n "$loc" ]; then
    LC_ALL=C "$GW" chain --n 3 --vimp 0.25 --restitution 0.9 --damping kk --out "$tmp/lc" --quiet --json >"$tmp/lc.json" 2>&1
    LC_ALL=$loc "$GW" chain --n 3 --vimp 0.25 --restitution 0.9 --damping kk --out "$tmp/lc" --quiet --json >"$tmp/ld.json" 2>&1
    cp "$tmp/lc/chain_wall_force.csv" "$tmp/lc.csv"
    LC_ALL=C "$GW" chain --n 3 --vimp 0.25 --restitution 0.9 --damping kk --out "$tmp/lc" --quiet --json >/dev/null 2>&1
    if cmp -s <(grep -v wall_time "$tmp/lc.json") <(grep -v wall_time "$tmp/ld.json") &&
        cmp -s "$tmp/lc.csv" "$tmp/lc/chain_wall_force.csv" && grep -q '"v_imp":	0.25' "$tmp/ld.json"; then
        ok "7 LC_ALL=$loc: same JSON and CSV (kept)"
    else ko "7 LC_ALL=$loc: outputs differ"; fi
else
    echo "SKIP: 7 no decimal-comma locale and localedef cannot make one"
fi

# 8 a small stack limit
S=$tmp/u77s.txt
(ulimit -s 64; exec "$GW" layer-impact --sample "$S" --t-max 0.01 --out "$tmp/st64") >/dev/null 2>"$tmp/e"; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l <"$tmp/e")" -eq 1 ] && grep -q 'ulimit -s 64 KiB' "$tmp/e" && [ ! -e "$tmp/st64" ] &&
    ok "8 ulimit -s 64: refused, nothing written" || ko "8 ulimit -s 64: exit $rc, $(head -c 300 "$tmp/e")"
(ulimit -s 256; exec "$GW" layer-impact --sample "$S" --t-max 0.01 --out "$tmp/st256") >/dev/null 2>&1; rc=$?
[ $rc -eq 0 ] && [ -s "$tmp/st256/impact.json" ] && ok "8 ulimit -s 256: layer-impact --out runs" ||
    ko "8 ulimit -s 256: exit $rc"

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
