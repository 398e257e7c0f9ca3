#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# `modes` (issue 22): the atlas's files and their agreement, the families born at flips, the
# atlas of any other chain (issue 49), and refusals. Usage: modes_test.sh GRAZELAB_CLI
set -uo pipefail
cli="$1"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
out="$work/stdout"
err="$work/stderr"
failures=0
source "$here/contract_lib.sh"

expect_ok modes --max-impacts 4 --out "$work/m/atlas" || exit 1
python3 - "$work/m" <<'PY' || fail "modes files"
import array, ast, json, math, os, sys
d = sys.argv[1]
meta = json.load(open(d + '/atlas.json'))
assert meta['format'] == 'grazelab-modes' and meta['max_impacts'] == 4
fams = meta['families']
assert [f['id'] for f in fams] == list(range(len(fams)))
ones = [f for f in fams if f['impacts'] == 1]
assert ones and all(f['born_at']['kind'] == 'one-periodic' for f in ones)
T2 = meta['model']['T2']
for f in fams:
    lines = open(os.path.join(d, f['file'])).read().splitlines()
    assert lines[0] == meta['about']['columns'] == 'energy,period,omega,trace,stability,u1,v1,min_impact_speed,min_clearance'
    rows = [l.split(',') for l in lines[1:]]
    assert len(rows) == f['rows'] > 0
    b = open(os.path.join(d, f['file'][:-4] + '.npy'), 'rb').read(); n = b[8] | (b[9] << 8)
    h = ast.literal_eval(b[10:10 + n].decode('latin1')); a = array.array('d'); a.frombytes(b[10 + n:])
    assert h['shape'] == (len(rows), 9), h
    assert all(x != y for x, y in zip(rows, rows[1:])), 'a row repeated in ' + f['file']
    for i, r in enumerate(rows):
        assert float(r[0]) == a[9 * i] and float(r[1]) == a[9 * i + 1] and float(r[3]) == a[9 * i + 3]
        assert abs(float(r[2]) - 2 * math.pi / float(r[1])) < 1e-12 * float(r[2])
        tr = float(r[3])
        assert r[4] == ('elliptic' if abs(tr) < 2 else 'hyperbolic' if tr > 2 else 'flip-hyperbolic') or r[4] == 'parabolic', r
    assert f['end']['kind'] in ('grazing-orbit', 'interior-grazing', 'impact-speed-zero', 'energy-limit', 'step-limit', 'undecided'), f['end']
    for x in f['bifurcations']:
        if x['kind'] == 'period-doubling':
            assert abs(x['trace'] + 2) < 1e-8, x
            kids = [g for g in fams if g['born_at']['kind'] == 'period-doubling' and g['born_at']['family'] == f['id']
                    and g['born_at']['energy'] == x['energy']]
            if 2 * f['impacts'] <= 4:
                assert len(kids) == 1 and kids[0]['impacts'] == 2 * f['impacts'] and kids[0]['side'] in ('below', 'above'), (x, kids)
# the 1IPP family of the grazing end: from GLO(lambda*) at T2
ends = [f for f in ones if f['start']['kind'] == 'grazing-orbit' and abs(f['start']['period'] - T2) < 1e-5 * T2]
assert len(ends) == 1, [f['start'] for f in ones]
assert any(f['impacts'] == 4 for f in fams)
PY
[ -e "$work/m/atlas.png" ] && [ -e "$work/m/atlas.svg" ] || [ ! -e "$work/m/atlas.svg" ] || fail "modes picture"

# an energy range finds the families that reach into it, wherever they were started
expect_ok modes --energy-range 0.2:1 --out "$work/r/atlas" || exit 1
python3 - "$work/r/atlas.json" <<'PY' || fail "modes --energy-range"
import json, sys
fams = json.load(open(sys.argv[1]))['families']
assert any(f['impacts'] == 1 for f in fams), fams
two = [f for f in fams if f['impacts'] == 2]
assert len(two) == 1 and abs(two[0]['born_at']['energy'] - 0.7) < 1e-9, two  # born at the flip at E = 0.7
for f in fams:
    assert f['end']['kind'] == 'energy-limit' and f['end']['energy'] <= 1, f['end']
PY
expect_ok modes --energy-range 0.01:0.1 --out "$work/r/none" || exit 1
python3 -c "import json,sys; assert json.load(open(sys.argv[1]))['families'] == []" "$work/r/none.json" || fail "an empty range"

# any chain but the note's 1:2 one takes the atlas of any chain: three masses stopped on the last,
# and two masses off the design; their files are the document's families, row for row
for chain in "--masses 1,0.7,0.4 --frequencies 3:2:1 --max-impacts 2" "--k2 0.6 --max-impacts 2"; do
  rm -rf "$work/c"
  # shellcheck disable=SC2086
  expect_ok modes $chain --out "$work/c/atlas" || exit 1
  python3 - "$work/c" <<'PY' || fail "modes $chain"
import array, ast, csv, json, pathlib, sys
d = pathlib.Path(sys.argv[1])
meta = json.load(open(d / 'atlas.json'))
assert meta['format'] == 'grazelab-modes' and 'model' not in meta, meta.keys()
n = len(meta['chain']['masses'])
columns = meta['about']['columns'].split(',')
assert len(columns) == 5 + 2 * n + 3 * (2 * n - 2), columns
assert meta['families'] and any(f['born_at']['kind'] == 'period-doubling' for f in meta['families'])
for f in meta['families']:
    rows = list(csv.reader(open(d / f['file'])))
    assert rows[0] == columns and len(rows) - 1 == f['rows'] > 0
    raw = (d / f['file'].replace('.csv', '.npy')).read_bytes()  # (.npy 1.0: its header, then float64)
    size = int.from_bytes(raw[8:10], 'little')
    assert ast.literal_eval(raw[10:10 + size].decode())['shape'] == (f['rows'], len(columns))
    table = array.array('d', raw[10 + size:])
    assert table[-len(columns)] == f['end']['orbit']['energy'] == float(rows[-1][0])
    assert {r[3] for r in rows[1:]} <= {'elliptic', 'hyperbolic', 'flip-hyperbolic', 'complex-quadruplet', 'undecided'}
    for b in f['bifurcations']:
        assert b['kind'] in ('period-doubling', 'fold', 'krein-collision', 'other')
        if b['kind'] == 'period-doubling':
            assert b['branch'] in ('born', 'reached', 'not-found', 'beyond-impacts')
PY
  [ ! -e "$work/c/atlas.svg" ] || [ -e "$work/c/atlas.png" ] || fail "modes $chain picture"
done

# family --impacts: the family of an orbit found from a guess, followed both ways, written as an
# atlas of that one family; the orbit it starts from lies on it
three="--masses 0.6865,1.963,0.8236 --springs 0.8423,1.0745,0.7486 --stop-mass 2"
# shellcheck disable=SC2086
expect_ok family --impacts 2 --energy 23.412611915561559 --guess=1.28,-6.54,0.01,-0.01 $three --count 300 \
  --out "$work/f/fam" || exit 1
python3 - "$work/f" <<'PY' || fail "family --impacts"
import csv, json, pathlib, sys
d = pathlib.Path(sys.argv[1])
meta = json.load(open(d / 'fam.json'))
[f] = meta['families']
assert f['born_at']['kind'] == 'given-orbit' and f['impacts'] == 2 and f['start'] is not None
rows = list(csv.reader(open(d / f['file'])))
assert len(rows) - 1 == f['rows'] <= 2 * 300
assert any(abs(float(r[0]) - 23.412611915561559) < 1e-9 for r in rows[1:]), "the start is a row"
assert (d / 'fam.png').exists() or not (d / 'fam.svg').exists()
PY
# shellcheck disable=SC2086
EXPECT_WORD="--guess" expect_invalid family --impacts 2 --energy 23.4 $three --out "$work/bad/f"
# shellcheck disable=SC2086
EXPECT_WORD="belongs to family --impacts" expect_invalid family --onepp --energy-range 1:2 $three --out "$work/bad/f"
# shellcheck disable=SC2086
EXPECT_WORD="no --onepp" expect_invalid family --onepp --impacts 2 --energy 23.4 --guess=1,1,0,0 $three --out "$work/bad/f"
# shellcheck disable=SC2086
EXPECT_WORD="no orbit to follow" expect_invalid family --impacts 2 --energy 23.4 --guess=50,50,0,0 $three --out "$work/bad/f"
# shellcheck disable=SC2086
EXPECT_WORD="outside" expect_invalid family --impacts 2 --energy 23.412611915561559 --guess=1.28,-6.54,0.01,-0.01 $three \
  --energy-range 1:2 --out "$work/bad/f"

EXPECT_WORD="--max-impacts" expect_invalid modes --max-impacts 0 --out "$work/bad/m"
EXPECT_WORD="--energy-range" expect_invalid modes --energy-range 2:1 --out "$work/bad/m"
EXPECT_WORD="--out" expect_invalid modes
EXPECT_WORD="does not apply" expect_invalid modes --contacts 3 --out "$work/bad/m"
[ ! -e "$work/bad" ] || [ -z "$(ls -A "$work/bad")" ] || fail "a refused atlas wrote files"
# SIGINT one second into the binary128 atlas (its scans, bisections, Newton loops and
# continuations all watch the stop): exit 130 within a second, no files (issue 29, item 9)
start=$(date +%s%N)
timeout --preserve-status -s INT 1 "$cli" modes --precision quad --out "$work/int/m" 2>"$err"
code=$?
took_ms=$(( ($(date +%s%N) - start) / 1000000 ))
[ "$code" -eq 130 ] || fail "interrupted modes exited $code, not 130"
[ "$took_ms" -lt 2000 ] || fail "modes --precision quad took $took_ms ms to stop (1000 of them before the signal)"
[ ! -e "$work/int/m.json" ] || fail "an interrupted atlas wrote its files"
# and the atlas of three masses likewise
start=$(date +%s%N)
timeout --preserve-status -s INT 1 "$cli" modes --masses 1,0.7,0.4 --frequencies 3:2:1 --precision quad \
  --out "$work/int/c" 2>"$err"
code=$?
took_ms=$(( ($(date +%s%N) - start) / 1000000 ))
[ "$code" -eq 130 ] || fail "interrupted modes of three masses exited $code, not 130"
[ "$took_ms" -lt 2000 ] || fail "modes of three masses in quad took $took_ms ms to stop"
[ ! -e "$work/int/c.json" ] || fail "an interrupted atlas of three masses wrote its files"

if [ "$failures" -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "modes: all checks passed"
