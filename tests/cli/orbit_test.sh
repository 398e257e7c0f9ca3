#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# `orbit` (issue 22): a 1IPP orbit agrees with the family's table and meets its identities in
# double and binary128; a 2-impact orbit is found from the family's flip; refusals are one line
# with exit 2. Usage: orbit_test.sh GRAZELAB_CLI
set -uo pipefail
cli="$1"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
out="$work/stdout"
err="$work/stderr"
failures=0
source "$here/contract_lib.sh"

expect_ok family --onepp --count 300 --out "$work/f" || exit 1
# the admissible row nearest 0.9 T2, and the first flip of the family
read -r period trace < <(python3 - "$work/f.csv" "$work/f.json" <<'PY'
import json, sys
T2 = json.load(open(sys.argv[2]))['model']['T2']
rows = [l.split(',') for l in open(sys.argv[1]).read().splitlines()[1:]]
row = min((r for r in rows if r[5] == '1'), key=lambda r: abs(float(r[0]) - 0.9 * T2))
print(row[0], row[6])
PY
)
expect_ok orbit --onepp --period "$period" || exit 1
python3 - "$out" "$period" "$trace" <<'PY' || fail "1IPP orbit"
import json, sys
o = json.load(open(sys.argv[1])); T = float(sys.argv[2]); trace = float(sys.argv[3])
assert o['format'] == 'grazelab-orbit' and o['admissible'] is True and o['impacts'] == 1, o
assert o['period'] == T and o['trace'] == trace, (o['period'], T, o['trace'], trace)  # the table's, bit for bit
assert abs(o['checks']['det_minus_1']) < 1e-13 and o['checks']['periodicity_residual'] < 1e-13, o['checks']
assert o['checks']['trivial_pair'] < 1e-6, o['checks']
mu = o['multipliers']
assert abs(mu[0][0] + mu[1][0] - o['trace']) < 1e-12
assert o['stability'] == ('elliptic' if abs(o['trace']) < 2 else 'hyperbolic' if o['trace'] > 2 else 'flip-hyperbolic')
assert o['symmetry'] == 'A' and o['state']['v1'] == 0 and o['state']['u2'] == 1 and o['state']['v2'] < 0
assert len(o['events']) == 1 and o['events'][0]['type'] == 'impact' and abs(o['events'][0]['t'] - T) < 1e-12 * T
PY
# binary128: its digits, and its identities to ~1e-30
expect_ok orbit --onepp --period "$period" --precision quad || exit 1
python3 - "$out" "$trace" <<'PY' || fail "1IPP orbit in binary128"
import json, re, sys
text = open(sys.argv[1]).read()
o = json.loads(text)
assert o['precision'] == 'quad'
digits = re.search(r'"trace": (-?[0-9.e+-]+)', text).group(1)
assert len(digits.replace('-', '').replace('.', '').split('e')[0]) >= 30, digits
assert abs(o['trace'] - float(sys.argv[2])) < 1e-12
assert abs(o['checks']['det_minus_1']) < 1e-30 and o['checks']['periodicity_residual'] < 1e-30, o['checks']
PY
# the 2-impact orbit born at the first flip, from its state and energy
read -r energy guess bornPeriod < <(python3 - "$work/f.json" <<'PY'
import json, sys
flip = next(b for b in json.load(open(sys.argv[1]))['bifurcations'] if b['kind'] == 'period-doubling')
born = flip['born']
print(repr(born['energy']), '%r,%r' % (born['state']['u1'] + 1e-6, born['state']['v1']), repr(born['period']))
PY
)
expect_ok orbit --impacts 2 --energy "$energy" --guess "$guess" || exit 1
python3 - "$out" "$bornPeriod" <<'PY' || fail "2-impact orbit"
import json, sys
o = json.load(open(sys.argv[1]))
assert o['impacts'] == 2 and len(o['events']) == 2 and all(e['type'] == 'impact' for e in o['events'])
assert abs(o['period'] - float(sys.argv[2])) < 1e-9 * o['period'], (o['period'], sys.argv[2])
assert o['symmetry'] in ('A', 'B'), o['symmetry']
assert abs(o['checks']['det_minus_1']) < 1e-12
PY

EXPECT_WORD="--period" expect_invalid orbit --onepp
EXPECT_WORD="--impacts" expect_invalid orbit --impacts 0 --energy 1 --guess 0,0
EXPECT_WORD="--guess" expect_invalid orbit --impacts 1 --energy 1 --guess 0.5
EXPECT_WORD="at the guess" expect_invalid orbit --impacts 1 --energy 0.01 --guess 3,0
EXPECT_WORD="positive energy" expect_invalid orbit --impacts 1 --energy -1 --guess 0,0
EXPECT_WORD="no admissible 1IPP orbit" expect_invalid orbit --onepp --period 9.5
# a period between the family's parts: where the parts are is said
EXPECT_WORD="T/T2 in about" expect_invalid orbit --onepp --period 5
EXPECT_WORD="does not apply" expect_invalid orbit --onepp --period 6 --contacts 3
EXPECT_WORD="only to 'family', 'orbit'" expect_invalid simulate --energy 2
# near T2 the closed form loses digits like 1 / (T2 - T): double refuses to print data it cannot
# give to 1e-9, auto goes to binary128, whose impact speed is the exact orbit's (issue 29, item 8)
EXPECT_WORD="--precision quad" expect_invalid orbit --onepp --period 8.8857658763 --precision double
expect_ok orbit --onepp --period 8.8857658763 --precision auto || exit 1
python3 - "$out" <<'PY' || fail "1IPP orbit 2e-12 below T2 in auto"
import json, sys
from decimal import Decimal
o = json.load(open(sys.argv[1]))
assert o['precision'] == 'quad', o['precision']
# the impact speed of the orbit of period T = 8.8857658763 (tools/reference/periodic_ref.py onepp, 50 digits)
v2 = Decimal(o['state']['v2'])
assert abs(v2 / Decimal('-5.5774980105873267e-12') - 1) < Decimal('1e-9'), v2
# its trace, 2 - 4.2e-22 (the reference's), is nearer 2 than binary128's error bound on it: the
# class is said undecided, with the trace and its error, not taken as elliptic or hyperbolic
trace, error = Decimal(o['trace']), Decimal(o['trace_error'])
assert o['stability'] == 'undecided' and abs(trace - 2) <= error, (o['stability'], trace, error)
assert abs(trace - Decimal('1.99999999999999999999958')) <= error, trace
PY
# just below T1 (lower design) the orbit exists: it is found, not refused as "does not close"
expect_ok orbit --onepp --m2 0.5 --branch lower --period 5.4408539528933835 || exit 1
python3 -c "import json,sys; o=json.load(open(sys.argv[1])); assert o['admissible'] and abs(float(o['state']['v2']) + 0.0032648415408) < 1e-12, o['state']" "$out" || fail "1IPP orbit just below T1"
# 1.3e-10 below T1 the return map amplifies the rounding 2e10 times: no precision decides the
# orbit, and binary128 says so (exit 2, one line), not that the path "does not close"
EXPECT_WORD="cannot be decided in quad" expect_invalid orbit --onepp --period 4.44288293802508
EXPECT_WORD="cannot be decided in quad" expect_invalid orbit --onepp --period 4.44288293802508 --precision quad
# a gap beyond double's range is read by the precision that holds it (not refused by double's
# reading of the chain first)
expect_ok orbit --onepp --period 8 --precision quad --gap 1e-400 || exit 1
python3 -c "import json,sys; from decimal import Decimal; o=json.load(open(sys.argv[1]), parse_float=Decimal)
assert o['precision'] == 'quad' and abs(o['model']['gap'] / Decimal('1e-400') - 1) < Decimal('1e-30'), o['model']" "$out" \
  || fail "a gap of 1e-400 in binary128"
EXPECT_WORD="out of range" expect_invalid orbit --onepp --period 8 --precision double --gap 1e-400

if [ "$failures" -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "orbit: all checks passed"
