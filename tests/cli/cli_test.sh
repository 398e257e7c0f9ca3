#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# The command-line contract of docs/design.md: outputs on success, exit 2 with one line on stderr
# and nothing on stdout for every invalid input.
set -u
cli="$1"
failures=0
out=$(mktemp)
err=$(mktemp)
work=$(mktemp -d)
trap 'rm -rf "$out" "$err" "$work"' EXIT

source "$(dirname "$0")/contract_lib.sh"

# invalid input, each with the word its message must contain
for bad in 0 -1 nan inf -inf abc; do
  EXPECT_WORD=m1 expect_invalid simulate --m1 "$bad"
  EXPECT_WORD=gap expect_invalid info --gap "$bad"
  EXPECT_WORD=k2 expect_invalid simulate --k2 "$bad"
done
EXPECT_WORD=m2 expect_invalid simulate --m2 nan
EXPECT_WORD=k1 expect_invalid info --k1 0
EXPECT_WORD="9/16" expect_invalid info --m2 0.6
EXPECT_WORD="9/16" expect_invalid simulate --m2 0.6 --branch lower
EXPECT_WORD=branch expect_invalid simulate --branch middle
EXPECT_WORD=exclude expect_invalid simulate --k2 0.5 --branch upper
EXPECT_WORD="past the stop" expect_invalid simulate --state 0,1.5,0,0
EXPECT_WORD="past the stop" expect_invalid simulate --glo 0.5 --perturb 0,0.1,0,0
EXPECT_WORD=state expect_invalid simulate --state 1,2,3
EXPECT_WORD=u1 expect_invalid simulate --state nan,0,0,0
EXPECT_WORD=perturb expect_invalid simulate --perturb 0,0,x,0
EXPECT_WORD=glo expect_invalid simulate --glo inf
EXPECT_WORD=onepp expect_invalid simulate --onepp 9.5
EXPECT_WORD=onepp expect_invalid simulate --onepp -1
EXPECT_WORD=contacts expect_invalid simulate --contacts -5
EXPECT_WORD=contacts expect_invalid simulate --contacts 1.5
EXPECT_WORD=t-end expect_invalid simulate --t-end nan
EXPECT_WORD=format expect_invalid simulate --format xml
EXPECT_WORD="one of" expect_invalid simulate --glo 0.5 --state 0,0,0,0
EXPECT_WORD=simulate expect_invalid info --glo 0.5
EXPECT_WORD=unknown expect_invalid frobnicate
EXPECT_WORD=command expect_invalid
EXPECT_WORD=Unknown expect_invalid simulate --no-such-flag
EXPECT_WORD=Missing expect_invalid simulate --m1

# every command refuses, before it runs, each option it does not take (issue "One
# architecture…", item 6: `simulate --max-impacts 7` ran and exited 0), naming who takes it
EXPECT_WORD="only to 'modes'" expect_invalid simulate --max-impacts 7
EXPECT_WORD="not apply to 'family'" expect_invalid family --onepp --energy-range 0.5:5 --max-impacts 1 --out "$work/f"
EXPECT_WORD="the parts say" expect_invalid merge --period 3 --out "$work/m" a b
EXPECT_WORD="more than once" expect_invalid map -x u1:0:1:2 -x u1:0:1:3 -y v1:0:1:2 --out "$work/m"
python3 - "$cli" <<'PY' || fail "the options each command takes"
import subprocess, sys
cli = sys.argv[1]
model = ["m1", "m2", "k1", "gap", "k2", "branch", "precision"]
start = ["glo", "onepp", "state", "perturb"]
takes = {
    "info": model + ["masses", "springs", "right-spring", "stop-mass", "frequencies", "design-branch"],
    "simulate": model + start + ["contacts", "t-end", "search-steps", "format", "trust",
                                 "sample-step", "sample-times", "masses", "springs", "right-spring",
                                 "stop-mass", "frequencies", "design-branch", "glo-weights"],
    "report": model[:-1] + start + ["contacts", "t-end", "out", "methods", "quick", "masses", "springs",
                                    "right-spring", "stop-mass", "frequencies", "design-branch", "glo-weights"],
    "stability": ["out", "methods", "quick", "masses", "springs", "right-spring", "stop-mass", "frequencies",
                  "design-branch", "gap", "state", "onepp", "perturb", "glo-weights"],
    "map": model + start + ["contacts", "trust", "out", "x", "y", "threads", "shard", "picture", "masses",
                            "springs", "right-spring", "stop-mass", "frequencies", "design-branch", "glo-weights"],
    "merge": ["out"],
    "family": model + ["onepp", "out", "count", "masses", "springs", "right-spring", "stop-mass",
                       "frequencies", "design-branch", "impacts", "energy", "period", "guess", "energy-range"],
    "orbit": model + ["onepp", "format", "period", "impacts", "energy", "guess", "masses", "springs",
                      "right-spring", "stop-mass", "frequencies", "design-branch"],
    "modes": model + ["out", "max-impacts", "energy-range", "masses", "springs", "right-spring",
                      "stop-mass", "frequencies", "design-branch"],
    "glo-set": model + ["masses", "springs", "right-spring", "stop-mass", "frequencies", "design-branch",
                        "directions", "out"],
    "bar": ["bar", "speed", "masses-count", "stop-end", "each-impact"],
}
options = sorted({o for names in takes.values() for o in names})
help_text = subprocess.run([cli, "--help"], capture_output=True, text=True).stdout
for option in options:  # the table names every option the program has, and no other
    assert (f"--{option} " in help_text or f"-{option} " in help_text), option
# an option a command takes may start real work: a refusal comes before any, so a run still
# going long after a refusal would have come was not refused (killed; it runs in a folder of its
# own). How long a refusal takes is measured here, eight at once as the probes run: under the
# sanitizers on a loaded machine a refusal alone took more than a second
import concurrent.futures, tempfile, time
def refusal_seconds(_):
    began = time.monotonic()
    subprocess.run([cli, "info", "--quick", "1"], capture_output=True)
    return time.monotonic() - began
with concurrent.futures.ThreadPoolExecutor(8) as pool:
    limit = max(1.0, 5 * max(pool.map(refusal_seconds, range(8))))
def probe(case):
    command, option = case
    flag = f"-{option}" if len(option) == 1 else f"--{option}"
    args = [cli, command, flag] + ([] if option in ("quick", "each-impact") else ["1"]) + (["part"] if command == "merge" else [])
    try:
        run = subprocess.run(args, capture_output=True, text=True, timeout=limit, cwd=work)
    except subprocess.TimeoutExpired:
        return None if option in takes[command] else f"{command} {flag}: not refused (still running)"
    refused = "not apply to" in run.stderr
    if refused != (option not in takes[command]) or (refused and run.returncode != 2):
        return f"{command} {flag}: exit {run.returncode}, {run.stderr.strip()[:120]}"
    return None
with tempfile.TemporaryDirectory() as work, concurrent.futures.ThreadPoolExecutor(8) as pool:
    wrong = [w for w in pool.map(probe, [(c, o) for c in takes for o in options]) if w]
assert not wrong, "\n".join(wrong)
PY

# info: the derived quantities of the m2 = 1/2 chain
if expect_ok info; then
  python3 - "$out" <<'PY' || fail "info JSON"
import json, math, sys
model = json.load(open(sys.argv[1]))["model"]
assert abs(model["k2"] - 0.5) < 1e-15, model["k2"]
assert abs(model["omega1"] ** 2 - 2) < 1e-14 and abs(model["omega2"] ** 2 - 0.5) < 1e-14
assert abs(model["T2"] - 2 * model["T1"]) < 1e-14 and model["resonant"] is True
assert abs(model["lambda_star"] - 8 / 9) < 1e-15
PY
fi
if expect_ok info --branch lower; then
  python3 -c "import json,sys; m=json.load(open('$out'))['model']; assert abs(m['k2']-2/9)<1e-15" \
    || fail "lower branch k2"
fi

# simulate json: fields, types, round-trip numbers, grazing GLO every T2
if expect_ok simulate --glo 0.5 --contacts 3; then
  python3 - "$out" <<'PY' || fail "simulate JSON (grazing)"
import json, sys
doc = json.load(open(sys.argv[1]))
# one document for every chain: the chain, the note's model of it, the start, ...
assert list(doc)[:4] == ["chain", "model", "initial", "events"], list(doc)
for key in ("final", "stop_reason", "contacts", "energy", "accuracy", "trust", "precision", "timing"):
    assert key in doc, key
assert doc["chain"]["masses"] == [1, 0.5] and doc["chain"]["stop_mass"] == 2, doc["chain"]
T2 = doc["model"]["T2"]
assert [e["type"] for e in doc["events"]] == ["grazing"] * 3
for k, e in enumerate(doc["events"], 1):
    assert abs(e["t"] - k * T2) <= 1e-14 * k * T2, (e["t"], k * T2)
    assert set(e) == {"t", "type", "u1", "u2", "v1_pre", "v2_pre", "v2_post"}
assert set(doc["final"]) == {"t", "u1", "u2", "v1", "v2"}
assert set(doc["energy"]) >= {"initial", "final", "max_rel_drift"}
assert set(doc["contacts"]) == {"total", "impacts", "grazings", "sticks", "releases"}, doc["contacts"]
PY
fi
if expect_ok simulate --glo 0.5 --perturb 0,0,0,-1e-3 --contacts 5; then
  python3 - "$out" <<'PY' || fail "simulate JSON (impacts)"
import json, sys
doc = json.load(open(sys.argv[1]))
events = doc["events"]
assert [e["type"] for e in events] == ["impact"] * 5
for e in events:
    assert e["v2_pre"] > 0 and e["v2_post"] == -e["v2_pre"] and e["u2"] == 1
    assert e["t"] < 10 * doc["model"]["T2"]
PY
fi
if expect_ok simulate --glo 1.5 --contacts 3; then
  python3 -c "
import json; d=json.load(open('$out')); t=[e['type'] for e in d['events']]
assert t[:2]==['stick','release'] and 'impact' in t, t" || fail "sticking start"
fi
if expect_ok simulate --onepp 8.5 --contacts 3 --format csv; then
  [ "$(head -1 "$out")" = "t,type,u1,u2,v1_pre,v2_pre,v2_post" ] || fail "csv header"
  [ "$(grep -c ',impact,' "$out")" -eq 3 ] || fail "1IPP csv rows"
fi
if expect_ok simulate --glo 0.5 --perturb 0,0,0,-0.05 --contacts 1000 --format summary; then
  grep -q "contacts       1000 (impacts 1000" "$out" || fail "summary counts: $(cat "$out")"
fi
if expect_ok simulate --k2 0.45 --state=-0.25,1,0,-0.05 --t-end 50; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['model']['resonant'] is False and d['final']['t']==50 and d['stop_reason']=='time-limit'" \
    || fail "detuned run to t-end"
fi

# issue 20: a touch double cannot decide is decided in binary128 (--precision auto, the
# default), and says so; in a fixed precision the verdict is not ok
if expect_ok simulate --glo 0 --perturb 0,0,0,-3e-9 --contacts 60; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['model']['precision'] == 'auto', d['model']['precision']
assert d['precision']['used'] == 'quad' and len(d['precision']['escalations']) == 2, d['precision']
assert d['contacts']['impacts'] == 60, d['contacts']
assert abs(d['final']['t'] - 359.87351789519487) < 1e-9, d['final']['t']" || fail "auto precision"
fi
# a chain beyond a precision's reach (a ratio beyond double's range; a fast phase that is
# rounding in double and long double) is refused there with the flag that helps, and raised by
# --precision auto: the refusal is typed as the precision's, not recognised by its words
if expect_ok simulate --m1 1e200 --m2 1e-200 --glo 0.5 --perturb 0,0,0,-1e-3 --contacts 3; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['precision']['used'] == 'long' and d['precision']['escalations'][0].startswith('from double: the ratios'), d['precision']
assert d['contacts']['impacts'] == 3, d['contacts']" || fail "a ratio beyond double's range raised"
fi
EXPECT_WORD="try --precision long or quad" expect_invalid simulate --m1 1e200 --m2 1e-200 --glo 0.5 --contacts 3 --precision double
if expect_ok simulate --k2 1e-30 --state 0,0,0,1 --contacts 1 --trust off; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['precision']['used'] == 'quad' and len(d['precision']['escalations']) == 2, d['precision']
assert d['contacts']['impacts'] == 1, d['contacts']" || fail "a fast phase rounding in double raised"
fi
EXPECT_WORD="--precision quad resolves more" expect_invalid simulate --k2 1e-30 --state 0,0,0,1 --contacts 1 --precision long
# issue 29: a run raised to binary128 says the start it used, in binary128's digits (the head,
# written before the raise, holds double's): the 1IPP orbit 3e-11 below T1, whose closed form
# loses digits there (its v2 differs from double's by 2e-6 relative)
if expect_ok simulate --onepp 4.44288293802508 --contacts 30; then
  python3 -c "
import json; from decimal import Decimal; d=json.load(open('$out'), parse_float=Decimal)
used = d['precision']['initial_state_used']; head = d['initial']['state']
assert d['precision']['used'] == 'quad', d['precision']
assert len(str(used['v2'])) > 30, used  # binary128's digits
assert abs(used['v2'] / head['v2'] - 1) > Decimal('1e-7'), (used, head)" \
    || fail "the start a raised run used"
fi
# in a fixed precision such a touch ends the run there, undecided, and says why (the run is not
# taken past a contact it cannot decide)
if expect_ok simulate --glo 0 --perturb 0,0,0,-3e-9 --contacts 60 --precision double; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['stop_reason'] == 'undecided' and d['contacts']['total'] < 60, (d['stop_reason'], d['contacts'])
assert 'precision auto raises' in d['message'], d['message']
assert d['trust']['verdict'] != 'ok' and 'cannot decide' in d['trust']['reason'], d['trust']" || fail "undecided in a fixed precision"
fi
# a raised run refused after a lower precision wrote events (the start past the stop in binary128
# only) closes its json whole, undecided, with exit 2 and the reason; the note's kernel whose
# springs are a 1:2 design's only to double's digits keeps an error estimate (the chain's)
"$cli" simulate --masses 1,1,0.5 --springs 1,1,0.5 --contacts 3 \
  --state 1,1.0000000000000002220446049250313080847263336181640625,1.0000000000000000000000001,0,0,0 >"$out" 2>"$err"
[ "$?" -eq 2 ] && grep -q "past the stop" "$err" && python3 -c "
import json; d=json.load(open('$out'))
assert d['stop_reason'] == 'undecided' and 'refused' in d['message'] and len(d['events']) == 2, d" ||
  fail "a raise refused after events were written: $(tail -c 300 "$out") $(cat "$err")"
if expect_ok simulate --masses 1,0.3 --springs 1,0.096591329157701 --state 0,0,0,1 --contacts 5; then
  python3 -c "
import json; d=json.load(open('$out'))
assert 'model' in d and d['trust']['verdict'] == 'ok', d['trust']" || fail "the note's kernel on a double-digit design keeps an estimate"
fi
# events written in long double before a raise to binary128 keep long double's error (event 1
# here is 1.6e-12 T2 off the 50-digit reference): the estimate covers them
if expect_ok simulate --glo 0 --perturb 0,0,0,-7e-9 --contacts 30 --branch lower; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['precision']['used'] == 'quad', d['precision']
assert d['trust']['estimated_time_error'] >= 1e-12, d['trust']
assert 'written before the raise' in d['trust']['reason'], d['trust']['reason']" \
    || fail "estimate of events written before a raise"
fi
# the fast mode's data alone (GLO_0), unpushed, names the slow mode still: its touches at T1 =
# T2/2 are decided exactly in every precision (the rounded state alone holds 1e-17 of the slow
# mode, a touch no precision decides), on both branches and other masses; the map's lambda = 0
# point is the same run
for chain in "" "--branch lower --m2 0.3 --m1 1.7 --gap 0.4"; do
  for precision in double long quad; do
    # shellcheck disable=SC2086
    if expect_ok simulate --glo 0 --contacts 6 --precision $precision $chain; then
      python3 -c "
import json; d=json.load(open('$out'))
T2 = float(d['model']['T2'])
assert d['stop_reason'] == 'contact-limit' and d['contacts']['grazings'] == 6, d['contacts']
for k, e in enumerate(d['events'], 1):
    assert abs(float(e['t']) - k * T2 / 2) <= 1e-12 * T2, (k, e['t'])
assert d['trust']['verdict'] == 'ok', d['trust']" || fail "GLO_0 grazes at T1 ($precision $chain)"
    fi
  done
  # shellcheck disable=SC2086
  if expect_ok map --x lambda:0:1:3 --y epsilon:0:0:1 --contacts 6 $chain --out "$work/glo0map/m"; then
    python3 -c "
import csv; rows = list(csv.DictReader(open('$work/glo0map/m.csv')))
assert rows[0]['grazings'] == '6' and rows[0]['impacts'] == '0', rows[0]" || fail "the map's GLO_0 point ($chain)"
  fi
done
# an exhausted search is its own stop, never 'no contact' (mass 2 moves away first; its
# amplitude 1.0015 gaps brings it back after about half a slow period)
if expect_ok simulate --k2 1e-6 --state 0,0.999,0,-1e-4 --contacts 1 --search-steps 10; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['stop_reason'] == 'search-budget' and d['trust']['verdict'] != 'ok', d
assert d['trust']['reason'].startswith('no contact'), d['trust']['reason']" \
    || fail "search budget"
fi
# at rest at 0.999 its amplitudes fall short of the stop: never a contact, said at once
if expect_ok simulate --k2 1e-6 --state 0,0.999,0,0 --contacts 1 --search-steps 10; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['stop_reason'] == 'no-further-contact' and d['final']['t'] == 0 and d['trust']['verdict'] == 'ok', d" \
    || fail "amplitudes short of the stop"
fi
EXPECT_WORD=search-steps expect_invalid simulate --search-steps 0
EXPECT_WORD="two-mass chain's detuned flight" expect_invalid simulate --masses 1,1,1 --springs 1,1,1 --state 0,0,0,0,0,1 --search-steps 5
EXPECT_WORD="w1/w2" expect_invalid simulate --k1 0.5e-55 --k2 1 --t-end 1.62
# springs designed for frequency ratios (issue 32): every design listed, each in the ratio by
# the chain's own spectrum; the two-mass 1:2 request is the note's two branches; requests no
# chain meets, or malformed, are refused with exit 2 and one line
if expect_ok info --masses 1,0.2,0.05 --springs 2 --frequencies 3:2:1 --design-branch 4; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['ratios']['commensurate'] and d['ratios']['harmonics'] == [3, 2, 1], d['ratios']
assert d['design']['branch'] == 4 and len(d['design']['designs']) == 6, d['design']
assert d['chain']['springs'] == d['design']['designs'][3]['springs'], d['chain']
assert all(x['springs'][0] == 2 and x['ratio_error'] <= 1e-13 for x in d['design']['designs'])
k2 = [x['springs'][1] for x in d['design']['designs']]
assert k2 == sorted(k2, reverse=True), k2" || fail "a designed three-mass chain"
fi
for branch in upper:1 lower:2; do
  "$cli" info --m2 0.3 --k1 2 --branch "${branch%%:*}" >"$out" 2>"$err" || fail "info --branch ${branch%%:*}"
  note_k2=$(python3 -c "import json; print(json.load(open('$out'))['model']['k2'])")
  if expect_ok info --masses 1,0.3 --springs 2 --frequencies 2:1 --design-branch "${branch##*:}"; then
    python3 -c "
import json, math; d=json.load(open('$out'))
assert math.isclose(d['chain']['springs'][1], $note_k2, rel_tol=1e-14), (d['chain'], $note_k2)" \
      || fail "the 1:2 design's ${branch%%:*} branch"
  fi
done
# a right wall is kept as given and k2 ... kN designed around it: the designed chain (wall
# included) has the ratios by its own spectrum, and its run's flights from the stop last T
if expect_ok info --masses 1,0.2,0.05 --frequencies 3:2:1 --right-spring 0.01; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['chain']['right_spring'] == 0.01 and d['design']['solutions'] == 12, d['design']
assert len(d['design']['designs']) == 4 and all(x['ratio_error'] <= 1e-13 for x in d['design']['designs']), d['design']
assert d['ratios']['commensurate'] and d['ratios']['harmonics'] == [3, 2, 1], d['ratios']" || fail "a design with a right wall"
fi
EXPECT_WORD="no chain with these masses" expect_invalid info --masses 1,0.2,0.05 --frequencies 3:2:1 --right-spring 0.5
EXPECT_WORD="no chain with these masses" expect_invalid info --masses 1,0.6 --frequencies 2:1
EXPECT_WORD="have 2 designs" expect_invalid info --masses 1,0.5 --frequencies 2:1 --design-branch 3
EXPECT_WORD="strictly decreasing" expect_invalid info --masses 1,0.5 --frequencies 1:2
EXPECT_WORD="3 ratios for 2 masses" expect_invalid info --masses 1,0.5 --frequencies 2:1:1
EXPECT_WORD="k1 alone" expect_invalid info --masses 1,0.5 --springs 1,1 --frequencies 2:1
EXPECT_WORD="picks a design" expect_invalid info --masses 1,0.5 --springs 1,1 --design-branch 2
EXPECT_WORD="7 masses at most" expect_invalid info --masses 1,1,1,1,1,1,1,1 --frequencies 8:7:6:5:4:3:2:1
# runs of chains of N masses (issue 32): the document, its refusals with one line
if expect_ok simulate --masses 1,0.2,0.05 --frequencies 3:2:1 --state 0,0,0,0,0,6.7 --contacts 20; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['contacts']['total'] == d['contacts']['impacts'] == 20 and d['stop_reason'] == 'contact-limit', d['stop_reason']
assert all(e['u3'] == 1 and e['type'] == 'impact' for e in d['events'])
t = [0] + [e['t'] for e in d['events']]
assert all(0 < b - a < d['chain']['period'] for a, b in zip(t[1:], t[2:]))  # FFT < T after an impact
assert d['energy']['relative_drift'] < 1e-12, d['energy']" || fail "a run of three masses"
fi
# pressed on an interior stop: held at once, released, and releases are not counted as contacts
if expect_ok simulate --masses 1,0.7,0.4 --springs 1,0.8,0.6 --stop-mass 2 --state 1.4,1,1.3,0.1,0,-0.2 --contacts 6; then
  python3 -c "
import json; d=json.load(open('$out'))
types = [e['type'] for e in d['events']]
assert types[:2] == ['stick', 'release'] and d['events'][0]['t'] == 0, types
assert d['contacts']['total'] == 6 and len(types) == 6 + types.count('release'), (d['contacts'], types)
assert d['contacts']['releases'] == types.count('release'), d['contacts']
assert all(e['u2'] == 1 for e in d['events'])
assert d['energy']['relative_drift'] < 1e-12, d['energy']" || fail "a stick of an interior mass"
fi
# GLO starts of N masses: inside the grazing set a grazing orbit (touches one period apart), a
# push off it impacts; the grazing sets themselves (the note's [0, 4/3] for the default chain)
if expect_ok simulate --masses 1,0.2,0.05 --frequencies 3:2:1 --glo-weights 0.5,0.3,0.2 --contacts 3; then
  python3 -c "
import json; d=json.load(open('$out'))
T = d['chain']['period']
assert [e['type'] for e in d['events']] == ['grazing'] * 3, d['events']
assert all(abs(e['t'] - (k + 1) * T) < 1e-12 * T for k, e in enumerate(d['events']))" || fail "a GLO start of three masses"
fi
# a GLOM of a fast mode alone returns to the stop after its own period T/n, in double (it was
# undecided at t = 0 in every precision); 4:2:1's two fast modes after T/2
for case in "1,0.2,0.05 3:2:1 1,0,0 3" "1,0.2,0.05 3:2:1 0,1,0 2" "1,0.2,0.05 4:2:1 0.5,0.5,0 2" \
            "1,0.5,0.2,0.05 4:3:2:1 0,1,0,0 3" "1,0.6,0.3,0.1,0.03 5:4:3:2:1 0,0,1,0,0 3" \
            "1,0.2,0.05 6:4:1 0.5,0.5,0 2"; do
  set -- $case
  if expect_ok simulate --masses "$1" --frequencies "$2" --glo-weights "$3" --contacts 4 --precision auto; then
    python3 -c "
import json; d=json.load(open('$out'))
T = d['chain']['period'] / $4
assert d['precision']['used'] == 'double', d['precision']
assert [e['type'] for e in d['events']] == ['grazing'] * 4, d['events']
assert all(abs(e['t'] - (k + 1) * T) < 1e-12 * T for k, e in enumerate(d['events']))" || fail "GLO $3 of $2"
  fi
done
if expect_ok simulate --masses 1,0.2,0.05 --frequencies 3:2:1 --glo-weights 0.5,0.3,0.2 --perturb 0,0,0,0,0,0.01 --contacts 3; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['events'][0]['type'] == 'impact' and d['events'][0]['t'] == 0, d['events'][0]
assert d['contacts']['total'] == 3, d['stop_reason']" || fail "a pushed GLO start of three masses"
fi
if expect_ok glo-set; then
  python3 -c "
import json; d=json.load(open('$out'))
s = d['grazing_set']
assert d['harmonics'] == [2, 1] and s['kind'] == 'interval', d
assert s['low'] == 0 and s['high'] == 4 / 3 and s['high_out'] > s['high'] and s['low_out'] < 0, s" || fail "the note's grazing set"
fi
if expect_ok glo-set --masses 1,0.2,0.05 --frequencies 3:2:1 --directions 6; then
  python3 -c "
import json; d=json.load(open('$out'))
b = d['grazing_set']['boundary']
assert d['harmonics'] == [3, 2, 1] and len(b) == 6 and all(p['radius'] < p['radius_out'] for p in b), d" || fail "a three-mode grazing set"
fi
# the grazing set drawn: PNG and SVG whose text is the document printed (the set's ends)
if expect_ok glo-set --masses 1,0.3 --frequencies 3:1 --out "$work/set31"; then
  python3 -c "
import json, zlib
printed = json.load(open('$out'))
assert printed['grazing_set']['high'] == 9 / 8, printed['grazing_set']
png = open('$work/set31.png', 'rb').read()
assert png[:8] == b'\\x89PNG\\r\\n\\x1a\\n', png[:8]
at, texts = 8, {}
while at < len(png):  # the PNG's text chunks
    size = int.from_bytes(png[at:at + 4], 'big'); kind = png[at + 4:at + 8]; body = png[at + 8:at + 8 + size]
    if kind == b'tEXt': key, _, value = body.partition(b'\\0'); texts[key] = value
    if kind == b'zTXt': key, _, value = body.partition(b'\\0'); texts[key] = zlib.decompress(value[1:])
    if kind == b'iTXt':
        key, _, rest = body.partition(b'\\0'); flag = rest[0]; rest = rest[2:]
        rest = rest.split(b'\\0', 2)[2]; texts[key] = zlib.decompress(rest) if flag else rest
    at += 12 + size
drawn = json.loads(texts[b'GrazeLabGrazingSet'])
assert drawn['grazing_set'] == printed['grazing_set'], drawn
svg = open('$work/set31.svg').read()
assert svg.startswith('<?xml') and 'grazing set [0, 1.125]' in svg, svg[:200]" || fail "the grazing set's picture"
fi
EXPECT_WORD="a point" expect_invalid glo-set --masses 1 --springs 1 --out "$work/set1"
# free ends: a floating chain (k1 = 0, no right wall) thrown at the stop bounces off and drifts away
if expect_ok simulate --masses 1,1 --springs 0,2 --state 1,1,1,1 --gap 1 --contacts 10; then
  python3 -c "
import json, math; d=json.load(open('$out'))
assert d['stop_reason'] == 'no-further-contact' and d['contacts']['total'] == 2, d['stop_reason']
t = [e['t'] for e in d['events']]
assert t[0] == 0 and abs(t[1] - math.pi / 2) < 1e-14, t  # half the period of sqrt(2k/m) = 2
assert abs(d['final']['v1'] + 1) < 1e-14 and abs(d['final']['v2'] + 1) < 1e-14, d['final']" || fail "a floating pair"
fi
EXPECT_WORD="k1" expect_invalid simulate --masses 1,1 --springs -1,2 --state 0,0,0,0
# no periodic orbit: every impact takes momentum from a floating chain
EXPECT_WORD="floating" expect_invalid orbit --masses 1,1 --springs 0,1 --onepp --period 3
EXPECT_WORD="floating" expect_invalid orbit --masses 1,1,1 --springs 0,1,1 --impacts 2 --energy 1 --guess 0.1,0.1,0,0
EXPECT_WORD="floating" expect_invalid modes --masses 1,1 --springs 0,1 --out "$work/floating"
EXPECT_WORD="floating" expect_invalid family --onepp --masses 1,1,1 --springs 0,1,1 --out "$work/floating"
EXPECT_WORD="floating" expect_invalid glo-set --masses 1,1,1 --springs 0,1,1
EXPECT_WORD="k2" expect_invalid simulate --masses 1,1 --springs 1,0 --state 0,0,0,0
# a bar thrown at a wall: one mass bounces once; two swing half their spring's period; the
# literature's steel bar's continuum; bad input refused
if expect_ok bar --masses-count 1,2,40 --each-impact; then
  python3 -c "
import json, math; d=json.load(open('$out'))
c = d['continuum']
assert abs(c['duration'] - 385.45e-6) < 5e-9 and abs(c['force'] - 1270.8) < 0.05, c
one, two, forty = d['rows']
assert one['impacts'] == 1 and one['rebound'] == -0.1 and one['duration'] == 0, one
m, k = 7800 * 3.14e-4 / 2, 2 * 210e9 * 3.14e-4
assert two['impacts'] == 2 and abs(two['duration'] / (math.pi / math.sqrt(2 * k / m)) - 1) < 1e-12, two
assert forty['status'] == 'computed' and len(forty['impact_times']) == forty['impacts'] > 20, forty['impacts']
assert abs(sum(forty['impact_impulses']) / forty['impulse'] - 1) < 1e-12
assert 0 < forty['vibration'] < 0.1 and -0.1 < forty['rebound'] < -0.09, forty
assert len(d['convergence']['rebound']['orders']) == 2" || fail "bar"
fi
EXPECT_WORD="ascending" expect_invalid bar --masses-count 10,5
EXPECT_WORD="four numbers" expect_invalid bar --bar 1,2,3
EXPECT_WORD="speed" expect_invalid bar --speed -1
EXPECT_WORD="first" expect_invalid bar --stop-end middle
EXPECT_WORD="2000" expect_invalid bar --masses-count 5000
# the 1IPP family of three masses: its files, its grazing limit; a run from one of its orbits
if expect_ok family --onepp --masses 1,0.2,0.05 --frequencies 3:2:1 --count 50 --out "$work/fam3"; then
  python3 -c "
import csv, json
d = json.load(open('$work/fam3.json'))
rows = list(csv.DictReader(open('$work/fam3.csv')))
assert d['rows'] == len(rows) and d['admissible_rows'] == sum(r['admissible'] == '1' for r in rows) > 10, d
w = d['grazing_limit']['weights']
assert abs(sum(w) - 1) < 1e-14 and min(w) > 0, w
last = [r for r in rows if r['admissible'] == '1'][-1]
assert abs(float(last['u1']) - d['grazing_limit']['u'][0]) < 1e-6, (last, d['grazing_limit'])" || fail "the 1IPP family of three masses"
fi
if expect_ok simulate --masses 1,0.2,0.05 --frequencies 3:2:1 --onepp 7 --contacts 3; then
  python3 -c "
import json; d=json.load(open('$out'))
assert [e['type'] for e in d['events']] == ['impact'] * 3, d['events']
assert all(abs(e['t'] - 7 * (k + 1)) < 1e-9 for k, e in enumerate(d['events'])), d['events']" || fail "a 1IPP start of three masses"
fi
EXPECT_WORD="no admissible 1IPP orbit" expect_invalid simulate --masses 1,0.2,0.05 --frequencies 3:2:1 --onepp 1
EXPECT_WORD="name the family" expect_invalid family --masses 1,0.2,0.05 --frequencies 3:2:1 --out "$work/x"
EXPECT_WORD="commensurate" expect_invalid glo-set --masses 1,1 --springs 1,1
EXPECT_WORD="two or three modes" expect_invalid glo-set --masses 1,0.6,0.36,0.216 --frequencies 4:3:2:1
EXPECT_WORD="--directions" expect_invalid glo-set --directions 2
EXPECT_WORD="sum to 1" expect_invalid simulate --masses 1,1 --springs 1,1 --glo-weights 0.5,0.6
EXPECT_WORD="one of them" expect_invalid simulate --masses 1,1 --springs 1,1 --glo-weights 0.5,0.5 --state 0,0,0,0
EXPECT_WORD="four numbers" expect_invalid simulate --masses 1,1 --springs 1,1 --glo-weights 0.5,0.5 --perturb 0,0
EXPECT_WORD="--state u1" expect_invalid simulate --masses 1,0.5 --springs 1,0.5
EXPECT_WORD="4 numbers for 3 masses" expect_invalid simulate --masses 1,1,1 --springs 1,1,1 --state 0,0,0,0
EXPECT_WORD="past the stop" expect_invalid simulate --masses 1,1 --springs 1,1 --state 0,2,0,0
EXPECT_WORD="not available for a chain" expect_invalid simulate --masses 1,1 --springs 1,1 --glo 0.5
EXPECT_WORD="not json, jsonl, csv or summary" expect_invalid simulate --masses 1,1 --springs 1,1 --state 0,0,0,1 --format ndjson
EXPECT_WORD="not off, auto or full" expect_invalid simulate --masses 1,1 --springs 1,1 --state 0,0,0,1 --trust most
# the error estimate of N masses: a short run agrees with its shadow; a long chaotic one passes
# its horizon, observed, within the run
if expect_ok simulate --masses 1,0.7,0.4 --springs 1,0.8,0.6 --stop-mass 2 --state 1.4,1,1.3,0.1,0,-0.2 --contacts 6; then
  python3 -c "
import json; d=json.load(open('$out'))
assert d['trust']['verdict'] == 'ok' and d['trust']['horizon'] > d['final']['t'], d['trust']" || fail "the trust of a short N-mass run"
fi
if expect_ok simulate --masses 1,0.7,0.4 --springs 1,0.8,0.6 --stop-mass 2 --state 1.4,1,1.3,0.1,0,-0.2 --contacts 100 --trust full; then
  python3 -c "
import json; d=json.load(open('$out'))
t = d['trust']
assert t['verdict'] == 'unreliable' and t['horizon'] < d['final']['t'] and 'observed' in t['horizon_method'], t" || fail "the trust of a chaotic N-mass run"
fi
# N masses in binary128: the same events as in double to double's precision, written with 36 digits
if expect_ok simulate --masses 1,0.7,0.4 --springs 1,0.8,0.6 --stop-mass 2 --state 1.4,1,1.3,0.1,0,-0.2 --contacts 4 --precision quad; then
  cp "$out" "$work/quad.json"
  if expect_ok simulate --masses 1,0.7,0.4 --springs 1,0.8,0.6 --stop-mass 2 --state 1.4,1,1.3,0.1,0,-0.2 --contacts 4 --precision double; then
    python3 -c "
import json
q = json.load(open('$work/quad.json')); d = json.load(open('$out'))
assert q['precision']['used'] == 'quad' and d['precision']['used'] == 'double', (q['precision'], d['precision'])
assert [e['type'] for e in q['events']] == [e['type'] for e in d['events']]
assert all(abs(a['t'] - b['t']) < 1e-12 * (1 + b['t']) for a, b in zip(q['events'], d['events']))
assert q['energy']['relative_drift'] < 1e-30, q['energy']
assert len(json.load(open('$work/quad.json'), parse_float=str)['events'][1]['t']) > 30
# the start read in binary128: 1.4 to its 34 digits, not the double nearest 1.4
from decimal import Decimal
u1 = Decimal(json.load(open('$work/quad.json'), parse_float=str)['initial']['state']['u1'])
assert abs(u1 - Decimal('1.4')) < Decimal('1e-33') and abs(Decimal(1.4) - Decimal('1.4')) > Decimal('1e-17'), u1" || fail "N masses in binary128"
  fi
fi
# a designed chain in binary128: the masses read in it (0.2 is not double's 0.2 there) and the
# springs designed for them to its rounding, so that its frequencies are 3:2:1 to ~1e-33 where
# the double design is off by ~1e-16: the characteristic polynomial of K - lambda M, exact in
# fractions from the printed numbers, has roots 9x, 4x, x (its coefficients' ratios 14, 49, 36)
if expect_ok simulate --masses 1,0.2,0.05 --frequencies 3:2:1 --glo-weights 0.5,0.3,0.2 --contacts 3 --precision quad; then
  python3 -c "
import json
from fractions import Fraction as F
d = json.load(open('$out'), parse_float=str)
c = d['chain']
m = [F(x) for x in c['masses']]; k = [F(x) for x in c['springs']]
assert abs(m[1] - F('0.2')) < F(1, 10 ** 33) and abs(F(0.2) - F('0.2')) > F(1, 10 ** 18), c['masses']
a = [k[0] + k[1], k[1] + k[2], k[2]]
# det(K - l M) = -m1 m2 m3 l^3 + c2 l^2 - c1 l + c0 for the tridiagonal K
p3 = m[0] * m[1] * m[2]
p2 = a[0] * m[1] * m[2] + a[1] * m[0] * m[2] + a[2] * m[0] * m[1]
p1 = a[0] * a[1] * m[2] + a[0] * a[2] * m[1] + a[1] * a[2] * m[0] - k[1] ** 2 * m[2] - k[2] ** 2 * m[0]
p0 = a[0] * a[1] * a[2] - a[0] * k[2] ** 2 - a[2] * k[1] ** 2
x = p2 / p3 / 14
errors = [abs(p1 / p3 / (49 * x * x) - 1), abs(p0 / p3 / (36 * x ** 3) - 1)]
assert max(errors) < F(1, 10 ** 30), [float(e) for e in errors]
assert d['precision']['used'] == 'quad' and len(d['events']) == 3, d['precision']
s = d['initial']['state']
assert F(s['u3']) == F(c['gap']), s" || fail "a chain designed in binary128"
fi
# a 1IPP orbit in binary128: its data computed there, so that its impacts come at T, 2T, 3T to
# binary128's precision (data computed in double would drift by 1e-16 of T a period)
if expect_ok simulate --masses 1,0.2,0.05 --frequencies 3:2:1 --onepp 7.1 --contacts 3 --precision quad; then
  python3 -c "
import json
from fractions import Fraction as F
d = json.load(open('$out'), parse_float=str)
times = [F(e['t']) for e in d['events']]
assert [e['type'] for e in d['events']] == ['impact'] * 3, d['events']
errors = [abs(t / (k + 1) / F('7.1') - 1) for k, t in enumerate(times)]
assert max(errors) < F(1, 10 ** 28), [float(e) for e in errors]
assert d['precision']['used'] == 'quad'" || fail "a 1IPP orbit of N masses in binary128"
fi
# --precision auto: mass 1 pressed one ulp past the gap, mass 2 on the stop and mass 3 beside it
# at the gap, is undecided in double by the modal kernel (the force on mass 2 is within its
# bound of double's rounding); the run again in long double, or binary128, gives the binary128
# run's events. The ulp is written exactly (1 + 2^-52): each precision reads the start again,
# and 1.0000000000000002 would be another number in long double
ulp="1.0000000000000002220446049250313080847263336181640625"
if expect_ok simulate --masses 1,0.5,0.5 --springs 1,0.5,0.5 --stop-mass 2 --state $ulp,1,1,0,0,0 --contacts 3; then
  cp "$out" "$work/auto.json"
  if expect_ok simulate --masses 1,0.5,0.5 --springs 1,0.5,0.5 --stop-mass 2 --state $ulp,1,1,0,0,0 --contacts 3 \
       --precision quad --trust off; then
    python3 -c "
import json
n = json.load(open('$work/auto.json')); quad = json.load(open('$out'))
assert n['precision']['used'] != 'double' and len(n['precision']['escalations']) >= 1, n['precision']
assert [e['type'] for e in n['events']] == [e['type'] for e in quad['events']] == ['stick', 'release', 'impact', 'impact']
# (the release from a force of one ulp is ill-conditioned, t going as its square root: long
# double's is 3e-12 off, which its estimate says, 2.4e-13 of the period)
assert all(abs(a['t'] - b['t']) < 1e-11 * (1 + b['t']) for a, b in zip(n['events'], quad['events']))
assert n['trust']['verdict'] == 'ok' and n['trust']['estimated_time_error'] < 1e-12, n['trust']" || fail "N masses raised past double"
  fi
fi
# the same start on two masses (1:2, the design's springs written out) is the note's chain: the
# one run takes the note's kernel, which decides it in double from its exact residuals, with
# the two-mass options' events to the last digit
if expect_ok simulate --masses 1,0.5 --springs 1,0.5 --state $ulp,1,0,0 --contacts 3 --format csv; then
  cp "$out" "$work/n.csv"
  if expect_ok simulate --state $ulp,1,0,0 --contacts 3 --trust off --format csv; then
    cmp -s "$out" "$work/n.csv" || fail "the note's chain by --masses and --springs: not the two-mass events"
  fi
  expect_ok simulate --masses 1,0.5 --springs 1,0.5 --state $ulp,1,0,0 --contacts 3 &&
    python3 -c "
import json
assert json.load(open('$out'))['precision']['used'] == 'double'" || fail "the note's chain by --masses and --springs: raised"
fi
EXPECT_WORD="given by --masses" expect_invalid simulate --springs 1,1 --state 0,0,0,1
# a command sent SIGNAL a second after it started must end within LIMIT ms with exit 130
expect_interrupted() {  # SIGNAL LIMIT_MS WHAT -- command arguments
  local signal=$1 limit=$2 what=$3
  shift 4
  "$cli" "$@" >"$out" 2>"$err" &
  local pid=$!
  sleep 1
  local started
  started=$(date +%s%N)
  kill "-$signal" "$pid"
  wait "$pid"
  local code=$?
  local elapsed_ms=$((($(date +%s%N) - started) / 1000000))
  [ "$code" -eq 130 ] || fail "$what: exit $code, not 130"
  [ "$elapsed_ms" -le "$limit" ] || fail "$what: the interrupt took $elapsed_ms ms"
}

# SIGINT during a long run of ten masses, and during a seven-mass design (its 5040 paths take
# tens of seconds), ends it within 1 s; the json, streamed past 10^6 contacts, is a whole document
# (its events so far, cancelled)
expect_interrupted INT 1000 "a run of ten masses" -- simulate --masses 1,1,1,1,1,1,1,1,1,1 \
  --springs 1,1,1,1,1,1,1,1,1,1 --state 0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,2 --contacts 100000000 --trust off
python3 -c "
import json
d = json.load(open('$out'))
assert d['stop_reason'] == 'cancelled' and len(d['events']) > 1000 and d['contacts']['total'] == len(d['events']), d['stop_reason']
assert d['final']['t'] == d['events'][-1]['t'] and d['trust']['verdict'] == 'unchecked', (d['final'], d['trust'])" ||
  fail "an interrupted json of ten masses is not a whole document: $(tail -c 300 "$out")"
expect_interrupted INT 1000 "a seven-mass design" -- info --masses 1,0.8,0.6,0.5,0.4,0.3,0.2 \
  --frequencies 7:6:5:4:3:2:1

# N masses streamed: csv rows equal the json's events digit for digit, one row per event; the
# summary counts them by type; bad input writes no header; an interrupted csv of 10^8 contacts
# (past json's 10^6) ends within 1 s on a complete row, the stderr line naming how many
nm="--masses 1,0.7,0.4 --springs 1,0.8,0.6 --stop-mass 2 --state 1.4,1,1.3,0.1,0,-0.2 --contacts 9"
if expect_ok simulate $nm; then
  cp "$out" "$work/n.json"
  if expect_ok simulate $nm --format csv --trust off; then
    cp "$out" "$work/n.csv"
    if expect_ok simulate $nm --format jsonl; then
      # jsonl: the run's head, each event, the end: the json's fields record by record
      python3 -c "
import json
d = json.load(open('$work/n.json'))
records = [json.loads(line) for line in open('$out')]
assert [r.pop('record') for r in records] == ['run'] + ['event'] * len(d['events']) + ['end'], records[:2]
assert records[0] == {k: d[k] for k in ('chain', 'initial')}, records[0]
assert records[1:-1] == d['events']
end = {k: v for k, v in d.items() if k not in ('chain', 'initial', 'events', 'timing')}
assert records[-1].pop('timing')['seconds'] > 0 and records[-1] == end, (records[-1], end)" || fail "N masses streamed as jsonl"
    fi
    if expect_ok simulate $nm --format summary; then
      python3 -c "
import csv, json
d = json.load(open('$work/n.json'), parse_float=str, parse_int=str)
rows = list(csv.DictReader(open('$work/n.csv')))
assert len(rows) == len(d['events']) > 9, (len(rows), len(d['events']))
for row, e in zip(rows, d['events']):
    assert row == e, (row, e)  # the same columns, the same digits
summary = open('$out').read()
kinds = [e['type'] for e in d['events']]
counts = 'contacts       %s (impacts %d, grazings %d, sticks %d; releases %d)' % (
    d['contacts']['total'], kinds.count('impact'), kinds.count('grazing'), kinds.count('stick'), kinds.count('release'))
assert counts in summary, (counts, summary)
assert 'trust          ' + json.load(open('$work/n.json'))['trust']['verdict'] in summary, summary
assert 'final          t=' + d['final']['t'] in summary, summary" || fail "N masses streamed as csv and summary"
    fi
  fi
fi
"$cli" simulate --masses 1,1 --springs 1,1 --state 0,2,0,0 --format csv >"$out" 2>"$err"
[ "$?" -eq 2 ] && [ ! -s "$out" ] || fail "a refused N-mass csv wrote something"
# a csv raised by --precision auto past rows it wrote: those rows stay, the raised run writes
# the rest and says whether it met the last of them again. Mass 3 held on the stop by mass 2 one
# ulp past the gap (mass 1 there too): long double writes the stick and the release, then meets a
# contact it cannot decide; binary128 finds the release 3e-9 later (a force of one ulp falls to 0
# after a time that goes as its square root: long double's rounding of it moves the release by
# 1e-5 of itself), and says so
"$cli" simulate --masses 1,1,0.5 --springs 1,1,0.5 --state 1,1.0000000000000002220446049250313080847263336181640625,1,0,0,0 \
  --contacts 3 --format csv >"$out" 2>"$err"
[ "$?" -eq 0 ] && [ "$(wc -l <"$out")" -eq 5 ] && grep -q "raised to quad .* after 2 rows; it DIFFERS from the last of them" "$err" &&
  [ "$(cut -d, -f2 "$out" | tr '\n' ' ')" = "type stick release impact impact " ] ||
  fail "a raised N-mass csv: $(cat "$out" "$err")"
EXPECT_WORD="error estimate" expect_invalid simulate --masses 1,1 --springs 1,1 --state 0,0,0,1 --format csv --trust full
EXPECT_WORD="--format json" expect_invalid simulate --masses 1,1 --springs 1,1 --state 0,0,0,1 --format csv --trust off --sample-step 0.1
EXPECT_WORD="exclude each other" expect_invalid simulate --masses 1,1 --springs 1,1 --state 0,0,0,1 --sample-step 0.1 --sample-times 1
# --trust full runs its shadow in lockstep and holds nothing: 200 000 contacts shadowed to the end
# in about the memory of 2 000 (holding the shadow's events took 35 MB more here, and was refused
# past 10^6 contacts); under the sanitizers, whose allocator keeps what is freed, the estimate alone
python3 - "$cli" <<'PY' || fail "--trust full over 2e5 contacts: not bounded, or not estimated"
import os, resource, subprocess, sys
def run(contacts):
    done = subprocess.run([sys.argv[1], "simulate", "--masses", "2", "--springs", "3", "--gap", "0.5", "--state",
                           "0.1,1.7", "--contacts", str(contacts), "--format", "summary", "--trust", "full",
                           "--precision", "double"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert f"contacts       {contacts}" in done.stdout and "trust          unchecked" not in done.stdout, done.stdout
    return resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # KiB, the largest child so far
short = run(2000)
long = run(200000)
if not os.environ.get("ASAN_OPTIONS"):
    assert long - short < 10 * 1024, f"{short} KiB for 2000 contacts, {long} KiB for 200000"
PY
expect_interrupted INT 1000 "a streamed run of three masses" -- simulate --masses 1,0.2,0.05 --frequencies 3:2:1 \
  --glo-weights 0.5,0.3,0.2 --perturb 0,0,0,0,0,-0.01 --contacts 100000000 --format csv
[ "$(tail -c1 "$out" | od -An -c | tr -d ' ')" = '\n' ] || fail "interrupted N-mass csv ends mid-record"
[ "$(($(wc -l <"$out") - 1))" -gt 1000 ] && grep -q "the $(($(wc -l <"$out") - 1)) events before it are written" "$err" ||
  fail "interrupted N-mass csv: $(wc -l <"$out") lines, $(cat "$err")"

# SIGTERM during a long detuned search, shadow run included, ends the command within 2 s with
# complete records and exit 130
expect_interrupted TERM 2000 "a detuned search" -- simulate --k2 1e-9 --glo 0.5 \
  --perturb 0,0,0,-1e-3 --contacts 100000000 --format csv
[ "$(tail -c1 "$out" | od -An -c | tr -d ' ')" = '\n' ] || fail "interrupted csv ends mid-record"

if [ "$failures" -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "all CLI contract checks passed"
