#!/bin/bash
# test_top_level.sh GRANWAVE SRCDIR: the program's own arguments, before any
# command (the seventeenth hostile pass). Each check failed on the code before:
#  1 `granwave help chain` printed the list of commands, not chain's options;
#    now `help COMMAND` is that command's --help, byte for byte, for every
#    command the list names.
#  2 `help nosuch`, `help chain extra`, `version extra`, `version --foo` exited
#    0 with the extra argument ignored; refused now (exit 2, one line naming it,
#    nothing on stdout).
#  3 `version --json` printed the plain text; it prints one JSON object now,
#    whose versions are checked against independent sources: the program's
#    own `version`, SUNDIALS' installed header, gsl-config, h5py's HDF5.
#  4 `version --help` and `help --help` (or -h) exited 2 ("unexpected argument
#    '--help'", "unknown command '--help'") where every command prints its
#    help, and `help version` / `help help` printed the whole list: each now
#    prints its own usage (exit 0, stdout only), `help X` = `X --help` as for
#    every command, and --help among version's other flags is the help
#    (8 of 9 checks fail on 22cefeb).
set -u
GW=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; checks=0
ok() { checks=$((checks + 1)); echo "ok   $1"; }
bad() { checks=$((checks + 1)); fails=$((fails + 1)); echo "FAIL $1"; }

# 1 help COMMAND is the command's own --help, for every listed command
cmds=$("$GW" --help | awk '/^commands:/ {on = 1; next} on && /^  [a-z]/ {print $1}' | grep -vxE 'version|help')
[ "$(echo "$cmds" | wc -w)" -ge 10 ] && ok "1 the list names $(echo "$cmds" | wc -w) commands" ||
    bad "1 the list names only: $cmds"
for c in $cmds; do
    "$GW" help "$c" >"$tmp/a" 2>"$tmp/ea"; ra=$?
    "$GW" "$c" --help >"$tmp/b" 2>/dev/null; rb=$?
    if [ $ra -eq 0 ] && [ $rb -eq 0 ] && [ -s "$tmp/b" ] && cmp -s "$tmp/a" "$tmp/b" && [ ! -s "$tmp/ea" ]; then
        ok "1 help $c is '$c --help'"
    else
        bad "1 help $c: exit $ra, differs from '$c --help' (exit $rb)"
    fi
done
"$GW" --help chain >"$tmp/a" 2>/dev/null && "$GW" chain --help >"$tmp/b" && cmp -s "$tmp/a" "$tmp/b" &&
    ok "1 --help chain is 'chain --help'" || bad "1 --help chain is not 'chain --help'"

# 2 extra arguments refused: exit 2, one line naming the argument, stdout empty
refused() {
    local want=$1; shift
    "$GW" "$@" >"$tmp/o" 2>"$tmp/e"; local rc=$?
    if [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/e")" -eq 1 ] && grep -qF -- "$want" "$tmp/e" && [ ! -s "$tmp/o" ]; then
        ok "2 '$*' refused: $(cat "$tmp/e")"
    else
        bad "2 '$*': exit $rc, stderr '$(head -c 200 "$tmp/e")', stdout $(wc -c <"$tmp/o") bytes"
    fi
}
refused "'nosuch'" help nosuch
refused "'extra'" help chain extra
refused "'extra'" version extra
refused "'--foo'" version --foo
refused "'--foo'" --version --foo
refused "given twice" version --json --json
refused "'nosuch'" nosuch

# 3 version --json: one object; each version from an independent source
"$GW" version --json >"$tmp/v.json" 2>"$tmp/e"; rc=$?
plain=$("$GW" version | awk '{print $2}')
sun=$(sed -n 's/^#define SUNDIALS_VERSION "\(.*\)"/\1/p' /usr/include/sundials/sundials_config.h)
gsl=$(gsl-config --version 2>/dev/null || echo "")
h5=$(/usr/bin/python3 -c 'import h5py; print(h5py.version.hdf5_version)' 2>/dev/null || echo "")
out=$(/usr/bin/python3 - "$tmp/v.json" "$plain" "$sun" "$gsl" "$h5" <<'EOF'
import json, sys
path, plain, sun, gsl, h5 = sys.argv[1:]
v = json.load(open(path))
bad = []
if v.get("version") != plain: bad.append(f"version {v.get('version')!r} != {plain!r}")
if not sun or v.get("sundials") != sun: bad.append(f"sundials {v.get('sundials')!r} != {sun!r}")
if gsl and v.get("gsl") != gsl: bad.append(f"gsl {v.get('gsl')!r} != {gsl!r}")
if not str(v.get("fftw", "")).startswith("fftw-3."): bad.append(f"fftw {v.get('fftw')!r}")
if h5 and v.get("hdf5") not in (h5, None): bad.append(f"hdf5 {v.get('hdf5')!r} != {h5!r}")
print("; ".join(bad) if bad else "ok " + json.dumps(v, sort_keys=True))
EOF
)
[ $rc -eq 0 ] && [ ! -s "$tmp/e" ] && [ "${out#ok }" != "$out" ] && ok "3 version --json: ${out#ok }" ||
    bad "3 version --json: exit $rc: $out $(head -c 200 "$tmp/e")"

# 4 version and help have their own --help, as every command
own_help() {
    local want=$1; shift
    "$GW" "$@" >"$tmp/o" 2>"$tmp/e"; local rc=$?
    if [ $rc -eq 0 ] && [ ! -s "$tmp/e" ] && [ "$(head -1 "$tmp/o")" = "usage: granwave $want" ]; then
        ok "4 '$*' prints its usage"
    else
        bad "4 '$*': exit $rc, stdout '$(head -1 "$tmp/o")', stderr '$(head -c 200 "$tmp/e")'"
    fi
}
own_help "version [--json]" version --help
own_help "version [--json]" version -h
# version --json --help: the help as JSON (test_help_json)
own_help "help [COMMAND] [--json]" help --help
own_help "help [COMMAND] [--json]" help -h
own_help "help [COMMAND] [--json]" --help --help
"$GW" help version >"$tmp/a" 2>&1; "$GW" version --help >"$tmp/b" 2>&1
[ -s "$tmp/a" ] && cmp -s "$tmp/a" "$tmp/b" && ok "4 help version is 'version --help'" ||
    bad "4 help version differs from 'version --help'"
"$GW" help help >"$tmp/a" 2>&1; "$GW" help --help >"$tmp/b" 2>&1
[ -s "$tmp/a" ] && cmp -s "$tmp/a" "$tmp/b" && ok "4 help help is 'help --help'" ||
    bad "4 help help differs from 'help --help'"
refused "'--foo'" version --foo --help

echo "$((checks - fails)) of $checks checks pass"
[ $fails -eq 0 ]
