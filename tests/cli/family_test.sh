#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# `family --onepp` (issue 10): the table's columns, its grazing end on the lambda* data, and
# refusals. Usage: family_test.sh GRAZELAB_CLI
set -uo pipefail
cli="$1"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
out="$work/stdout"
err="$work/stderr"
failures=0
source "$here/contract_lib.sh"

expect_ok family --onepp --m2 0.3 --count 300 --out "$work/f/family" || exit 1
python3 - "$work" <<'PY' || fail "family table"
import array, ast, json, math, sys
work = sys.argv[1]
lines = open(work + '/f/family.csv').read().splitlines()
assert lines[0] == 'T,omega,V,u1,energy,admissible,trace,stability', lines[0]
cells = [l.split(',') for l in lines[1:]]
rows = [list(map(float, c[:6])) + [float(c[6]) if c[6] else math.nan] for c in cells]
classes = [c[7] for c in cells]
meta = json.load(open(work + '/f/family.json'))
assert meta['rows'] == len(rows) >= 300
b = open(work + '/f/family.npy', 'rb').read(); n = b[8] | (b[9] << 8)
h = ast.literal_eval(b[10:10 + n].decode('latin1')); a = array.array('d'); a.frombytes(b[10 + n:])
assert h['shape'] == (len(rows), 8), h
same = lambda x, y: x == y or (math.isnan(x) and math.isnan(y))
assert all(same(a[8 * i + j], rows[i][j]) for i in range(len(rows)) for j in range(7))
T2, end = meta['model']['T2'], meta['grazing_end']
assert all(0 < r[0] < T2 for r in rows) and all(x[0] < y[0] for x, y in zip(rows, rows[1:]))
last = rows[-1]
assert last[5] == 1 and -1e-10 < last[2] < 0, last
assert abs(last[3] - end['u1']) < 1e-10 and abs(last[4] - end['energy']) < 1e-10 * end['energy'], (last, end)
assert all(r[2] < 0 for r in rows if r[5] == 1), 'an admissible orbit with V >= 0'
# a trace and a class for every admissible orbit, none otherwise, and the class is the trace's
for r, c in zip(rows, classes):
    assert (r[5] == 1) == (not math.isnan(r[6])) == (c != ''), (r, c)
    if c == 'elliptic': assert abs(r[6]) < 2, (r, c)
    if c == 'hyperbolic': assert r[6] > 2, (r, c)
    if c == 'flip-hyperbolic': assert r[6] < -2, (r, c)
# the bifurcations: in increasing T, the family's grazing end last (at T2, on the lambda* data);
# each flip has trace -2 and the 2-impact orbit born there has twice its period
bif = meta['bifurcations']
assert [x['T'] for x in bif] == sorted(x['T'] for x in bif)
assert bif[-1]['kind'] == 'grazing-orbit' and bif[-1]['T'] == T2, bif[-1]
assert abs(bif[-1]['state']['u1'] - end['u1']) < 1e-12
flips = [x for x in bif if x['kind'] == 'period-doubling']
assert flips, bif
for f in flips:
    assert abs(f['trace'] + 2) < 1e-9, f
    born = f['born']
    assert born['impacts'] == 2 and born['side'] in ('below', 'above'), born
    assert abs(born['period'] - 2 * f['T']) < 1e-3 * f['T'], (born, f)
    assert abs(born['energy'] - f['energy']) < 1e-2 * f['energy'], (born, f)
PY
if [ -e "$work/f/family.svg" ]; then
  # its description holds "V < 0": Qt 6.4 wrote it unescaped, and no reader could open the file
  python3 - "$work/f/family.svg" <<'PY' || fail "family.svg is not well-formed or lacks its table's description"
import json, sys, xml.etree.ElementTree as ET
desc = ET.parse(sys.argv[1]).getroot().find('{http://www.w3.org/2000/svg}desc').text
assert json.loads(desc)['format'] == 'grazelab-family'
PY
fi
EXPECT_WORD="--onepp" expect_invalid family --out "$work/bad/f"
EXPECT_WORD="resonant" expect_invalid family --onepp --k2 0.6 --out "$work/bad/f"
EXPECT_WORD="--out" expect_invalid family --onepp
EXPECT_WORD="--count" expect_invalid family --onepp --count 0 --out "$work/bad/f"
EXPECT_WORD="--precision" expect_invalid family --onepp --precision octuple --out "$work/bad/f"
EXPECT_WORD="does not apply" expect_invalid family --onepp --contacts 5 --out "$work/bad/f"
[ ! -e "$work/bad" ] || [ -z "$(ls -A "$work/bad")" ] || fail "a refused family wrote files"
EXPECT_WORD="only to 'family'" expect_invalid simulate --count 5

# an interrupt ends a long family with exit 130 and no files
timeout --preserve-status -s INT 1 "$cli" family --onepp --count 10000000 --out "$work/long/f" 2>"$err"
code=$?
[ "$code" -eq 130 ] || fail "interrupted family exited $code, not 130"
[ ! -e "$work/long/f.csv" ] || fail "an interrupted family wrote its table"
if [ "$failures" -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "family: all checks passed"
