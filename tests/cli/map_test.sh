#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# `map` and `merge` (issue 10): four stripes computed through GNU parallel and merged equal the
# unsharded map byte for byte; the files are what docs/cli.md promises; bad input is refused.
# Usage: map_test.sh GRAZELAB_CLI pictures|no-pictures
set -uo pipefail
cli="$1"
pictures="${2:-pictures}"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
out="$work/stdout"
err="$work/stderr"
failures=0
source "$here/contract_lib.sh"

if ! command -v parallel >/dev/null; then
  echo "FAIL: GNU parallel is missing (tools/setup-debian.sh installs the Debian package 'parallel')"
  exit 1
fi
quantities="fft_first fft_min fft_max fft_mean impacts grazings sticks first_impact_time horizon"
grid=(--x u1:-1:2:40 --y v1:-1.5:1.5:27 --contacts 6 --trust auto)

# the whole map, then stripe k of 4 in four processes at once, merged
expect_ok map "${grid[@]}" --out "$work/whole/map" || exit 1
parallel --halt now,fail=1 "$cli" map "${grid[@]}" --threads 1 --shard {}/4 --out "$work/parts/part{}" \
  ::: 1 2 3 4 2>"$err" || fail "parallel shards: $(cat "$err")"
expect_ok merge --out "$work/merged/map" "$work/parts/part1" "$work/parts/part2" \
  "$work/parts/part3" "$work/parts/part4"
for q in $quantities; do
  cmp -s "$work/whole/map-$q.npy" "$work/merged/map-$q.npy" || fail "merged $q differs from the whole map"
done
cmp -s "$work/whole/map.csv" "$work/merged/map.csv" || fail "merged CSV differs from the whole map's"
# the stripes given in another order merge the same
expect_ok merge --out "$work/merged2/map" "$work/parts/part3" "$work/parts/part1" \
  "$work/parts/part4" "$work/parts/part2"
cmp -s "$work/whole/map-fft_first.npy" "$work/merged2/map-fft_first.npy" || fail "merge depends on the order of the parts"
# one thread and all threads: the same bytes
expect_ok map "${grid[@]}" --threads 1 --out "$work/one/map"
for q in $quantities; do
  cmp -s "$work/whole/map-$q.npy" "$work/one/map-$q.npy" || fail "$q differs between 1 and all threads"
done

# the files: npy shapes and types, the JSON's axes and T2, the grazing family at T2 exactly
python3 - "$work" <<'PY' || fail "file contents"
import array, ast, json, math, sys
work = sys.argv[1]
def load(path):
    b = open(path, 'rb').read()
    assert b[:6] == b'\x93NUMPY' and b[6] == 1, path
    n = b[8] | (b[9] << 8)
    assert (10 + n) % 64 == 0, 'header not aligned to 64 bytes'
    h = ast.literal_eval(b[10:10 + n].decode('latin1'))
    a = array.array('d' if h['descr'] == '<f8' else 'q'); a.frombytes(b[10 + n:])
    return h, a
meta = json.load(open(work + '/whole/map.json'))
spec, run = meta['spec'], meta['run']
assert {k: spec['x'][k] for k in ('variable', 'from', 'to', 'count')} == {'variable': 'u1', 'from': -1, 'to': 2, 'count': 40}, spec['x']
assert run['shape'] == [27, 40] and run['rows'] == [0, 27]
for q, info in spec['quantities'].items():
    h, a = load(work + '/whole/map-%s.npy' % q)
    assert h['shape'] == (27, 40) and h['fortran_order'] is False, (q, h)
    assert h['descr'] == ('<i8' if info['dtype'] == 'int64' else '<f8'), (q, h)
T2 = spec['model']['T2']
_, fft = load(work + '/whole/map-fft_first.npy')
assert all(f <= T2 for f in fft if f == f), 'a first flight longer than T2'
assert any(f == T2 for f in fft) and any(f < T2 for f in fft)
_, horizon = load(work + '/whole/map-horizon.npy')
_, impacts = load(work + '/whole/map-impacts.npy')
# every run's horizon estimated; the one point with no run is GLOM_1's data (u1 = -d at rest,
# column 0, row 13: a touch at T1 no precision decides), said so with counts -1
assert all(h > 0 for i, h in enumerate(horizon) if i != 13 * 40), 'horizon not estimated with --trust auto'
assert impacts[13 * 40] == -1 and horizon[13 * 40] != horizon[13 * 40], 'GLOM_1 is run, not left undecided'
# the CSV row of (column 3, row 5) is the arrays' [5, 3]
rows = [l.split(',') for l in open(work + '/whole/map.csv').read().splitlines()]
head, row = rows[0], next(r for r in rows[1:] if r[0] == '3' and r[1] == '5')
assert float(row[head.index('fft_first')]) == fft[5 * 40 + 3]
PY

# GLO_lambda over lambda in [0, 4/3] (lambda > 0): every flight lasts T2 exactly
expect_ok map --x lambda:0.125:1.3333333333333333:8 --y gap:0.5:2:3 --contacts 5 --out "$work/glo/map"
python3 - "$work" <<'PY' || fail "the grazing family is not at T2 exactly"
import array, ast, json, sys
work = sys.argv[1]
b = open(work + '/glo/map-fft_first.npy', 'rb').read(); n = b[8] | (b[9] << 8)
a = array.array('d'); a.frombytes(b[10 + n:])
T2 = json.load(open(work + '/glo/map.json'))['spec']['model']['T2']
assert all(x == T2 for x in a), (T2, sorted(set(a)))
PY

if [ "$pictures" = pictures ]; then
  for suffix in png svg; do
    [ -s "$work/whole/map.$suffix" ] || fail "no map.$suffix"
    [ -s "$work/merged/map.$suffix" ] || fail "no merged map.$suffix"
  done
  [ ! -e "$work/parts/part1.png" ] || fail "a stripe drew a picture of itself"
  # well-formed XML whose description is the map's spec
  python3 - "$work/whole/map.svg" <<'PY' || fail "map.svg is not well-formed or lacks its spec"
import json, sys, xml.etree.ElementTree as ET
desc = ET.parse(sys.argv[1]).getroot().find('{http://www.w3.org/2000/svg}desc').text
assert json.loads(desc)['format'] == 'grazelab-map'
PY
fi

# more stripes than rows: the empty ones merge away
parallel "$cli" map --x u1:-1:2:5 --y v1:-1:1:3 --threads 1 --shard {}/4 --out "$work/few/part{}" \
  ::: 1 2 3 4 2>"$err" || fail "shards of 3 rows: $(cat "$err")"
expect_ok merge --out "$work/few/merged" "$work/few/part4" "$work/few/part2" "$work/few/part1" "$work/few/part3"
expect_ok map --x u1:-1:2:5 --y v1:-1:1:3 --out "$work/few/whole"
cmp -s "$work/few/whole-fft_first.npy" "$work/few/merged-fft_first.npy" || fail "3 rows in 4 stripes merge wrong"

# counts at points with no run are -1, not 0 (a designed chain has no m2/m1 above 9/16)
expect_ok map --x mass-ratio:0.5:0.7:3 --y v1:0:0:1 --out "$work/ratio/map"
python3 - "$work" <<'PY' || fail "counts where nothing was run"
import sys
rows = [l.split(',') for l in open(sys.argv[1] + '/ratio/map.csv').read().splitlines()]
head = rows[0]
last = rows[-1]  # m2/m1 = 0.7
assert last[head.index('impacts')] == '-1' and last[head.index('fft_first')] == 'nan', last
assert rows[1][head.index('impacts')] != '-1', rows[1]
PY

# refused, with one line, nothing written
EXPECT_WORD="--onepp" expect_invalid map --x u1:0:1:3 --y v1:0:1:3 --onepp 100 --out "$work/bad/a"
EXPECT_WORD="different variables" expect_invalid map --x u1:0:1:3 --y u1:0:1:3 --out "$work/bad/a"
EXPECT_WORD="mass-ratio" expect_invalid map --x speed:0:1:3 --y v1:0:1:3 --out "$work/bad/a"
EXPECT_WORD="count from 1" expect_invalid map --x u1:0:1:3 --y v1:0:1:3 --shard 0/4 --out "$work/bad/a"
EXPECT_WORD="NAME:from:to:count" expect_invalid map --x u1:0:1 --y v1:0:1:3 --out "$work/bad/a"
EXPECT_WORD="--out" expect_invalid map --x u1:0:1:3 --y v1:0:1:3
EXPECT_WORD="lambda" expect_invalid map --x lambda:0:1:3 --y u1:0:1:3 --out "$work/bad/a"
EXPECT_WORD="--picture" expect_invalid map --x u1:0:1:3 --y v1:0:1:3 --picture speed --out "$work/bad/a"
EXPECT_WORD="only to 'map'" expect_invalid simulate --x u1:0:1:3
[ ! -e "$work/bad" ] || [ -z "$(ls -A "$work/bad")" ] || fail "a refused map wrote files"
EXPECT_WORD="missing" expect_invalid merge --out "$work/bad2/m" "$work/parts/part1" "$work/parts/part2" "$work/parts/part4"
EXPECT_WORD="twice" expect_invalid merge --out "$work/bad2/m" "$work/parts/part1" "$work/parts/part1" \
  "$work/parts/part2" "$work/parts/part3" "$work/parts/part4"
expect_ok map --x u1:-1:2:40 --y v1:-1.5:1.5:27 --contacts 7 --shard 2/4 --out "$work/other/part2"
EXPECT_WORD="different maps" expect_invalid merge --out "$work/bad2/m" "$work/parts/part1" \
  "$work/other/part2" "$work/parts/part3" "$work/parts/part4"
[ ! -e "$work/bad2/m.json" ] || fail "a refused merge wrote files"

# a chain of N masses (3:2:1, axes u3 and v3 of the start): stripes merge to the whole map, a
# point is the simulate run it names (its first flight from the stop, its impacts), flights
# from the stop last at most the chain's period T, and the spec names the chain and the period
nm=(--masses 1,0.2,0.05 --frequencies 3:2:1 --state 0,0,0.5,0,0,0 --x u3:-1:0.9:24 --y v3:-2:2:18 --contacts 5)
expect_ok map "${nm[@]}" --out "$work/n/whole" || exit 1
for k in 1 2 3; do expect_ok map "${nm[@]}" --shard $k/3 --threads 1 --out "$work/n/part$k"; done
expect_ok merge --out "$work/n/merged" "$work/n/part1" "$work/n/part2" "$work/n/part3"
for q in $quantities; do
  cmp -s "$work/n/whole-$q.npy" "$work/n/merged-$q.npy" || fail "N masses: merged $q differs from the whole map"
done
if expect_ok simulate --masses 1,0.2,0.05 --frequencies 3:2:1 --state 0,0,-0.83478260869565224,0,0,1.7647058823529411 --contacts 5 --trust off; then
  python3 -c "
import csv, json, math
spec = json.load(open('$work/n/whole.json'))['spec']
assert spec['chain']['masses'] == [1, 0.2, 0.05] and spec['x']['variable'] == 'u3' and spec['contacts'] == 5, spec
T = spec['period']
assert abs(T - spec['chain']['period']) < 1e-12 * T, spec
rows = list(csv.DictReader(open('$work/n/whole.csv')))
assert len(rows) == 24 * 18 and 'u3' in rows[0] and 'v3' in rows[0], rows[0]
point = [r for r in rows if r['column'] == '2' and r['row'] == '16'][0]
assert float(point['u3']) == -0.83478260869565224 and float(point['v3']) == 1.7647058823529411, point
events = json.load(open('$out'))['events']
assert [e['type'] for e in events] == ['impact'] * 5, events
assert int(point['impacts']) == 5 and abs(float(point['fft_first']) - (events[1]['t'] - events[0]['t'])) < 1e-12 * T, (point, events)
flights = [float(r['fft_first']) for r in rows if math.isfinite(float(r['fft_first']))]
assert len(flights) > 100 and max(flights) <= T * (1 + 1e-12), max(flights)" || fail "a map of N masses"
fi
# with no --state a map of N masses starts on the grazing-start plane, as the two-mass map: the
# stopped mass (here the second of three, with a wall; gap 0.7) at rest on the stop, all else 0
plane=(--masses 1,0.5,2 --springs 1,0.8,1.3 --right-spring 0.4 --stop-mass 2 --gap 0.7 --x u1:-0.5:0.5:4 --y v3:-0.3:0.3:3 --contacts 6)
expect_ok map "${plane[@]}" --out "$work/plane/default" &&
  expect_ok map "${plane[@]}" --state 0,0.7,0,0,0,0 --out "$work/plane/given" &&
  for q in $quantities; do
    cmp -s "$work/plane/default-$q.npy" "$work/plane/given-$q.npy" || fail "N masses: the default start is not the grazing-start plane ($q)"
  done
EXPECT_WORD="u<i>|v<i>" expect_invalid map --masses 1,1 --springs 1,1 --x lambda:0:1:3 --y u1:0:1:3 --out "$work/bad3/a"
EXPECT_WORD="--state" expect_invalid map --masses 1,1 --springs 1,1 --x u1:0:1:3 --y v1:0:1:3 --glo 0.5 --out "$work/bad3/a"
EXPECT_WORD="given by --masses" expect_invalid map --springs 1,1 --x u1:0:1:3 --y v1:0:1:3 --out "$work/bad3/a"
[ ! -e "$work/bad3" ] || [ -z "$(ls -A "$work/bad3")" ] || fail "a refused N-mass map wrote files"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "map and merge: all checks passed"
