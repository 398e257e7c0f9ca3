#!/bin/bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# One chain however it is written (issue 47, "one model"): the two-mass options and --masses
# describe the same chain, and the commands that compute the note's chain (orbit, modes; and for
# its 1:2 design simulate, family, map, glo-set) give the same bits for both, on the note's chain and on chains the issue does not name (the lower
# branch with other masses and scale, a detuned chain with its springs given, binary128 with
# masses that double rounds). A chain they cannot compute yet is refused in one line, exit 2.
# usage: one_chain_test.sh GRAZELAB_CLI
set -u
cli="$1"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
out="$work/stdout"
err="$work/stderr"
failures=0
source "$here/contract_lib.sh"

# the same document but for what measures the machine (seconds, the generator's version is equal)
same_json() {
  python3 - "$1" "$2" <<'PY'
import json, sys
def strip(value):
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items() if "second" not in k and "time" != k[-4:]}
    if isinstance(value, list):
        return [strip(v) for v in value]
    return value
a, b = (strip(json.load(open(path))) for path in sys.argv[1:3])
assert a == b, "\n".join(f"{k}: {a.get(k)!r} != {b.get(k)!r}" for k in a if a.get(k) != b.get(k))[:2000]
PY
}

# two ways of writing each chain: the note's options | --masses
cases=(
  "|--masses 1,0.5 --frequencies 2:1"
  "--m1 2 --m2 0.3 --k1 1.5 --gap 0.7 --branch lower|--masses 2,0.3 --springs 1.5 --frequencies 2:1 --design-branch 2 --gap 0.7"
  "--m1 1 --m2 0.4 --k1 1.2 --k2 0.37|--masses 1,0.4 --springs 1.2,0.37"
  "--m1 1 --m2 0.3 --precision quad|--masses 1,0.3 --frequencies 2:1 --precision quad"
)
# a command run on both forms of a chain: the same exit code, the same output (or the same one
# line of refusal); with --out, the same files (the pictures apart: their metadata carry the
# command line). usage: same_both LABEL NOTE MASSES OUTDIR COMMAND...
same_both() {
  local label=$1 note=$2 masses=$3 outdir=$4
  shift 4
  same_pair "$label" "$outdir" "$* $note" "$* $masses"
}

# two command lines that write one computation: the same exit code and output (or refusal), and
# with an out folder NAME the same files (pictures apart). usage: same_pair LABEL NAME "A" "B"
same_pair() {
  local label=$1 outdir=$2 first=$3 second=$4
  # shellcheck disable=SC2086
  "$cli" $first ${outdir:+--out "$work/a/$outdir/x"} > "$work/a.out" 2> "$work/a.err"
  local codeA=$?
  # shellcheck disable=SC2086
  "$cli" $second ${outdir:+--out "$work/b/$outdir/x"} > "$work/b.out" 2> "$work/b.err"
  local codeB=$?
  if [ "$codeA" -ne "$codeB" ]; then
    fail "$label: exit $codeA written one way, $codeB the other ($(cat "$work/a.err" "$work/b.err" | head -2))"
    return
  fi
  if [ "$codeA" -ne 0 ]; then
    cmp -s "$work/a.err" "$work/b.err" || fail "$label: refused differently: $(cat "$work/a.err") / $(cat "$work/b.err")"
    return
  fi
  case "$first" in
    *"--format csv"*) cmp -s "$work/a.out" "$work/b.out" || fail "$label: the csv differs" ;;
    *) if [ -s "$work/a.out" ]; then same_json "$work/a.out" "$work/b.out" || fail "$label: the output differs"; fi ;;
  esac
  if [ -n "$outdir" ]; then
    for file in "$work/a/$outdir"/*; do
      local name
      name=$(basename "$file")
      case "$name" in
        *.png|*.svg|*.pdf) ;;
        *.json) same_json "$file" "$work/b/$outdir/$name" || fail "$label: $name differs" ;;
        *) cmp -s "$file" "$work/b/$outdir/$name" || fail "$label: $name differs" ;;
      esac
    done
  fi
  ran=$((ran + 1))
}

ran=0
index=0
for case in "${cases[@]}"; do
  index=$((index + 1))
  note="${case%%|*}"
  masses="${case#*|}"
  # shellcheck disable=SC2086
  { expect_ok info $note && cp "$out" "$work/info-a"; } || continue
  # a period of the 1IPP family: 0.93 of the slow one
  period=$(python3 -c "import json,sys; print(repr(0.93 * float(json.load(open(sys.argv[1]))['model']['T2'])))" "$work/info-a")
  same_both "case $index: orbit" "$note" "$masses" "" orbit --onepp --period "$period"
  same_both "case $index: modes" "$note" "$masses" "modes$index" modes --max-impacts 2 --energy-range 0.3:1.5
  # the note's design written with --masses is run by the note's engine: simulate (its starts
  # written as a chain's: --glo-weights 1 - lambda, lambda for --glo lambda), family, map (over
  # u<i>, v<i>, from the grazing-start plane when no state is given, as for every chain)
  case "$masses" in *"--frequencies 2:1"*) ;; *) continue ;; esac
  same_pair "case $index: simulate from a state" "" "simulate $note --state 0.1,0.5,0,0.3 --contacts 40" \
    "simulate $masses --state 0.1,0.5,0,0.3 --contacts 40"
  same_pair "case $index: simulate near grazing" "" "simulate $note --glo 0.3 --perturb 0,0,0,-0.01 --contacts 30" \
    "simulate $masses --glo-weights 0.7,0.3 --perturb 0,0,0,-0.01 --contacts 30"
  same_pair "case $index: simulate a 1IPP orbit, csv" "" "simulate $note --onepp $period --contacts 5 --format csv" \
    "simulate $masses --onepp $period --contacts 5 --format csv"
  same_pair "case $index: simulate sampled" "" "simulate $note --state 0,0.6,0,0 --t-end 20 --sample-step 0.5" \
    "simulate $masses --state 0,0.6,0,0 --t-end 20 --sample-step 0.5"
  same_both "case $index: glo-set" "$note" "$masses" "" glo-set
  same_pair "case $index: family" "family$index" "family --onepp --count 150 $note" "family --onepp --count 150 $masses"
  same_pair "case $index: map" "map$index" "map --x u1:-0.8:0.8:5 --y v2:-0.4:0.4:4 --contacts 4 $note" \
    "map --x u1:-0.8:0.8:5 --y v2:-0.4:0.4:4 --contacts 4 $masses"
  same_pair "case $index: map from a state" "mapstate$index" \
    "map --x u1:-0.8:0.8:5 --y v1:-0.4:0.4:4 --contacts 4 --state 0,0.5,0,0 $note" \
    "map --x u1:-0.8:0.8:5 --y v1:-0.4:0.4:4 --contacts 4 --state 0,0.5,0,0 $masses"
done
[ "$ran" -ge 26 ] || fail "only $ran commands ran on both forms"
# the note's chain written with --masses keeps a chain's starts: one of them, --glo refused
EXPECT_WORD="one of them" expect_invalid simulate --masses 1,0.5 --frequencies 2:1 --contacts 3
EXPECT_WORD="not available for a chain" expect_invalid simulate --masses 1,0.5 --frequencies 2:1 --glo 0.5
EXPECT_WORD="sum to 1" expect_invalid simulate --masses 1,0.5 --frequencies 2:1 --glo-weights 0.5,0.6

# a chain off the note's form takes the atlas of any chain: two masses stopped on the first
expect_ok modes --masses 1,0.5 --springs 1,0.5 --stop-mass 1 --max-impacts 1 --out "$work/ok/m" || exit 1
grep -q '"stop_mass": 1' "$work/ok/m.json" || fail "modes of a chain stopped on mass 1"
# kIPP orbits of any chain by Newton on the return map (core/orbits/chain_kipp.h): the guess is u
# then v of every mass but the stopped one (and v_s last at a fixed period)
EXPECT_WORD="give 4 numbers" expect_invalid orbit --impacts 2 --energy 1 --guess 0,0 --masses 1,0.2,0.05 --frequencies 3:2:1
EXPECT_WORD="give 5 numbers" expect_invalid orbit --impacts 1 --period 7 --guess 0.1,0.3,0,0 --masses 1,0.2,0.05 --frequencies 3:2:1
EXPECT_WORD="below 0" expect_invalid orbit --impacts 1 --period 7 --guess 0.1,0.3,0,0,0.4 --masses 1,0.2,0.05 --frequencies 3:2:1
# a 2IPP orbit of three masses stopped on the middle one, born at a period doubling of the 1IPP
# family (T* = 5.3118): symmetric (v1 = v3 = 0 at its impacts), hyperbolic
three="--masses 0.6865,1.963,0.8236 --springs 0.8423,1.0745,0.7486 --stop-mass 2"
expect_ok orbit --impacts 2 --energy 23.412611915561559 --guess 1.28,-6.54,0.01,-0.01 $three || exit 1
python3 - "$out" <<'PY' || fail "the 2IPP orbit of three masses"
import json, sys
o = json.load(open(sys.argv[1]))
assert o['impacts'] == 2 and len(o['events']) == 2 and all(e['type'] == 'impact' for e in o['events']), o
assert abs(o['period'] - 10.623624493363227) < 1e-9 and abs(o['energy'] - 23.412611915561559) < 1e-12, o
a, b = (e['u'] for e in o['events'])
assert max(abs(x - y) for x, y in zip(a, b)) > 0.1, (a, b)  # two impacts, not one orbit twice
assert o['stability'] == 'hyperbolic' and len(o['multipliers']) == 4, o
mu = [complex(re, im) for re, im in o['multipliers']]
real = sorted(z.real for z in mu if z.imag == 0)
assert len(real) == 2 and abs(real[0] * real[1] - 1) < 1e-8, mu  # mu and 1/mu
assert o['checks']['symplectic'] < 1e-13 and o['checks']['periodicity_residual'] < 1e-12, o['checks']
PY
# the 1IPP orbit by Newton, at its energy and at its period, is the closed form's
expect_ok orbit --onepp --period 7 --masses 1,0.2,0.05 --frequencies 3:2:1 || exit 1
cp "$out" "$work/onepp.json"
expect_ok orbit --impacts 1 --energy 0.06997844762300173 --guess 0.13,0.3,0.01,0.01 --masses 1,0.2,0.05 --frequencies 3:2:1 || exit 1
cp "$out" "$work/byenergy.json"
expect_ok orbit --impacts 1 --period 7 --guess 0.13,0.3,0.01,0.01,-0.4 --masses 1,0.2,0.05 --frequencies 3:2:1 || exit 1
python3 - "$work/onepp.json" "$work/byenergy.json" "$out" <<'PY' || fail "the 1IPP orbit by Newton"
import json, sys
exact, *found = (json.load(open(f)) for f in sys.argv[1:])
for o in found:
    assert abs(o['period'] - 7) < 1e-12 and abs(o['energy'] - exact['energy']) < 1e-14, o
    for key in ('u', 'v'):
        assert max(abs(x - y) for x, y in zip(o['state'][key], exact['state'][key])) < 1e-12, o['state']
    for (re, im), (re0, im0), bar in zip(o['multipliers'], exact['multipliers'], o['multiplier_errors']):
        assert abs(complex(re, im) - complex(re0, im0)) < 1e-10 + bar, o['multipliers']
PY
# the 1IPP orbit of any chain, by its 2N x 2N monodromy (docs/model.md section 12)
expect_ok orbit --onepp --period 7 --masses 1,0.2,0.05 --frequencies 3:2:1 || exit 1
python3 - "$out" <<'PY' || fail "the 1IPP orbit of three masses"
import json, sys
o = json.load(open(sys.argv[1]))
assert o['format'] == 'grazelab-orbit' and o['period'] == 7 and o['impacts'] == 1, o
assert len(o['multipliers']) == 4 and len(o['krein']) == 4 and len(o['multiplier_errors']) == 4
assert o['stability'] == 'elliptic' and all(o['on_circle']), o
mu = [complex(re, im) for re, im in o['multipliers']]
for i, z in enumerate(mu):  # each multiplier's conjugate is there, with the opposite signature
    j = min(range(4), key=lambda k: abs(mu[k] - z.conjugate()))
    assert j != i and o['krein'][j] == -o['krein'][i] != 0, (mu, o['krein'])
assert o['checks']['symplectic'] < 1e-14 and o['checks']['trivial_pair'] < 1e-13, o['checks']
assert o['state']['u'][2] == 1 and o['state']['v'][2] < 0
PY
expect_ok orbit --onepp --period 3 --masses 1,0.5 --springs 1,0.5 --right-spring 0.2 || exit 1
python3 -c "import json,sys; o=json.load(open(sys.argv[1])); assert len(o['multipliers']) == 2 and o['chain']['right_spring'] == 0.2, o" "$out" \
  || fail "the 1IPP orbit of two masses with a right wall"
EXPECT_WORD="no 1IPP orbit of period 1" expect_invalid orbit --onepp --period 1 --masses 1,0.2,0.05 --frequencies 3:2:1
# springs 1e25 apart: no flight's return can be searched within the budget; the family says so
# in one line after its first rows, where it took 40 s of computing 2023 rows "never returning"
EXPECT_WORD="cannot be searched within the budget" expect_invalid family --onepp --masses 1,1e-25,1 \
  --springs 1e25,1,1 --count 2000 --out "$work/x/stiff"
# and its atlas likewise, where it once wrote "0 families" after 13 s
EXPECT_WORD="cannot be searched within the budget" expect_invalid modes --masses 1,1e-25,1 \
  --springs 1e25,1,1 --out "$work/x/stiffmodes"
# report computes any chain (tests/cli/report_test.sh): a chain of N masses names its start
EXPECT_WORD="one of them" expect_invalid report --quick --masses 1,1,1 --springs 1,1,1 --out "$work/x/r"
# the chain's own refusals, as for info and simulate
EXPECT_WORD="no chain with these masses" expect_invalid orbit --onepp --period 7 --masses 1,0.6 --frequencies 2:1
EXPECT_WORD="not both" expect_invalid orbit --onepp --period 7 --masses 1,0.5 --m2 0.5 --springs 1,0.5
EXPECT_WORD="given by --masses" expect_invalid modes --springs 1,0.5 --out "$work/x/m"
[ ! -e "$work/x" ] || fail "a refused command wrote $(ls -R "$work/x")"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "one chain however written: the same bits in orbit, modes, simulate, family, map and glo-set"
