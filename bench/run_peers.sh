#!/bin/bash
# bench/run_peers.sh [BUILD_DIR]: time to solution of the 40-bead Falcon column
# (and, last, the 2D layer against LAMMPS: bench_layer_peer.sh)
# (v_imp = 0.3 m/s, steel: k, K, m of gw_chain_params_default) at 1e-6 relative
# accuracy on F_max and tau_N, for granwave's backends (bench_tts) and the peers
# that are installed: SciPy solve_ivp (DOP853, LSODA; Debian python3-scipy) and
# LAMMPS (Debian lammps: pair granular hertz + fix wall/gran, after a one-bead
# check of the force law against the closed form tau_1). Prints measurements
# only (never pass/fail) and a table with ratio = granwave best / peer time,
# all measured in this run (the machine is shared: compare ratios, not seconds).
# Environment: ACC (default 1e-6), REPS (default 3), LMP (LAMMPS binary),
# DT_OUT (granwave sampling interval, s, default 1e-4: events only in between,
# as the peers, which are not sampled in their timed runs either; 0 = the
# gw_chain_collide default tau_1/200, on which rk4 then lands every step).
set -euo pipefail
# shellcheck source=bench/bench_lib.sh
. "$(dirname "$0")/bench_lib.sh" # (before the cd: it records the caller's directory)
bench_args 1 "$@"
bench_build_dir "${1-$bench_checkout/build}"
bench_path_var LMP
cd "$bench_checkout"
ACC=${ACC:-1e-6}
REPS=${REPS:-3}
DT_OUT=${DT_OUT:-1e-4}
PY=/usr/bin/python3
posint REPS "$REPS"
cmake --build "$B" --target bench_tts >/dev/null
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

echo "== granwave"
"$B/bench/bench_tts" --acc "$ACC" --reps "$((REPS + 2))" --dt-out "$DT_OUT" | tee "$OUT/gw.txt"
read -r FREF TREF TEND _ < <(awk '$1 == "REF" {print $2, $3, $4, $5}' "$OUT/gw.txt")
read -r PK PKW PM PV PR < <(awk '$1 == "PARAMS" {print $2, $3, $4, $5, $6}' "$OUT/gw.txt")
grep '^TTS ' "$OUT/gw.txt" | awk '{print $2, $3, $4, $5, $6}' >"$OUT/table.txt"

echo
echo "== scipy"
if [ -x "$PY" ] && "$PY" -c 'import scipy.integrate' 2>/dev/null; then
    "$PY" bench/peer_scipy.py --params "$PK" "$PKW" "$PM" "$PV" "$PR" \
        --ref "$FREF" "$TREF" "$TEND" --acc "$ACC" --reps "$REPS" | tee "$OUT/scipy.txt"
    grep '^PEER ' "$OUT/scipy.txt" | awk '{print $2, $3, $4, $5, $6}' >>"$OUT/table.txt"
else
    echo "skipped: $PY with scipy not found (Debian package python3-scipy)"
fi

echo
echo "== lammps"
LMP=${LMP:-$(command -v lmp || command -v lmp_serial || true)}
if [ -n "$LMP" ] && [ -x "$PY" ]; then
    "$PY" bench/peer_lammps.py --lmp "$LMP" --verify --params "$PK" "$PKW" "$PM" "$PV" "$PR" |
        tee "$OUT/verify.txt"
    if grep -q '^VERIFY lammps pass' "$OUT/verify.txt"; then
        "$PY" bench/peer_lammps.py --lmp "$LMP" --params "$PK" "$PKW" "$PM" "$PV" "$PR" \
            --ref "$FREF" "$TREF" "$TEND" --acc "$ACC" --reps "$REPS" | tee "$OUT/lammps.txt"
        grep '^PEER ' "$OUT/lammps.txt" | awk '{print $2, $3, $4, $5, $6}' >>"$OUT/table.txt"
    else
        echo "lammps: force-law check failed, not timed"
    fi
else
    echo "skipped: LAMMPS binary (lmp or lmp_serial) not found (Debian package lammps)"
fi

echo
echo "== time to solution, 40-bead column, F_max and tau_N within $ACC of the reference"
awk -v acc="$ACC" '
    { name[NR] = $1; set[NR] = $2; ms[NR] = $3; ef[NR] = $4; et[NR] = $5
      if ($1 !~ /^(scipy|lammps)/ && $3 == $3 + 0 && (best == "" || $3 < best)) best = $3 }
    END {
      printf "%-14s %-14s %11s %16s %10s %10s\n", "solver", "setting", "ms", "granwave-best/x", "F_max err", "tau_N err"
      for (i = 1; i <= NR; i++) {
        if (ms[i] == "nan") { printf "%-14s %-14s %11s\n", name[i], set[i], "not reached"; continue }
        printf "%-14s %-14s %11.3f %16.3g %10.1e %10.1e\n", name[i], set[i], ms[i], best / ms[i], ef[i], et[i]
      }
    }' "$OUT/table.txt"

echo
echo "== the 2D layer: granwave layer-impact against LAMMPS (bench_layer_peer.sh)"
if [ -n "$LMP" ]; then
    LMP="$LMP" REPS="$REPS" bash bench/bench_layer_peer.sh "$B"
else
    echo "skipped: LAMMPS binary (lmp or lmp_serial) not found (Debian package lammps)"
fi
