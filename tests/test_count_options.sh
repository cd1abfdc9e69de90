#!/bin/bash
# test_count_options.sh GRANWAVE SRCDIR: a count held as a real. `dispersion
# --min-bins` counts frequency bins, but the library's table and its public
# struct hold it as a double (ABI 3): its help printed the range [1,
# 8.3886e+06] (8388605 taken above the printed end), and 1.5 or 30.5 bins ran,
# in the program, the library and Python. As an integer option the program
# refused '1.0', which Python's keyword takes (test_frontend_parity). It is now
# one kind of option and of table row, a count (GW_OPT_COUNT, GW_PARAM_COUNT):
# a real taken only when a whole number in its range, its range printed as
# integers.
#  1 the program takes the whole numbers Python takes, as integers or reals
#    (1.0, 30, 30.0, 3e1): exit 0, the settings say that number; 1.5, 30.5
#    and 1e-3 refused: exit 2, one line naming --min-bins and the integers it
#    takes, nothing written; 8388607 and 0 refused as outside [1, 8388606]
#  2 the text help prints the range as integers, [1, 8388606]; the JSON help
#    the same range, kind "integer", min 1 and max 8388606
#  3 Python (not in a sanitizer build): min_bins=1.0 and 30 run, min_bins=1.5
#    refused naming min_bins and the integers; granwave.params says "count";
#    the program's and Python's refusals of 1.5 give the same integers
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
BASE="dispersion --n 16 --t-samples 64"

# --- 1 whole numbers as integers or reals taken; others refused ---
for v in 1.0 30 30.0 3e1; do
    want=$(/usr/bin/python3 -c "print(int(float('$v')))")
    # shellcheck disable=SC2086
    if runs_json "--min-bins $v" "m.json" $BASE --min-bins "$v" --quiet; then
        got=$(jq_py m.json 'd["settings"]["spectrum"]["min_bins"]')
        [ "$got" = "$want" ] && ok "--min-bins $v: exit 0, min_bins $got" || ko "--min-bins $v: min_bins $got, not $want"
    fi
done
# shellcheck disable=SC2086
for v in 1.5 30.5 1.000001; do
    refused "--min-bins $v refused" "^granwave dispersion --min-bins: '$v' is not a whole number \(give an integer in \[1, 8388606\]\)$" \
        $BASE --min-bins "$v" --out "$tmp/o"
done
# shellcheck disable=SC2086
refused "--min-bins 8388607 (the integer above the end) refused" \
    '^granwave dispersion --min-bins: 8388607 is outside \[1, 8388606\]$' $BASE --min-bins 8388607 --out "$tmp/o"
# shellcheck disable=SC2086
refused "--min-bins 0 refused" '^granwave dispersion --min-bins: 0 is outside \[1, 8388606\]$' $BASE --min-bins 0 --out "$tmp/o"
# shellcheck disable=SC2086
refused "--min-bins 1e-3 refused" '^granwave dispersion --min-bins: 1e-3 is outside \[1, 8388606\]$' $BASE --min-bins 1e-3 --out "$tmp/o"

# --- 2 the help's range as integers, text and JSON alike ---
line=$("$GW" dispersion --help | grep -- '--min-bins')
case $line in
*", in [1, 8388606] [8]") ok "text help: --min-bins in [1, 8388606]";;
*) ko "text help: $line";;
esac
if "$GW" dispersion --help --json >h.json; then
    res=$(jq_py h.json '[(o["kind"], o["range"], o["min"], o["max"]) for o in d["options"] if o["name"] == "min-bins"]')
    [ "$res" = "[('integer', '[1, 8388606]', 1, 8388606)]" ] && ok "JSON help: --min-bins an integer in [1, 8388606]" ||
        ko "JSON help: $res"
else
    ko "dispersion --help --json: exit $?"
fi

# --- 3 Python: the same whole numbers and refusals ---
if sanitizer_build; then
    echo "SKIP: Python in a sanitizer build"
else
    lib=$(cd "$(dirname "$GW")" && pwd)/lib/libgranwave.so
    py=$(GRANWAVE_LIB=$lib PYTHONPATH=$SRC/python /usr/bin/python3 -W ignore -c '
import granwave
out = []
for v in (1.0, 30):
    r = granwave.dispersion(n=16, t_samples=64, min_bins=v)
    out.append("ran %r" % v)
try:
    granwave.dispersion(n=16, t_samples=64, min_bins=1.5)
    out.append("1.5 ran")
except ValueError as e:
    out.append(str(e))
out.append([p["type"] for p in granwave.params("dispersion") if p["keyword"] == "min_bins"][0])
print("|".join(out))' 2>&1)
    [ "$py" = "ran 1.0|ran 30|dispersion: min_bins: '1.5' is not a whole number (give an integer in [1, 8388606])|count" ] &&
        ok "Python: min_bins 1.0 and 30 run, 1.5 refused naming min_bins and [1, 8388606], its type a count" ||
        ko "Python: $py"
fi

test_summary test_count_options
