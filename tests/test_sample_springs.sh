#!/bin/bash
# test_sample_springs.sh GRANWAVE SRCDIR: a sample carries its contacts'
# tangential springs (issue 18, class 5: silent wrong answers). layer-make
# settles a pile with Mindlin/Coulomb springs in its contacts; a sample held
# the particles alone, so an impact started every spring at zero and the pile
# sagged into it until friction built up again (the default block resting on
# the 1000-disc pile: 5.9 kJ of potential energy in 100 ms, 1.2 kJ of soil
# motion at 10 ms). The springs are now written after the particles
# ("springs M", then "a b u": the contact and the spring's elastic
# displacement u = F_t / K_t) and an impact starts from them (docs/formats.md,
# gw_layer_spring). Checked:
#  1 layer-make writes the section: a 300-disc pile (seed 1) holds more than
#    n/2 springs, each a contact of the file's own positions;
#  2 the impact starts from them: the ledger's tangential strain energy at
#    t = 0 is sum K_t u^2 / 2 over the springs, K_t (B.4) at the file's
#    overlaps, to 1e-8 (the ledger's 9 digits); at friction 20 degrees
#    (other-settling) each spring's force is clipped to tan(20 deg) F_n, the
#    energy sum min(K_t |u|, tan(phi) F_n)^2 / (2 K_t), smaller (by 1.7 %: most
#    springs lie within the lower bound too); with
#    --zero-springs it is 0;
#  3 the sag: the default block resting on the 300-disc pile (0.01 m/s, gap
#    1e-8 m) for 10 ms: the soil's kinetic energy stays below E_th, the
#    settling's own threshold (1e-5 M g R_m, 8.5 J: the pile was called at rest
#    with up to this much motion), and from zero springs it is above 2 E_th
#    (measured 4.4 J against 26 J; the 600-disc pile 8.9 J against 313 J);
#  4 round trip and identity (a 40-disc pile): the same pile written as text
#    and as HDF5 gives the same impact to the bit (the penetration,
#    energy_error, dissipated_first_contact) and is refused by sweep --check as one pile; the text file
#    without its springs section runs as --zero-springs does (an old sample
#    behaves as before) and is another pile; the pile shuffled, its springs
#    following their discs (a pair in either order), gives the impact within
#    1e-9 and is one pile; one spring halved makes another pile;
#  5 refused (exit 2, one line naming the file and the spring's line, nothing
#    written): an index outside the sample, a NaN, a wall that is none, a
#    pair given twice, a pair not in contact, a spring 10 times beyond the
#    recorded settling's Coulomb bound, two discs of one clump, a section
#    shorter than its count, a count that is not one, data after the section;
#    an HDF5 spring_u with a NaN (naming the spring's index); Python's
#    layer_impact raises naming the file, and takes zero_springs; the
#    library's writer and reader (through a ctypes mirror of the struct, its
#    size the library's) carry two springs to the bit in text and HDF5, and
#    the writer refuses a pair that does not touch.
# On the code before, layer-make wrote no springs and the reader refused the
# section: every check but the pile's making fails.
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
PY=/usr/bin/python3

make_sample s.txt --n 300 --seed 1
make_sample f.txt --n 40 --seed 2

# 1 the section
$PY - s.txt <<'EOF' && ok "1 layer-make: a springs section after the 300 particles, each spring a contact" || ko "1 the springs section: $(grep -c . s.txt) lines, $(grep '^springs' s.txt)"
import math, sys
L = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
k = next(i for i, f in enumerate(L) if f[0] == "n")
n = int(L[k][1]); P = [tuple(map(float, f[:3])) for f in L[k + 1:k + 1 + n]]
assert L[k + 1 + n][0] == "springs"
m = int(L[k + 1 + n][1]); S = L[k + 2 + n:]
assert len(S) == m > n / 2, (len(S), m)
W = float(next(f[1] for f in L if f[0] == "width"))
for a, b, u in S:
    x, y, r = P[int(a)]
    un = {"left": r - x, "right": r - (W - x), "bottom": r - y}.get(b)
    if un is None:
        X, Y, R = P[int(b)]
        un = r + R - math.hypot(X - x, Y - y)
    assert un > 0 and math.isfinite(float(u)), (a, b, u, un)
EOF

# 2 the ledger's tangential strain at t = 0
est() { # SAMPLE FRICTION: sum over the springs of min(K_t |u|, tan(phi) F_n)^2 / (2 K_t), J
    $PY - "$1" "$2" <<'EOF'
import math, sys
L = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
k = next(i for i, f in enumerate(L) if f[0] == "n")
n = int(L[k][1]); P = [tuple(map(float, f[:3])) for f in L[k + 1:k + 1 + n]]
W = float(next(f[1] for f in L if f[0] == "width"))
G, nu, tp = 4e10, 0.25, math.tan(math.radians(float(sys.argv[2])))  # the default material
e = 0.0
for a, b, u in L[k + 2 + n:]:
    x, y, r = P[int(a)]
    un = {"left": r - x, "right": r - (W - x), "bottom": r - y}.get(b)
    rp = r
    if un is None:
        X, Y, R = P[int(b)]
        un, rp = r + R - math.hypot(X - x, Y - y), 2 * r * R / (r + R)
    kn = 2 * math.sqrt(2 * rp) * G / (3 * (1 - nu))                    # B.3
    kt = 2 * (3 * G * G * (1 - nu) * rp) ** (1 / 3) / (2 - nu) * kn ** (1 / 3) * math.sqrt(un)  # B.4
    f = min(kt * abs(float(u)), tp * kn * un ** 1.5)
    e += f * f / (2 * kt)
print(repr(e))
EOF
}
st0() { # ARGS...: the ledger's strain_tangent at t = 0 of a short impact
    rm -rf "$tmp/m"
    "$GW" layer-impact --t-max 1e-4 --out "$tmp/m" --quiet "$@" >/dev/null 2>&1 || { echo nan; return; }
    $PY -c "import csv, sys; print(next(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith('#')))['strain_tangent'])" \
        "$tmp/m/ledger.csv"
}
e30=$(est s.txt 30) e20=$(est s.txt 20)
g30=$(st0 --sample s.txt) g20=$(st0 --sample s.txt --friction 20 --other-settling) g0=$(st0 --sample s.txt --zero-springs)
$PY -c "import sys; e30, e20, g30, g20, g0 = map(float, sys.argv[1:]); sys.exit(not (e30 > 0 and abs(g30 - e30) <= 1e-8 * e30 and e20 < (1 - 1e-3) * e30 and abs(g20 - e20) <= 1e-8 * e20 and g0 == 0))" \
    "$e30" "$e20" "$g30" "$g20" "$g0" &&
    ok "2 E_st(0) = sum K_t u^2 / 2 = $g30 J ($e30 from the file); at 20 deg clipped to the Coulomb bound: $g20 J ($e20); zero springs: $g0" ||
    ko "2 E_st(0): $g30 J against $e30 from the file; at 20 deg $g20 against $e20; zero springs $g0"

# 3 the sag of the pile under the block resting on it
eth=$($PY - s.txt <<'EOF'
import math, sys
L = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
k = next(i for i, f in enumerate(L) if f[0] == "n")
n = int(L[k][1]); rm = float(next(f[1] for f in L if f[0] == "rm"))
M = sum(math.pi * float(f[2]) ** 2 * 2650 for f in L[k + 1:k + 1 + n])
print(1e-5 * M * 9.81 * rm)
EOF
)
ksoil() { # ARGS...: the soil's kinetic energy 10 ms after the block was set on the pile, J
    "$GW" layer-impact --sample s.txt --vi 0.01 --gap 1e-8 --t-max 0.01 --full --json --quiet "$@" \
        2>/dev/null | $PY -c "import json, sys; print(json.load(sys.stdin)['ledger_end']['kinetic_soil'])" 2>/dev/null || echo nan
}
k1=$(ksoil) k0=$(ksoil --zero-springs)
$PY -c "import sys; k1, k0, e = map(float, sys.argv[1:]); sys.exit(not (k1 < e and k0 > 2 * e))" "$k1" "$k0" "$eth" &&
    ok "3 the block resting on the 300-disc pile, 10 ms: soil E_k $k1 J with its springs, $k0 J from zero (E_th $eth J)" ||
    ko "3 the sag: soil E_k $k1 J with springs, $k0 J from zero, E_th $eth J"

# 4 round trip and identity, on the 40-disc pile
num() { $PY -c "import json, sys; d = json.load(open(sys.argv[1])); print(' '.join(repr(d[k]) for k in ('penetration', 'energy_error', 'dissipated_first_contact')))" "$1" 2>/dev/null; }
imp() { "$GW" layer-impact --t-max 0.05 --json --quiet "$@" >"$tmp/i.json" 2>/dev/null && num "$tmp/i.json"; }
sed -e "/^# lines after 'springs'/d" -e '/^springs /,$d' f.txt >f0.txt
ft=$(imp --sample f.txt) fz=$(imp --sample f.txt --zero-springs) f0=$(imp --sample f0.txt)
[ -n "$ft" ] && [ "$f0" = "$fz" ] && [ "$ft" != "$fz" ] &&
    ok "4 without its springs section the sample runs as --zero-springs ($f0), with it otherwise ($ft)" ||
    ko "4 no section: '$f0', --zero-springs: '$fz', the springs: '$ft'"
sweep_ini() { printf '[sweep]\nmodel = layer\n[grid]\nsample = %s\n[params]\nt-max = 0.002\n' "$2" >"$1"; }
one_pile() { # WHAT A B: sweep --check refuses A and B as one pile
    sweep_ini o.ini "$2, $3"
    exits_refused "$1" "sample: '.*$2' and '.*$3' hold the same pile" 60 "$GW" sweep o.ini --out "$tmp/o" --check &&
        ok "$1: one pile" || true
}
two_piles() { # WHAT A B: sweep --check passes A and B
    sweep_ini o.ini "$2, $3"
    "$GW" sweep o.ini --out "$tmp/o" --check >/dev/null 2>"$tmp/stderr" && ok "$1: two piles" ||
        ko "$1: $(head -c 300 "$tmp/stderr")"
}
two_piles "4 the sample and its particles without springs" f.txt f0.txt
if "$GW" version --json | grep -q '"hdf5":[[:space:]]*"'; then
    make_sample f.h5 --n 40 --seed 2
    fh=$(imp --sample f.h5)
    [ -n "$ft" ] && [ "$fh" = "$ft" ] && ok "4 HDF5: the same impact to the bit ($fh)" || ko "4 HDF5: '$fh' against text '$ft'"
    one_pile "4 the pile as text and as HDF5" f.txt f.h5
    $PY - <<'EOF'
import shutil, h5py, math
shutil.copy("f.h5", "bad.h5")
with h5py.File("bad.h5", "r+") as f:
    u = f["spring_u"][()]
    u[3] = math.nan
    f["spring_u"][...] = u
EOF
    refused "5 HDF5 spring_u with a NaN" "^granwave layer-impact: sample 'bad.h5': spring at index 3: spring .*: displacement u = nan m is not a finite number" \
        layer-impact --sample bad.h5 --out "$tmp/o"
else
    echo "(no HDF5 in this build: its round trip skipped)"
fi
# shuffle SRC DST SEED [HALVE]: SRC's particles in another order, the springs
# following their discs, each pair in a random order; HALVE: one spring's u halved
$PY - f.txt p.txt 1 <<'EOF'
import random, sys
src, dst, seed = sys.argv[1], sys.argv[2], int(sys.argv[3])
rnd = random.Random(seed)
lines = open(src).read().split("\n")
k = next(i for i, l in enumerate(lines) if l.split()[:1] == ["n"])
n = int(lines[k].split()[1])
rows, spr = lines[k + 1:k + 1 + n], [l.split() for l in lines[k + 2 + n:] if l.strip()]
order = list(range(n)); rnd.shuffle(order)
at = {o: i for i, o in enumerate(order)}
walls = ("left", "right", "bottom")
spr = [[str(at[int(a)]), b if b in walls else str(at[int(b)]), u] for a, b, u in spr]
spr = [[b, a, u] if b not in walls and rnd.random() < 0.5 else [a, b, u] for a, b, u in spr]
rnd.shuffle(spr)
out = lines[:k + 1] + [rows[i] for i in order] + ["springs %d" % len(spr)] + [" ".join(q) for q in spr]
open(dst, "w").write("\n".join(out) + "\n")
half = list(out)
j = len(lines[:k + 1]) + n + 1
a, b, u = half[j].split()
half[j] = "%s %s %r" % (a, b, float(u) / 2)
open("h.txt", "w").write("\n".join(half) + "\n")
EOF
fp=$(imp --sample p.txt)
$PY -c "import sys; a, b = (list(map(float, s.split())) for s in sys.argv[1:]); sys.exit(not (len(a) == len(b) == 3 and all(abs(x - y) <= 1e-9 * abs(x) for x, y in zip(a, b))))" "$ft" "$fp" &&
    ok "4 shuffled, the springs following their discs: the impact within 1e-9 ($fp)" || ko "4 shuffled: '$fp' against '$ft'"
one_pile "4 the pile and its shuffled listing" f.txt p.txt
two_piles "4 the shuffled pile with one spring halved" p.txt h.txt

# 5 refusals
# bad NAME SED: f.txt with its first spring line edited by the sed expression
spr_line=$(grep -n '^springs ' f.txt | cut -d: -f1)
first=$((spr_line + 1))
bad() { sed "${first}$2" f.txt >"$1"; }
bad b_index.txt 's/^[^ ]* [^ ]* \([^ ]*\)$/0 99 \1/'
bad b_nan.txt 's/ [^ ]*$/ nan/'
bad b_wall.txt 's/^\([0-9]*\) [^ ]* /\1 top /'
nspr=$(sed -n "${spr_line}s/^springs //p" f.txt)
sed -e "${first}p" -e "s/^springs $nspr\$/springs $((nspr + 1))/" f.txt >b_twice.txt
read -r fa fb fu <<<"$(sed -n "${first}p" f.txt)"
far=$($PY - f.txt "$fa" <<'EOF'
import math, sys
L = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
k = next(i for i, f in enumerate(L) if f[0] == "n")
n = int(L[k][1]); P = [tuple(map(float, f[:3])) for f in L[k + 1:k + 1 + n]]
a = int(sys.argv[2])
print(max(range(n), key=lambda j: math.hypot(P[j][0] - P[a][0], P[j][1] - P[a][1])))
EOF
)
bad b_open.txt "s/^.*\$/$fa $far $fu/"
u10=$($PY -c "print(repr(10 * float('$fu')))")
bad b_bound.txt "s/^.*\$/$fa $fb $u10/"
sed "s/^springs $nspr\$/springs $((nspr + 5))/" f.txt >b_short.txt
sed "s/^springs \([0-9]*\)/springs 1.5/" f.txt >b_count.txt
{ cat f.txt; echo "0 1 0"; } >b_after.txt
sl=$first
refused "5 a particle index outside the sample" "^granwave layer-impact: sample 'b_index.txt': line $sl: spring 0 99: a particle index outside \[0, 40\)" \
    layer-impact --sample b_index.txt --out "$tmp/o"
refused "5 a NaN displacement" "^granwave layer-impact: sample 'b_nan.txt': line $sl: expected 'a b u'" \
    layer-impact --sample b_nan.txt --out "$tmp/o"
refused "5 a wall that is none (top)" "sample 'b_wall.txt': line $sl: expected 'a b u'" layer-impact --sample b_wall.txt --out "$tmp/o"
refused "5 a pair given twice" "sample 'b_twice.txt': line $((sl + 1)): spring .* given twice \(first at line $sl\)" \
    layer-impact --sample b_twice.txt --out "$tmp/o"
refused "5 a pair not in contact ($fa, $far)" "sample 'b_open.txt': line $sl: spring [0-9]+ [0-9]+: the pair is not in contact \(gap [0-9.e+-]+ m\)" \
    layer-impact --sample b_open.txt --out "$tmp/o"
refused "5 a spring 10 times its own (beyond the Coulomb bound)" "sample 'b_bound.txt': line $sl: spring .*: displacement .* is beyond the Coulomb bound .* of the settling the sample records \(friction 30 deg" \
    layer-impact --sample b_bound.txt --out "$tmp/o"
refused "5 a section shorter than its count" "sample 'b_short.txt': truncated after line [0-9]+: [0-9]+ of [0-9]+ springs" \
    layer-impact --sample b_short.txt --out "$tmp/o"
refused "5 a count that is not an integer" "sample 'b_count.txt': line $spr_line: expected 'springs M'" \
    layer-impact --sample b_count.txt --out "$tmp/o"
refused "5 data after the section" "sample 'b_after.txt': line [0-9]+: data after the [0-9]+ springs" \
    layer-impact --sample b_after.txt --out "$tmp/o"
settling_sweep_ini b.ini "$tmp/b_bound.txt"
refused "5 a layer sweep's --check over the spring beyond its bound" "b_bound.txt': line $sl: .*beyond the Coulomb bound" \
    sweep b.ini --out "$tmp/o" --check

# two discs of one clump
make_sample c.txt --n 12 --clumps --width-rm 12 --seed 3
pair=$($PY - c.txt <<'EOF'
import sys
L = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
k = next(i for i, f in enumerate(L) if f[0] == "n")
n = int(L[k][1]); B = [f[3] for f in L[k + 1:k + 1 + n]]
print(next("%d %d" % (i, j) for i in range(n) for j in range(i + 1, n) if B[i] == B[j]))
EOF
)
cl=$(($(grep -n '^springs ' c.txt | cut -d: -f1) + 1))
if [ -n "$pair" ] && grep -q '^springs ' c.txt; then
    sed "${cl}s/^[^ ]* [^ ]* /$pair /" c.txt >b_clump.txt
    refused "5 two discs of one clump" "sample 'b_clump.txt': line $cl: spring $pair: the two discs are one clump" \
        layer-impact --sample b_clump.txt --out "$tmp/o"
    "$GW" layer-impact --sample c.txt --t-max 0.002 >/dev/null 2>&1 && ok "the clump pile's springs read and run" ||
        ko "the clump pile with springs does not run"
else
    ko "the clump pile: no springs section, or no clump of two discs ($pair)"
fi

py_checks 6 <<'EOF'
# the library's writer and reader, through a mirror of the C struct
import ctypes, os
class Settled(ctypes.Structure):
    _fields_ = [("recorded", ctypes.c_int), ("shear_modulus", ctypes.c_double), ("poisson", ctypes.c_double),
                ("friction_deg", ctypes.c_double), ("density", ctypes.c_double), ("gravity", ctypes.c_double),
                ("mass_law", ctypes.c_int), ("line", ctypes.c_long), ("clump_mass", ctypes.c_int),
                ("unsettled", ctypes.c_int)]
class Spring(ctypes.Structure):
    _fields_ = [("a", ctypes.c_int), ("b", ctypes.c_int), ("u", ctypes.c_double)]
class Sample(ctypes.Structure):
    _fields_ = [("n", ctypes.c_int), ("width", ctypes.c_double), ("rm", ctypes.c_double),
                ("volume_ratio", ctypes.c_double), ("porosity", ctypes.c_double), ("seed", ctypes.c_long),
                ("mass_law", ctypes.c_int), ("clump_mass", ctypes.c_int), ("x", ctypes.POINTER(ctypes.c_double)),
                ("y", ctypes.POINTER(ctypes.c_double)), ("r", ctypes.POINTER(ctypes.c_double)),
                ("body", ctypes.POINTER(ctypes.c_int)), ("content_hash", ctypes.c_ulonglong),
                ("settled", Settled), ("n_springs", ctypes.c_int), ("springs", ctypes.POINTER(Spring)),
                ("settled_converged", ctypes.c_int)]
lib = ctypes.CDLL(granwave.library_path)
lib.gw_layer_sample_size.restype = ctypes.c_size_t
check(ctypes.sizeof(Sample) == lib.gw_layer_sample_size(), "the mirror of gw_layer_sample with its springs: %d bytes, "
      "the library's %d" % (ctypes.sizeof(Sample), lib.gw_layer_sample_size()))
d3 = lambda v: (ctypes.c_double * 3)(*v)
def sample(springs):
    sp = (Spring * len(springs))(*[Spring(a, b, u) for a, b, u in springs])
    return Sample(n=3, width=1.0, rm=0.1, porosity=float("nan"), x=d3([0.1, 0.299, 0.5]), y=d3([0.1, 0.1, 0.0999]),
                  r=d3([0.1, 0.1, 0.1]), n_springs=len(springs), springs=sp), sp
good = [(0, 1, 1e-5), (2, -3, -2.5e-5)]  # discs 0 and 1 overlap by 1e-3 m, disc 2 the floor by 1e-4 m
err = ctypes.create_string_buffer(512)
got = {}
for name in ("w.txt", "w.h5"):
    s, keep = sample(good)
    rc = lib.gw_layer_sample_write(ctypes.byref(s), name.encode(), None, err)
    back = Sample()
    if rc == 0 and lib.gw_layer_sample_read(name.encode(), ctypes.byref(back), err) == 0:
        got[name] = [(back.springs[k].a, back.springs[k].b, back.springs[k].u) for k in range(back.n_springs)]
        lib.gw_layer_sample_free(ctypes.byref(back))
    else:
        got[name] = (rc, err.value)
check(got["w.txt"] == good and (got["w.h5"] == good or (isinstance(got["w.h5"], tuple) and got["w.h5"][0] == -6)),
      "the library writes and reads the springs back to the bit (text, HDF5): %r" % got)
s, keep = sample([(0, 2, 1e-5)])
rc = lib.gw_layer_sample_write(ctypes.byref(s), b"wbad.txt", None, err)
check(rc == -1 and not os.path.exists("wbad.txt") and b"spring at index 0: spring 0 2: the pair is not in contact" in err.value,
      "the library's writer refuses a spring whose discs do not touch (%d: %s)" % (rc, err.value))
refused("Python: a spring beyond its bound", ["b_bound.txt", "line", "Coulomb bound"], granwave.layer_impact,
        sample="b_bound.txt", t_max=0.002)
a = granwave.layer_impact(sample="f.txt", t_max=0.002)
z = granwave.layer_impact(sample="f.txt", t_max=0.002, zero_springs=True)
o = granwave.layer_impact(sample="f0.txt", t_max=0.002)
check(z["energy_error"] == o["energy_error"] and a["energy_error"] != z["energy_error"],
      "Python zero_springs=True: as the sample without springs (%r, %r), not as with them (%r)"
      % (z["energy_error"], o["energy_error"], a["energy_error"]))
p = granwave.layer_impact(sample="p.txt", t_max=0.002)
check(abs(p["energy_error"] - a["energy_error"]) <= 1e-9 * abs(a["energy_error"]),
      "Python: the shuffled pile's impact as the pile's (%r, %r)" % (p["energy_error"], a["energy_error"]))
EOF

test_summary test_sample_springs
