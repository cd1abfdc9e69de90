#!/bin/bash
# test_cli_refusals.sh GRANWAVE SRCDIR: the hardening classes of issue 18, each
# asserted by its behaviour (exit code, nothing written, no hang, no sanitizer
# report), not only by its message:
#  1 memory: a negative or absurd item of a --vimp / --heights / --radii list is
#    refused by the list parser itself (exit 2, the item named; before the fix
#    wavespeed printed it after freeing the list); falcon refuses the speeds
#    chain refuses, and a height whose fall under --gravity leaves them
#    (gw_chain_falcon_speeds; 5e7 mm at 1e4 m/s^2 ran at 31623 m/s).
#  2 unbounded work: dispersion --min-bins in [1, T/2 - 2] (above, no ridge can
#    be resolved); the column's --gamma <= 1e14, --alpha <= 1e8, --energy-tol <= 1
#    in every chain command and a chain sweep, and --restitution refused when it
#    needs a constant beyond them; falcon, wavespeed and softwall refuse a range
#    of N whose work (sum of N^2 x columns per N) exceeds 2e6, at once, before
#    --out is made.
#  3 special files: a FIFO or /dev/zero given as a sweep config, a layer sample,
#    a layer-stats table or FFTW wisdom is refused at once (exit 2 within 5 s,
#    one line naming the input), never read.
#  4 outputs: a refused run writes nothing in --out; an --out under a file or a
#    read-only directory is refused before the work; --wisdom never overwrites a
#    file that is not FFTW wisdom (exit 2, the file unchanged) and still writes
#    real wisdom; a file name too long for its temporary is refused before the
#    work.
#  5 tolerances outside [1e-15, 1e-4] are refused by every command (chain,
#    falcon, wavespeed, softwall, dispersion, drop, sweep); options with no effect
#    (--gamma without --damping kk, --alpha without hc, --restitution-v without
#    --restitution, softwall --sheets with --kwall / --sheet / --wall-material)
#    are refused, naming the option; so are, on the layer side, a --method the
#    solver does not offer, --rtol/--atol with a fixed-step solver, --clump-mass
#    without clumps and --until verdict with --full; a layer-make that does not
#    settle writes its sample marked converged 0 and warns on one line.
#  8 a misspelt sweep model is reported as such; "n = 5:1" as an empty range;
#    results written to a full device (/dev/full) exit 1 with "stdout: write
#    failed", never 0 nor "write failed: Success", and files written to a full
#    file system (a 64 KiB tmpfs, where mounting one is permitted) exit 1 with
#    "No space left on device"; layer-stats
#    refuses duplicated cases and bouncing rows without e_n, and warns about
#    undecided points.
set -u
GW=$1
SRC=${2:-.}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"

# --- 1: lists checked item by item inside the parser
refused "wavespeed --vimp with a negative item" 'wavespeed --vimp: item 2 is -0.3' wavespeed --vimp 0.1,-0.3 --out "$tmp/o"
refused "wavespeed --vimp with an absurd item" 'wavespeed --vimp: item 1 is 1e\+308' wavespeed --vimp 1e308 --out "$tmp/o"
refused "falcon --vimp refuses what chain refuses (2000 m/s)" 'falcon --vimp: item 2' falcon --n 1:2 --vimp 0.3,2000 --heights none --out "$tmp/o"
"$GW" chain --vimp 2000 >/dev/null 2>&1; [ $? -eq 2 ] && ok "chain --vimp 2000 refused (the shared bound)" || ko "chain --vimp 2000 not refused"
refused "falcon --heights beyond the shared speed bound" 'falcon --heights: item 1' falcon --n 1:2 --heights 1e12 --out "$tmp/o"
# a height's fall under the run's gravity: the table's row of heights holds the
# speeds at 9.81; 5e7 mm at 1e4 m/s^2 ran at 31623 m/s, 1 mm at 1e-300 at 4.5e-152
refused "falcon --heights 5e7 --gravity 1e4 (a fall of 31623 m/s)" \
    '^granwave falcon --heights: item 1 is 5e\+07 mm: at gravity 10000 m/s\^2 it falls to v = sqrt\(2 g h\) = 31622.8 m/s, outside the impact speeds \[1e-09, 1000\] m/s$' \
    falcon --n 1:2 --heights 5e7 --gravity 1e4 --out "$tmp/o"
refused "falcon --vimp 0.3 --heights 1 --gravity 1e-300 (a fall of 4.5e-152 m/s)" \
    '^granwave falcon --heights: item 1 is 1 mm: at gravity 1e-300 m/s\^2 it falls to v = sqrt\(2 g h\) = 4.47214e-152 m/s' \
    falcon --n 1:2 --vimp 0.3 --heights 1 --gravity 1e-300 --out "$tmp/o"
refused "chain --radii below a micron (the mass underflowed to 0)" 'chain --radii: item 1 is 1e-300, outside \[1e-06, 1\]' chain --n 2 --radii 1e-300,4e-3 --out "$tmp/o"
refused "chain --wall-material with --kwall (no effect)" 'chain --wall-material: has no effect with kwall' chain --n 3 --wall-material rigid --kwall 1e9 --out "$tmp/o"
refused "chain --rtol with the fixed-step rk4 (no effect)" 'chain --rtol: has no effect with the fixed-step rk4 solver' chain --n 3 --solver rk4 --rtol 1e-6 --out "$tmp/o"
refused "chain --dt-max 1e-12 (1.1e8 steps: minutes)" 'dt-max: a step of 1e-12 s needs about 1.1e\+08 steps' chain --n 3 --solver cvode --dt-max 1e-12 --out "$tmp/o"
refused "falcon --dt-max 1e-12: refused by the run, --out taken back" 'dt-max: a step of 1e-12 s' falcon --n 3:5 --dt-max 1e-12 --quiet --out "$tmp/o"
refused "dispersion --rtol with the fixed-step rk4 (no effect)" 'dispersion --rtol: has no effect with the fixed-step rk4 solver' dispersion --n 16 --t-samples 64 --solver rk4 --rtol 1e-6 --out "$tmp/o"
refused "chain --radii with a zero radius" 'radii: item 2 is 0' chain --n 3 --radii 4e-3,0,4e-3 --out "$tmp/o"

# --- 2: physical ranges (the parameter tables) and the work of a study over N,
# refused before anything is written and before any column runs
refused "dispersion --min-bins absurd" 'dispersion --min-bins: 1e9 is outside' dispersion --n 16 --t-samples 64 --min-bins 1e9 --out "$tmp/o"
refused "dispersion --min-bins above T/2 - 2 (nothing resolvable)" 'dispersion --min-bins: 31 is above 30, .* t-samples 64' dispersion --n 16 --t-samples 64 --min-bins 31 --out "$tmp/o"
"$GW" dispersion --n 16 --t-samples 64 --min-bins 30 >/dev/null 2>&1 && ok "dispersion --min-bins T/2 - 2 accepted" || ko "dispersion --min-bins 30 at 64 samples refused"
for cmd in "chain --n 2" "falcon --n 1:3 --heights none" "wavespeed --n 6:8 --vimp 0.3" "softwall --n 1:3" "drop --n 2 --t-max 2e-4"; do
    c=${cmd%% *}
    refused "$c --gamma above 1e14" "$c --gamma: 1.1e14 is outside" $cmd --damping kk --gamma 1.1e14 --out "$tmp/o"
    refused "$c --alpha 1e300" "$c --alpha: 1e300 is outside" $cmd --damping hc --alpha 1e300 --out "$tmp/o"
    refused "$c --energy-tol 1e300 (acted as off)" "$c --energy-tol: 1e300 is outside" $cmd --energy-tol 1e300 --out "$tmp/o"
done
"$GW" chain --n 2 --damping hc --alpha 1e8 --t-max 1e-3 >/dev/null 2>&1; rc=$?
[ $rc -le 1 ] && ok "chain --alpha 1e8 (the bound) runs (exit $rc: overdamped, the bead stays)" || ko "chain --alpha 1e8: exit $rc"
"$GW" chain --n 2 --energy-tol 1 >/dev/null 2>&1 && ok "chain --energy-tol 1 accepted" || ko "chain --energy-tol 1 refused"
refused "chain --restitution needing alpha above the bound" 'chain --restitution: e = 0.01 at 1e-07 m/s needs alpha above' chain --n 2 --damping hc --restitution 0.01 --restitution-v 1e-7 --out "$tmp/o"
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\ndamping = kk\ngamma = 1e15\n' >"$tmp/gamma.ini"
refused "sweep with gamma = 1e15" 'gamma: 1e\+15 is outside' sweep "$tmp/gamma.ini" --out "$tmp/o"
t0=$(date +%s)
refused "falcon --n 1:100000 (days of work)" 'falcon --n: 1:100000 at 5 columns per N' falcon --n 1:100000 --out "$tmp/o"
refused "wavespeed --n 5:100000" 'wavespeed --n: 5:100000 at 1 column' wavespeed --n 5:100000 --vimp 0.3 --out "$tmp/o"
refused "softwall --n 1:100000" 'softwall --n: 1:100000' softwall --n 1:100000 --out "$tmp/o"
refused "softwall --sheets --n 1:100 (9 walls)" 'softwall --n: 1:100 at 9 columns' softwall --sheets --n 1:100 --out "$tmp/o"
refused "falcon --n 1:182 at one speed (sum N^2 = 2026115)" 'falcon --n: 1:182' falcon --n 1:182 --heights none --out "$tmp/o"
[ $(( $(date +%s) - t0 )) -le 10 ] && ok "the study refusals took seconds" || ko "the study refusals took $(( $(date +%s) - t0 )) s"

# --- 3: special files
mkfifo "$tmp/fifo"
refused "sweep config is a FIFO" 'FIFO' sweep "$tmp/fifo" --out "$tmp/o"
refused "layer-impact --sample is a FIFO" 'sample.*FIFO' layer-impact --sample "$tmp/fifo" --out "$tmp/o"
refused "layer-impact --sample is /dev/zero" 'sample.*character device' layer-impact --sample /dev/zero --out "$tmp/o"
refused "layer-stats table is a FIFO" 'FIFO' layer-stats "$tmp/fifo" --out "$tmp/o"
refused "dispersion --wisdom is a FIFO" 'wisdom.*FIFO' dispersion --n 16 --t-samples 64 --wisdom "$tmp/fifo" --out "$tmp/o"
refused "dispersion --wisdom is /dev/zero" 'wisdom.*character device' dispersion --n 16 --t-samples 64 --wisdom /dev/zero --out "$tmp/o"
refused "layer-make --out is a FIFO" 'FIFO' layer-make --n 10 --width-rm 6 --t-max 0.05 --out "$tmp/fifo"
[ -p "$tmp/fifo" ] && ok "the FIFO is still a FIFO" || ko "layer-make replaced the FIFO"

# --- 4: outputs
echo "my notes" >"$tmp/notes.txt"
refused "--wisdom naming a file that is not wisdom" 'not FFTW wisdom' dispersion --n 16 --t-samples 64 --wisdom "$tmp/notes.txt"
[ "$(cat "$tmp/notes.txt")" = "my notes" ] && ok "that file is unchanged" || ko "--wisdom overwrote a file that is not wisdom"
"$GW" dispersion --n 16 --t-samples 64 --wisdom "$tmp/w.wis" >/dev/null 2>&1 && head -c 7 "$tmp/w.wis" | grep -q '(fftw-3' &&
    "$GW" dispersion --n 16 --t-samples 64 --wisdom "$tmp/w.wis" >/dev/null 2>&1 &&
    ok "--wisdom writes wisdom and reads it back" || ko "--wisdom round trip"
# wisdom of another FFTW (version, precision) or of another configuration of
# this one: said so, naming both, where it was told "is not FFTW wisdom"; still
# refused and left as it was. This build's preamble is the first line of the
# wisdom it just wrote ("(fftw-3.3.10 fftw_wisdom #x.. #x.. #x.. #x..").
own=$(head -n 1 "$tmp/w.wis")
own_ver=$(printf '%s' "$own" | cut -d' ' -f1 | tr -d '(')
sig=$(printf '%s' "$own" | cut -d' ' -f3-)
other_ver=fftw-3.3.9; [ "$own_ver" = fftw-3.3.9 ] && other_ver=fftw-3.3.8
printf '(%s fftw_wisdom %s\n)\n' "$other_ver" "$sig" >"$tmp/old.wis"
printf '(%s fftwf_wisdom %s\n)\n' "$own_ver" "$sig" >"$tmp/single.wis"
printf '(%s fftw_wisdom #x1 #x2 #x3 #x4\n)\n' "$own_ver" >"$tmp/config.wis"
for f in old single config; do cp "$tmp/$f.wis" "$tmp/$f.keep"; done
refused "--wisdom of $other_ver (another version), both versions named" \
    "^granwave dispersion --wisdom: '$tmp/old.wis' is FFTW wisdom of another FFTW version or precision \($other_ver, double precision\) than this build's \($own_ver, double precision\); refusing to overwrite it\$" \
    dispersion --n 16 --t-samples 64 --wisdom "$tmp/old.wis"
refused "--wisdom of single precision (fftwf_wisdom), both precisions named" \
    "is FFTW wisdom of another FFTW version or precision \($own_ver, single precision\) than this build's \($own_ver, double precision\)" \
    dispersion --n 16 --t-samples 64 --wisdom "$tmp/single.wis"
refused "--wisdom of this version from another configuration (its planner's signature)" \
    "is FFTW wisdom of $own_ver \(double precision\) from another configuration of it \(its planner's signature '#x1 #x2 #x3 #x4', this build's" \
    dispersion --n 16 --t-samples 64 --wisdom "$tmp/config.wis"
cmp -s "$tmp/old.wis" "$tmp/old.keep" && cmp -s "$tmp/single.wis" "$tmp/single.keep" &&
    cmp -s "$tmp/config.wis" "$tmp/config.keep" && ok "  the three wisdom files are unchanged" ||
    ko "  --wisdom overwrote another FFTW's wisdom"
# a name too long for its temporary (NAME.tmp.HOST.PID.XXXXXX above the
# directory's 255): refused before the run, where dispersion ran and then said
# "cannot create: File name too long" (exit 0, nothing saved); 200 characters
# still written
long=$(printf 'w%.0s' $(seq 1 240))
refused "--wisdom with a 240-character name (its temporary above NAME_MAX)" 'wisdom.*too long a name.*at most' \
    dispersion --n 16 --t-samples 64 --wisdom "$tmp/$long" --out "$tmp/o"
[ ! -e "$tmp/$long" ] && ! ls "$tmp" | grep -q "^www.*tmp" && ok "  nothing written beside it" || ko "  wrote $tmp/$long"
refused "layer-make --out with a 240-character name" 'layer-make --out.*too long a name' \
    layer-make --n 10 --width-rm 6 --t-max 0.05 --out "$tmp/$long"
"$GW" dispersion --n 16 --t-samples 64 --wisdom "$tmp/${long:0:200}" >/dev/null 2>&1 &&
    head -c 7 "$tmp/${long:0:200}" | grep -q '(fftw-3' && ok "--wisdom with a 200-character name is written" ||
    ko "--wisdom with a 200-character name"
# a missing --out is named as every other flag is, after the command's name
# (the thirty-second pass: "granwave layer-make: --out: ...")
refused "layer-make without --out" '^granwave layer-make --out: the sample file to write is required$' \
    layer-make --n 10 --width-rm 6 --json
# an empty file (touch, mktemp) holds nothing to lose: taken as no wisdom and
# written at the end, as an absent one (it was refused as "not FFTW wisdom")
# (64 beads over 256 samples: enough wavenumbers below qa = 0.5 for c0, so
# the run says nothing on stderr)
: >"$tmp/empty.wis"
"$GW" dispersion --n 64 --t-samples 256 --wisdom "$tmp/empty.wis" --quiet --json >"$tmp/ew.json" 2>"$tmp/ew.err" &&
    [ ! -s "$tmp/ew.err" ] && head -c 7 "$tmp/empty.wis" | grep -q '(fftw-3' &&
    /usr/bin/python3 -c 'import json, sys; sys.exit(json.load(open(sys.argv[1]))["settings"].get("fftw_wisdom_fnv1a64") is not None)' "$tmp/ew.json" &&
    ok "--wisdom on an empty file: no wisdom read, wisdom written" || ko "--wisdom on an empty file: $(head -c 200 "$tmp/ew.err")"
# the settings name the wisdom a run planned over: FNV-1a 64 of the bytes read
# (computed here independently), null when there was none
wis_hash=$(/usr/bin/python3 -c "
import sys
h = 14695981039346656037
for b in open(sys.argv[1], 'rb').read():
    h = ((h ^ b) * 1099511628211) % (1 << 64)
print('%016x' % h)" "$tmp/w.wis")
got=$("$GW" dispersion --n 16 --t-samples 64 --wisdom "$tmp/w.wis" --json 2>/dev/null |
    /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin)['settings']['spectrum']['fftw_wisdom_fnv1a64'])")
none=$("$GW" dispersion --n 16 --t-samples 64 --json 2>/dev/null |
    /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin)['settings']['spectrum']['fftw_wisdom_fnv1a64'])")
[ -n "$wis_hash" ] && [ "$got" = "$wis_hash" ] && [ "$none" = "None" ] &&
    ok "the settings record the wisdom read ($got) and null without --wisdom" ||
    ko "settings' fftw_wisdom_fnv1a64: '$got' for wisdom hashing to '$wis_hash', '$none' without"
refused "layer-make --out naming a file that is not a sample" "layer-make --out: '$tmp/notes.txt' exists and is not a granwave sample" layer-make --n 10 --width-rm 6 --t-max 0.05 --out "$tmp/notes.txt"
[ "$(cat "$tmp/notes.txt")" = "my notes" ] && ok "that file is unchanged" || ko "layer-make overwrote a file that is not a sample"
"$GW" layer-make --n 10 --width-rm 6 --t-max 0.05 --out "$tmp/s1.txt" >/dev/null 2>&1 &&
    "$GW" layer-make --n 10 --width-rm 6 --t-max 0.05 --seed 2 --out "$tmp/s1.txt" >/dev/null 2>&1 &&
    grep -q -- '--seed 2' "$tmp/s1.txt" && ok "layer-make replaces a sample it wrote before" ||
    ko "layer-make did not replace its own sample"
refused "chain --out under a regular file" '[Nn]ot a directory' chain --n 2 --out "$tmp/notes.txt/sub"
mkdir "$tmp/ro"; chmod 555 "$tmp/ro"
if [ "$(id -u)" -ne 0 ]; then
    refused "chain --out in a read-only directory" 'cannot write' chain --n 2 --out "$tmp/ro/x"
else
    echo "SKIP: read-only directory (running as root)"
fi
refused "layer-make --out in a missing directory, before the run" 'directory' layer-make --n 10 --width-rm 6 --out "$tmp/missing/s.txt"
refused "layer-stats --out under a file, before reading" '[Nn]ot a directory' layer-stats "$SRC/data/measured/layer_walls/results.csv" --out "$tmp/notes.txt/x"
# a directory that refuses new files: read-only for a user; as root (whom the
# mode does not stop) a new name under /proc, where nothing can be created
if [ "$(id -u)" -ne 0 ]; then unw="$tmp/ro/stats"; else unw="/proc/granwave-stats-$$"; fi
refused "layer-stats --out in a directory that refuses new files, before the analysis" 'layer-stats --out: cannot write into' \
    layer-stats "$SRC/data/measured/layer_walls/results.csv" --out "$unw"
[ ! -s "$tmp/stdout" ] && [ ! -e "$unw" ] && ok "  no statistics printed, nothing made" || ko "layer-stats printed or made something on a refused --out"
refused "layer-stats with a missing table writes no --out" 'layer-stats.*missing.csv' layer-stats "$tmp/missing.csv" --out "$tmp/o"

# --- 5: tolerances and options with no effect
for cmd in "chain --n 2" "falcon --n 1:2 --heights none" "wavespeed --n 6:8 --vimp 0.3" "softwall --n 1:3" "dispersion --n 16 --t-samples 64" "drop --n 2 --t-max 2e-4"; do
    c=${cmd%% *}
    refused "$c --rtol 1" "$c --rtol: 1 is outside" $cmd --rtol 1 --out "$tmp/o"
    refused "$c --atol 1" "$c --atol: 1 is outside" $cmd --atol 1 --out "$tmp/o"
    refused "$c --rtol 1e-2 (17 % off)" "$c --rtol" $cmd --rtol 1e-2 --out "$tmp/o"
done
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\nrtol = 0.5\n' >"$tmp/tol.ini"
refused "sweep with rtol = 0.5" 'rtol' sweep "$tmp/tol.ini" --out "$tmp/o"
"$GW" chain --n 2 --rtol 1e-4 --atol 1e-4 >/dev/null 2>&1 && ok "chain --rtol 1e-4 accepted (the bound)" || ko "chain --rtol 1e-4 refused"
refused "chain --gamma without damping" 'chain --gamma: has no effect' chain --n 2 --gamma 3 --out "$tmp/o"
refused "chain --alpha with kk" 'chain --alpha: has no effect' chain --n 2 --damping kk --alpha 0.1 --out "$tmp/o"
refused "chain --gamma with --restitution" 'chain --gamma' chain --n 2 --damping kk --gamma 1 --restitution 0.9 --out "$tmp/o"
refused "chain --restitution-v without --restitution" 'restitution-v' chain --n 2 --restitution-v 0.3 --out "$tmp/o"
refused "softwall --sheets --kwall" 'softwall --kwall: has no effect with --sheets' softwall --sheets --kwall 1e9 --out "$tmp/o"
refused "softwall --sheets --sheet" 'softwall --sheet: has no effect' softwall --sheets --sheet brass --out "$tmp/o"
refused "softwall --wall-material (the wall is --kwall)" 'softwall --wall-material' softwall --wall-material brass --out "$tmp/o"
"$GW" chain --n 2 --damping kk --gamma 1 >/dev/null 2>&1 && ok "chain --damping kk --gamma accepted" || ko "chain --damping kk --gamma refused"
# the layer side: a method the backend does not offer, tolerances of a
# fixed-step solver, a clump mass without clumps; refused before any output
# (before the sample is read for the first, before the run for the others)
"$GW" layer-make --n 20 --width-rm 10 --seed 4 --t-max 0.3 --out "$tmp/L.txt" >/dev/null 2>&1 || ko "layer-make for the layer refusals"
# class 5: a sample with two discs deep inside each other (here one disc twice)
# is refused when read, naming the pair; the sample itself is accepted (the
# copy made by hand: without layer-make's settings line, whose n it breaks)
awk '/^# settings:/ {next} /^n /{print "n", $2 + 1; next} {print} /^[0-9]/ && NF == 3 && !d {print; d = 1}' "$tmp/L.txt" >"$tmp/Ldup.txt"
refused "a sample with two coincident discs" "overlap by 2 R_p, above 0.05 R_p" layer-impact --sample "$tmp/Ldup.txt" --t-max 1e-4 --out "$tmp/o"
"$GW" layer-impact --sample "$tmp/L.txt" --t-max 1e-4 >/dev/null 2>&1 && ok "the same sample without the copy runs" || ko "the sample without the copy refused"
refused "layer-impact --method bdf with verlet" "layer-impact --method: 'bdf' has no effect with the verlet solver" layer-impact --sample "$tmp/L.txt" --method bdf --out "$tmp/o"
refused "layer-impact --solver cvode --method erk" "layer-impact --method: 'erk' has no effect with the cvode solver" layer-impact --sample "$tmp/L.txt" --solver cvode --method erk --out "$tmp/o"
refused "layer-impact --rtol with verlet" 'layer-impact --rtol: has no effect with the fixed-step verlet solver' layer-impact --sample "$tmp/L.txt" --rtol 1e-6 --out "$tmp/o"
refused "layer-impact --exact --atol (rk4)" 'layer-impact --atol: has no effect with the fixed-step rk4 solver' layer-impact --sample "$tmp/L.txt" --exact --atol 1e-6 --out "$tmp/o"
refused "layer-impact --clump-mass on a disc sample" 'layer-impact --clump-mass: has no effect: the sample .* has no clumps' layer-impact --sample "$tmp/L.txt" --clump-mass union --out "$tmp/o"
refused "layer-impact --until verdict --full" 'layer-impact --until: verdict has no effect with full' layer-impact --sample "$tmp/L.txt" --until verdict --full --out "$tmp/o"
refused "layer-make --clump-mass without --clumps" 'layer-make --clump-mass: has no effect without clumps' layer-make --n 10 --clump-mass union --out "$tmp/cm.txt"
[ -e "$tmp/cm.txt" ] && ko "layer-make --clump-mass without --clumps wrote its sample"
printf '[sweep]\nmodel = layer\n[grid]\npoint = 0:1\n[params]\nsample = %s\npoints = 2\nrtol = 1e-6\n' "$tmp/L.txt" >"$tmp/ltol.ini"
refused "layer sweep with rtol and the verlet default" 'rtol: has no effect' sweep "$tmp/ltol.ini" --out "$tmp/o"
"$GW" layer-impact --sample "$tmp/L.txt" --solver cvode --rtol 1e-6 --t-max 1e-4 >/dev/null 2>&1 && ok "layer-impact --solver cvode --rtol accepted" || ko "layer-impact --solver cvode --rtol refused"
# a layer-make that does not settle still writes its sample, recorded as such, and says so on one stderr line
"$GW" layer-make --n 20 --width-rm 10 --seed 4 --t-max 0.01 --out "$tmp/U.txt" --quiet --json >"$tmp/U.json" 2>"$tmp/U.err"; rc=$?
if [ $rc -eq 0 ] && [ "$(wc -l <"$tmp/U.err")" -eq 1 ] && grep -q 'warning: the sample did not settle' "$tmp/U.err" \
    && grep -q 'converged 0' "$tmp/U.txt" && grep -q '"converged":[[:space:]]*false' "$tmp/U.json"; then
    ok "layer-make not settled: exit 0, sample written with converged 0, one warning line"
else
    ko "layer-make not settled: exit $rc, $(cat "$tmp/U.err")"
fi

# the layer commands' bounds on work and memory, and their file inputs: refused
# before anything is allocated or written (the --out directory is not left behind)
refused "layer-impact --dt 1e-12 (5e10 steps)" 'dt: a step of 1e-12 s takes 5e\+10 steps' layer-impact --sample "$tmp/L.txt" --dt 1e-12 --t-max 0.05 --out "$tmp/o"
refused "layer-impact --rings 1000 with 2e6 samples (64 GB)" 'dt-out: .* GB of series' layer-impact --sample "$tmp/L.txt" --rings 1000 --t-max 40 --out "$tmp/o"
refused "layer-make --dt 1e-12 (6e12 steps)" 'dt: a step of 1e-12 s' layer-make --n 10 --dt 1e-12 --out "$tmp/o"
refused "layer-impact --t-max above 1000 s" 'layer-impact --t-max: 2000 is outside' layer-impact --sample "$tmp/L.txt" --t-max 2000 --out "$tmp/o"
refused "layer-impact --skin above 1e6 m" 'layer-impact --skin: 1e\+07 is outside' layer-impact --sample "$tmp/L.txt" --skin 1e7 --out "$tmp/o"
mkdir "$tmp/adir"; : >"$tmp/empty.txt"
refused "layer-impact --sample is a directory" 'sample.*directory' layer-impact --sample "$tmp/adir" --out "$tmp/o"
refused "layer-impact --sample is empty" 'empty file' layer-impact --sample "$tmp/empty.txt" --out "$tmp/o"
refused "layer-impact --out is /dev/full" 'not a directory' layer-impact --sample "$tmp/L.txt" --t-max 1e-3 --out /dev/full
refused "layer-make --out is /dev/zero" 'character device' layer-make --n 10 --out /dev/zero
refused "layer-make --out is a directory" 'directory' layer-make --n 10 --out "$tmp/adir"
# unwritable even for root: a directory under /proc takes no new files
refused "layer-make --out under /proc, before the run" "layer-make --out: cannot write into '/proc'" layer-make --n 10 --out /proc/granwave_no.txt
refused "layer-impact --out under /proc, before the run" "layer-impact --out: cannot write into '/proc'" layer-impact --sample "$tmp/L.txt" --t-max 1e-3 --out /proc/granwave_no
refused "layer-stats table is /dev/zero" 'character device' layer-stats /dev/zero --out "$tmp/o"
refused "sweep config is /dev/zero" 'character device' sweep /dev/zero --out "$tmp/o"
"$GW" layer-impact --sample "$tmp/L.txt" --dt 0 --t-max 1e-4 >/dev/null 2>&1 && ok "layer-impact --dt 0 (auto, as its help says) accepted" ||
    ko "layer-impact --dt 0 refused"

# --- 8: smaller gaps
printf '[sweep]\nmodel = chian\n[grid]\nn = 1:2\n' >"$tmp/m.ini"
refused "misspelt sweep model" "m.ini:2: unknown model 'chian'" sweep "$tmp/m.ini" --out "$tmp/o"
printf '[sweep]\nmodel = chain\n[grid]\nn = 5:1\n' >"$tmp/r.ini"
refused "n = 5:1 is an empty range" "r.ini:4: n: range '5:1' is empty" sweep "$tmp/r.ini" --out "$tmp/o"
if [ -w /dev/full ]; then
    # results to a full device: exit 1 with the reason, never exit 0 or "Success"
    for args in "chain --n 2 --json" "chain --n 2" "layer-stats $SRC/data/measured/layer_walls/results.csv --json"; do
        "$GW" $args >/dev/full 2>"$tmp/full.err"; rc=$?
        if [ $rc -eq 1 ] && grep -q "stdout: write failed" "$tmp/full.err" && ! grep -q Success "$tmp/full.err"; then
            ok "granwave $args >/dev/full: exit 1, 'stdout: write failed' (not 'Success')"
        else
            ko "granwave $args >/dev/full: exit $rc: $(cat "$tmp/full.err")"
        fi
    done
else
    echo "SKIP: /dev/full not available"
fi
# files written to a full file system (a 64 KiB tmpfs, when this user may mount
# one): exit 1 naming the file and "No space left", never "Success" nor exit 0,
# and no half-written result left under its own name
mkdir -p "$tmp/full"
if mount -t tmpfs -o size=64k tmpfs "$tmp/full" 2>/dev/null; then
    trap 'umount "$tmp/full" 2>/dev/null; rm -rf "$tmp"' EXIT
    dd if=/dev/zero of="$tmp/full/fill" bs=1k count=64 2>/dev/null
    for args in "chain --n 5 --out $tmp/full/ch" "layer-make --n 20 --width-rm 10 --seed 4 --t-max 0.01 --out $tmp/full/s.txt" \
                "layer-impact --sample $tmp/L.txt --t-max 1e-3 --out $tmp/full/imp" \
                "layer-stats $SRC/data/measured/layer_walls/results.csv --out $tmp/full/st"; do
        "$GW" $args >/dev/null 2>"$tmp/fs.err"; rc=$?
        if [ $rc -eq 1 ] && grep -q 'No space left on device' "$tmp/fs.err" && ! grep -q Success "$tmp/fs.err" \
            && [ ! -s "$tmp/full/s.txt" ] && [ ! -e "$tmp/full/imp/ledger.csv" ] && [ ! -e "$tmp/full/st/groups.csv" ]; then
            ok "granwave ${args%% *} to a full file system: exit 1, 'No space left on device'"
        else
            ko "granwave ${args%% *} to a full file system: exit $rc: $(tail -1 "$tmp/fs.err")"
        fi
        rm -rf "$tmp/full/ch" "$tmp/full/s.txt" "$tmp/full/imp" "$tmp/full/st"
    done
    umount "$tmp/full"
else
    echo "SKIP: cannot mount a small tmpfs (not permitted here); /dev/full covers stdout"
fi
h="# granwave test\ncase,rb-rm,point,x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,dissipated_first_contact,block_loss_first_contact,energy_error,wave_speed,t_end,steps"
row() { echo "$1,1,$2,0,$3,$4,0.5,10,1,0.5,0.5,0.01,0.1,0.1,0.1,1e-6,100,0.05,1000"; }
{ echo -e "$h"; row 0 0 1 0.5; row 1 1 0 nan; row 1 2 1 0.5; } >"$tmp/dup.csv"
refused "layer-stats refuses a duplicated case" 'case 1 appears more than once' layer-stats "$tmp/dup.csv" --out "$tmp/o"
{ echo -e "$h"; row 0 0 1 0.5; row 1 1 1 nan; } >"$tmp/nan.csv"
refused "layer-stats refuses a bouncing row without e_n" 'case 1 bounced but its e_n is nan' layer-stats "$tmp/nan.csv" --out "$tmp/o"
{ echo -e "$h"; row 0 0 1 0.5; row 1 1 nan nan; row 2 2 0 nan; } >"$tmp/und.csv"
"$GW" layer-stats "$tmp/und.csv" --json >"$tmp/und.json" 2>"$tmp/und.err"; rc=$?
if [ $rc -eq 0 ] && grep -q "1 point(s) with bounced = nan" "$tmp/und.err" && grep -q '"n_valid":[[:space:]]*2' "$tmp/und.json"; then
    ok "layer-stats warns about an undecided point and records n_valid = 2 of 3"
else
    ko "layer-stats undecided point: exit $rc, $(cat "$tmp/und.err")"
fi
# tables with the first free-flight maximum (issue 18, class 7): a bouncing row
# whose run ended before T_f has e_n = e = alpha_r = nan and its e_n_first; it
# counts in the share and is left out of the e_n statistics with a warning; a
# bouncing row without its e_n_first is refused
h2="$h,e_n_first,e_first,alpha_r_first,v_nr_first,v_r_first,t_leave,t_rebound,t_f"
row2() { echo "$(row "$1" "$2" "$3" "$4"),$5,0.5,10,0.5,1,0.002,0.002,0.1"; }
# (case 2 did not bounce: nan at every rebound column, as the model writes it;
# layer-stats refuses a number there in a table with e_n_first)
{ echo -e "$h2"; row2 0 0 1 0.5 0.4; row2 1 1 1 nan 0.3
  echo "2,1,2,0,0,nan,nan,nan,1,nan,nan,0.01,0.1,0.1,0.1,1e-6,100,0.05,1000,nan,nan,nan,nan,nan,nan,nan,nan"; } >"$tmp/cut.csv"
sed -i '4s/,0.5,10,1,0.5,0.5,0.01,/,nan,nan,1,nan,nan,0.01,/' "$tmp/cut.csv" # row of case 1 (line 4, after the comment and the header): e, alpha_r, v_nr, v_r nan
"$GW" layer-stats "$tmp/cut.csv" --json >"$tmp/cut.json" 2>"$tmp/cut.err"; rc=$?
if [ $rc -eq 0 ] && [ "$(wc -l <"$tmp/cut.err")" -eq 1 ] && grep -q "1 bouncing point(s) with e = nan" "$tmp/cut.err" \
    && /usr/bin/python3 -c "import json,sys; g=json.load(open('$tmp/cut.json'))['groups']; sys.exit(0 if len(g)==1 and g[0]['n_bounced']==2 and g[0]['e']['n']==1 and g[0]['e_n_first']['n']==2 and abs(g[0]['e_n_first']['mean']-0.35)<1e-12 else 1)"; then
    ok "layer-stats: a bouncing row cut before T_f counts in the share, not in e_n (one warning), e_n_first over both"
else
    ko "layer-stats rows cut before T_f: exit $rc, $(cat "$tmp/cut.err")"
fi
{ echo -e "$h2"; row2 0 0 1 0.5 0.4; row2 1 1 1 0.5 nan; } >"$tmp/nofirst.csv"
refused "layer-stats refuses a bouncing row without e_n_first" 'case 1 bounced but its e_n_first is nan' layer-stats "$tmp/nofirst.csv" --out "$tmp/o"
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
