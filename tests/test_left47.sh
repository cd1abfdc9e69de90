#!/bin/bash
# test_left47.sh GRANWAVE SRCDIR: what the forty-seventh pass left, asserted
# through the program.
#  1 `dispersion --min-bins` (a control): a run keeps its resolved ridges at B
#    bins up. The option is a count held as a real (test_count_options): as an
#    integer option the program refused '1.0', which Python's keyword (a double
#    in the library's table and its public struct) takes.
#  2 `layer-stats --fit ...,tan_gamma` warned "tan_gamma at an end of [tan
#    1e-6 deg, tan 89 deg]" without saying which; beta and a/b likewise. The
#    warning now names the end of every parameter on its edge, checked against
#    the fitted value in the JSON (a lower end named only where the value is
#    there, the upper end of beta with its value, the smallest R_b/R_m).
#  3 `wavespeed --n 5:12 --vimp 0.01,0.3 --gravity 1e3`: the beta line gave
#    its own reason "(n/a: undecided, columns held by gravity)" beside the held
#    columns' warning: it now says, as the period line does, that the warning
#    says why; the warning is printed once and the JSON is the same.
#  4 `layer-impact --out NEW` that failed (exit 1) before a snapshot of it was
#    placed left the empty NEW it made (a snapshot_0.vtk that cannot be
#    written: a file-size limit of 0, SIGXFSZ ignored): it now takes back
#    the directories it made while they are empty; an --out that existed
#    stays as it was, and a run that fails later keeps its snapshots.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# tree DIR: what DIR holds (recursively), one line; "-" when it does not exist
tree() { if [ -e "$1" ]; then (cd "$1" && find . -mindepth 1 | sort | tr '\n' ' '); else echo -; fi; }

# --- 1 dispersion --min-bins: a run keeps its resolved ridges at B bins up ---
# a run: every resolved ridge lies at 30 bins or more, the settings say 30
if runs_json "dispersion --min-bins 30" d.json dispersion --n 64 --t-samples 256 --min-bins 30 --quiet; then
    res=$(jq_py d.json '(d["settings"]["spectrum"]["min_bins"] == 30, d["n_resolved"] > 0 and all(w / d["d_omega"] >= 30 - 1e-9 for w, r in zip(d["omega_ridge"], d["resolved"]) if r))' 2>&1)
    [ "$res" = "(True, True)" ] && ok "dispersion --min-bins 30: min_bins 30, each resolved ridge at 30 bins or more" ||
        ko "dispersion --min-bins 30: $res"
fi

# --- 2 layer-stats: which end of its box each parameter is on ---
tab="$SRC/data/measured/layer_diagram/results.csv"
# edge_named WHAT ARGS...: stderr's and the JSON's warning name, for every
# parameter at_bound lists, the end its fitted value is at
edge_named() {
    local what=$1; shift
    runs_json "$what" l.json layer-stats "$tab" "$@" || return
    local res
    res=$(/usr/bin/python3 - l.json "$tmp/stderr" <<'PYEOF'
import json, math, sys
d = json.load(open(sys.argv[1]))
err = [l.split("warning: ", 1)[1].rstrip("\n") for l in open(sys.argv[2]) if "warning: " in l]
f = d["diagrams"][0]["fit"]
w = [x for x in d["warnings"] if "stopped at the edge of its box" in x]
bad = []
if len(w) != 1 or err != d["warnings"]:
    bad.append("warnings %s, stderr %s" % (w, err))
text = w[0] if w else ""
ends = {"beta": (0.0, None), "a_over_b": (1e-6, 1e6), "tan_gamma": (math.tan(math.radians(1e-6)), math.tan(math.radians(89)))}
label = {"beta": "beta", "a_over_b": "a/b", "tan_gamma": "tan_gamma"}
for p in f["at_bound"]:
    if p == "offset":
        if f["offset"] != 0 or "offset at 0" not in text:
            bad.append("offset %s" % f["offset"])
        continue
    v, (lo_, hi_) = f[p], ends[p]
    at_lo = abs(v - lo_) <= 1e-5 * (lo_ if lo_ > 0 else 1) if p != "beta" else v == 0
    named = "%s at its %s end" % (label[p], "lower" if at_lo else "upper")
    if named not in text:
        bad.append("%s = %g: '%s' not said" % (p, v, named))
    if p == "beta" and not at_lo and "the smallest R_b/R_m (%.4g)" % v not in text:
        bad.append("beta's upper end without its value %g" % v)
    if "at an end" in text:
        bad.append("'at an end' still said")
print("PASS" if f["at_bound"] and not bad else "FAIL: %s %s" % (f["at_bound"], bad))
PYEOF
)
    [ "$res" = PASS ] && ok "$what: the warning names the end of each of $(jq_py l.json 'd["diagrams"][0]["fit"]["at_bound"]')" ||
        ko "$what: $res"
}
edge_named "layer-stats --fit beta,a_over_b,tan_gamma" --fit beta,a_over_b,tan_gamma
edge_named "layer-stats --delta-rm 1e6" --delta-rm 1e6
edge_named "layer-stats --gamma-deg 89" --gamma-deg 89
edge_named "layer-stats --fit beta,a_over_b,offset" --fit beta,a_over_b,offset

# --- 3 wavespeed under gravity 1e3: the beta line defers to the warning ---
if timeout -s KILL 120 "$GW" wavespeed --n 5:12 --vimp 0.01,0.3 --gravity 1e3 --quiet >ws.txt 2>ws.err &&
    timeout -s KILL 120 "$GW" wavespeed --n 5:12 --vimp 0.01,0.3 --gravity 1e3 --quiet --json >ws.json 2>wsj.err; then
    beta=$(grep '^  beta:' ws.txt)
    [[ $beta == *"(n/a: the warning says why)" ]] && ! grep -q 'held by gravity' ws.txt &&
        [ "$(grep -c 'warning: .*held by gravity' ws.err)" = 1 ] &&
        ok "wavespeed --gravity 1e3: beta n/a, 'the warning says why', the held warning once (stderr)" ||
        ko "wavespeed --gravity 1e3: '$beta'; stdout held: $(grep -c 'held by gravity' ws.txt), stderr: $(grep -c 'held by gravity' ws.err)"
    res=$(/usr/bin/python3 - ws.json ws.err <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[1]))
err = [l.split("warning: ", 1)[1].rstrip("\n") for l in open(sys.argv[2]) if "warning: " in l]
ok = err == d["warnings"] and any("held by gravity" in w for w in d["warnings"]) and d["fits"]["tq"]["beta"] is None and d["n_held"] > 0
print("PASS" if ok else "FAIL: %s / %s / %s" % (d["warnings"], err, d.get("beta")))
PYEOF
)
    [ "$res" = PASS ] && ok "wavespeed --gravity 1e3 --json: fits.tq.beta null, n_held > 0, the text's warnings are the JSON's" ||
        ko "wavespeed --gravity 1e3 --json: $res"
else
    ko "wavespeed --n 5:12 --vimp 0.01,0.3 --gravity 1e3: exit $? ($(head -c 300 ws.err))"
fi

# --- 4 layer-impact --out after a failure before its first snapshot ---
"$GW" layer-make --n 20 --width-rm 10 --seed 1 --out s.txt --quiet >/dev/null 2>&1 || ko "layer-make"
# unwritable OUT: layer-impact into OUT under a file-size limit of 0 (SIGXFSZ
# ignored: the write fails, EFBIG); stderr through a pipe (no limit there);
# sets rc and msg
unwritable() {
    msg=$( (trap '' XFSZ; ulimit -f 0; timeout -s KILL 120 "$GW" layer-impact --sample s.txt --out "$1" --quiet \
        2>&1 >/dev/null; echo "rc=$?") | cat)
    rc=${msg##*rc=}
    msg=${msg%rc=*}
}
rm -rf N
unwritable N/a
[ "$rc" = 1 ] && [[ $msg == *"snapshot_0.vtk: write failed"* ]] && [ "$(tree N)" = - ] &&
    ok "layer-impact --out N/a, snapshot_0.vtk unwritable: exit 1 naming it, no N left" ||
    ko "layer-impact --out N/a, snapshot_0.vtk unwritable: exit $rc ($msg), N holds: $(tree N)"
rm -rf N && mkdir N
unwritable N/a/b/
[ "$rc" = 1 ] && [ "$(tree N)" = "" ] &&
    ok "layer-impact --out N/a/b/ (N existing), snapshot_0.vtk unwritable: exit 1, N as it was (empty)" ||
    ko "layer-impact --out N/a/b/ (N existing): exit $rc ($msg), N holds: $(tree N)"
rm -rf E && mkdir E && echo keep >E/mine.txt
unwritable E
[ "$rc" = 1 ] && [ "$(tree E)" = "./mine.txt " ] && ok "layer-impact --out E (existing), unwritable: E as it was" ||
    ko "layer-impact --out E (existing): exit $rc ($msg), E holds: $(tree E)"
# control: a run failing after its first snapshot keeps the snapshots in what it made
rm -rf N
timeout -s KILL 120 "$GW" layer-impact --sample s.txt --energy-tol 1e-16 --out N/a --quiet >/dev/null 2>&1
rc=$?
[ $rc = 1 ] && [ "$(tree N)" = "./a ./a/snapshot_0.vtk ./a/snapshot_failure.vtk " ] &&
    ok "control: layer-impact --energy-tol 1e-16 --out N/a: exit 1, its snapshots kept" ||
    ko "control: layer-impact --energy-tol 1e-16 --out N/a: exit $rc, N holds: $(tree N)"

test_summary test_left47
