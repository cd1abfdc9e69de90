#!/bin/bash
# test_hostile_fortyninth.sh GRANWAVE SRCDIR: what the forty-ninth hostile
# pass found, fixed at its root and asserted here.
#  1 A crown width whose square is no normal double (--ring-width 1e-160, up
#    to 1.49e-154 m) was refused by the regions' setup, "granwave
#    layer-impact: layer regions: ring width w = 1e-160 m is too small",
#    naming no input; a layer sweep's check named the case but not the key.
#    The impact's parameter check (layer_impact.c, shared by the program, a
#    sweep's cases and the library) now refuses it naming ring-width. Control:
#    1.5e-154 m still runs (with its warning that no crown holds a centre).
#  2 An --out (or layer-make --out FILE) longer than a path may be (4095
#    bytes) was refused as "bad path '...'", and the message, cut in the middle
#    of the long path, gave no reason. gw_io_paths.c now says "the path is N
#    bytes long, more than the 4095 a path may hold" before the path, for
#    every command's --out (one helper for the three checks that refused it).
#  3 Results printed as zero. falcon's text gave v_imp with four fixed
#    decimals and forces with two, softwall's F_plateau with two: a legal slow
#    impact (`falcon --vimp 1e-6`, softwall's alike) printed "v_imp 0.0000
#    m/s: F_max 0.00 N (0.00..0.00)" and "F_plateau 0.00 N" while --json held
#    1.8e-5 and 1.3e-5 N. Both now print four significant digits; checked
#    against --json's numbers (and the default falcon line's 67.45 N kept).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

make_sample s20 --n 20 --quiet

# 1 the crown width's square
refused "layer-impact --ring-width 1e-160 names the flag" \
    '^granwave layer-impact --ring-width: 1e-160 m is too small: its square is no normal double' \
    layer-impact --sample s20 --ring-width 1e-160 --out "$tmp/o" --quiet
refused "layer-impact --ring-width 1e-160 --json names the flag" \
    '^granwave layer-impact --ring-width: 1e-160 m' \
    layer-impact --sample s20 --ring-width 1e-160 --json --quiet
printf '[sweep]\nmodel = layer\nout = %s/o\n[grid]\nring-width = 0, 1e-160\n[params]\nsample = %s/s20\nvi = 20\nt-max = 0.002\n' \
    "$tmp" "$tmp" >rw.ini
refused "a layer sweep's case of ring-width 1e-160 names the key (--check)" \
    '^granwave sweep: rw.ini: case 1: ring-width: 1e-160 m is too small' sweep rw.ini --check
refused "a layer sweep's case of ring-width 1e-160 names the key (run)" \
    '^granwave sweep: rw.ini: case 1: ring-width: 1e-160 m is too small' sweep rw.ini --quiet
py_checks 1 <<PYEOF
refused("Python layer_impact(ring_width=1e-160) names ring_width", ["ring_width: 1e-160 m is too small"],
        granwave.layer_impact, sample="$tmp/s20", ring_width=1e-160)
PYEOF
cpu_run 60 "$GW" layer-impact --sample s20 --ring-width 1.5e-154 --t-max 0.002 --quiet >/dev/null 2>rw.err
rc=$?
[ $rc -eq 0 ] && grep -q "warning: ring-width: crowns 1.5e-154 m wide" rw.err &&
    ok "control: --ring-width 1.5e-154 runs, warned that no crown holds a centre" ||
    ko "control: --ring-width 1.5e-154: exit $rc, $(head -c 300 rw.err)"

# 2 a path longer than a path may be
long=$tmp
for _ in $(seq 1 22); do long=$long/$(printf 'd%.0s' {1..200}); done
len=${#long}
refused "chain --out of $len bytes says the path is too long" \
    "^granwave chain --out: the path is $len bytes long, more than the 4095 a path may hold: '" \
    chain --n 2 --quiet --out "$long"
refused "layer-impact --out of $len bytes says the path is too long" \
    "^granwave layer-impact --out: the path is $len bytes long, more than the 4095" \
    layer-impact --sample s20 --quiet --out "$long"
refused "layer-make --out FILE of $((len + 6)) bytes says the path is too long" \
    "^granwave layer-make --out: the path is $((len + 6)) bytes long, more than the 4095" \
    layer-make --n 2 --quiet --out "$long/s.txt"
[ ! -e "$tmp/d$(printf 'd%.0s' {1..199})" ] && ok "nothing made under the long path" ||
    ko "the long --out made directories"
# control: a long path within the bound is still a directory made and written
ok_dir=$tmp/$(printf 'e%.0s' {1..200})/$(printf 'f%.0s' {1..200})
cpu_run 60 "$GW" chain --n 2 --quiet --out "$ok_dir" >/dev/null 2>/dev/null && [ -s "$ok_dir/chain.json" ] &&
    ok "control: an --out of ${#ok_dir} bytes is written" || ko "control: an --out of ${#ok_dir} bytes"

# 3 numbers printed as zero in the studies' text
# field TEXT PATTERN: the first number after PATTERN in TEXT
field() { sed -n "s/.*$2 \\([-+0-9.e]*\\).*/\\1/p" <<<"$1" | head -1; }
# near A B: A within 1e-3 relative of B (both numbers)
near() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b != 0 && (a - b) / b < 1e-3 && (b - a) / b < 1e-3) }'; }
fj=$(cpu_run 60 "$GW" falcon --n 1:3 --heights none --vimp 1e-6 --jobs 1 --quiet --json 2>/dev/null)
ft=$(cpu_run 60 "$GW" falcon --n 1:3 --heights none --vimp 1e-6 --jobs 1 --quiet 2>/dev/null)
fm=$(/usr/bin/python3 -c 'import json,sys; print(json.loads(sys.argv[1])["velocities"][0]["f_max_mean"])' "$fj" 2>/dev/null)
vt=$(field "$ft" "v_imp"); ftm=$(field "$ft" "F_max")
near "$vt" 1e-6 && near "$ftm" "$fm" &&
    ok "falcon --vimp 1e-6 prints v_imp $vt m/s and F_max $ftm N (--json: $fm)" ||
    ko "falcon --vimp 1e-6 prints v_imp '$vt' and F_max '$ftm' N where --json has 1e-6 and $fm: $(grep v_imp <<<"$ft")"
ft0=$(cpu_run 60 "$GW" falcon --n 1:3 --heights none --jobs 1 --quiet 2>/dev/null)
grep -qE "v_imp 0\.3(000)? m/s: F_max 67\.45 N \(66\.39\.\.67\.98\)" <<<"$ft0" &&
    ok "control: the default falcon line at 0.3 m/s keeps 67.45 N (66.39..67.98)" ||
    ko "control: the falcon line at 0.3 m/s: $(grep v_imp <<<"$ft0")"
sj=$(cpu_run 60 "$GW" softwall --n 1:5 --vimp 1e-6 --jobs 1 --quiet --json 2>/dev/null)
st=$(cpu_run 60 "$GW" softwall --n 1:5 --vimp 1e-6 --jobs 1 --quiet 2>/dev/null)
fp=$(/usr/bin/python3 -c 'import json,sys; print(json.loads(sys.argv[1])["f_plateau"])' "$sj" 2>/dev/null)
fpt=$(grep -- "--kwall" <<<"$st" | awk '{ print $(NF-1) }')
near "$fpt" "$fp" && ok "softwall --vimp 1e-6 prints F_plateau $fpt N (--json: $fp)" ||
    ko "softwall --vimp 1e-6 prints F_plateau '$fpt' N where --json has $fp: $(grep -- --kwall <<<"$st")"

test_summary test_hostile_fortyninth
