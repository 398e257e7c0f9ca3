#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# The contracts of `report` and `stability` (issue 8): the files, their columns, the method
# names, a verdict and a reason for every cell, exit 2 with one line for every invalid input.
set -u
cli="$1"
failures=0
dir=$(mktemp -d)
out=$(mktemp)
err=$(mktemp)
trap 'rm -rf "$dir" "$out" "$err"' EXIT
export QT_QPA_PLATFORM=offscreen

source "$(dirname "$0")/contract_lib.sh"

EXPECT_WORD=--out expect_invalid report --quick
EXPECT_WORD=rk4 expect_invalid report --quick --out "$dir/x" --methods exact,rk4
EXPECT_WORD=format expect_invalid report --quick --out "$dir/x" --format csv
EXPECT_WORD=m2 expect_invalid report --quick --out "$dir/x" --m2 -1
EXPECT_WORD=both expect_invalid report --quick --out "$dir/x" --t-end 10 --contacts 5
EXPECT_WORD=glo-weights expect_invalid report --quick --out "$dir/x" --glo-weights 0.5,0.5
EXPECT_WORD=state expect_invalid stability --quick --masses 1,0.5 --springs 1,1 --state 1,2 --out "$dir/st"
[ -e "$dir/st" ] && fail "a stability refused for its chain made its directory"
EXPECT_WORD=stability expect_invalid stability --quick --out "$dir/x" --m2 0.3
EXPECT_WORD=report expect_invalid simulate --out "$dir/x"
[ -e "$dir/x/results.csv" ] && fail "an invalid report wrote files"

# report --quick on the default problem
if "$cli" report --quick --out "$dir/report" 2>"$err"; then
  for f in results.csv work_precision.svg work_precision.png convergence.svg convergence.png report.md; do
    [ -s "$dir/report/$f" ] || fail "report did not write $f"
  done
  grep -q "report: \[1/" "$err" || fail "no progress on stderr"
  python3 - "$dir/report/results.csv" <<'PY' || fail "results.csv"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
header = open(sys.argv[1]).readline().strip().split(",")
assert header == ["method", "parameter", "value", "seconds_min", "seconds_median", "runs",
                  "state_error", "contact_time_error", "impact_speed_error", "missed_contacts",
                  "extra_contacts", "energy_drift", "status", "reason"], header
names = {"exact", "moreau-jean", "moreau-jean-theta1", "schatzman-paoli", "dopri5-events",
         "cvode-adams", "cvode-bdf", "penalty"}
seen = {r["method"] for r in rows}
assert seen == names, seen
params = {"exact": "eps", "moreau-jean": "h", "moreau-jean-theta1": "h", "schatzman-paoli": "h",
          "dopri5-events": "rtol", "cvode-adams": "rtol", "cvode-bdf": "rtol", "penalty": "k_c"}
for r in rows:
    # the penalty's tolerance sweep (full report only) has rtol as its knob
    assert r["parameter"] == params[r["method"]] or (r["method"], r["parameter"]) == ("penalty", "rtol"), r
    assert r["status"] in {"completed", "budget", "undecided", "failed", "refused", "cancelled"}, r
    if r["status"] == "completed":
        assert float(r["seconds_min"]) > 0 and float(r["seconds_min"]) <= float(r["seconds_median"]) * (1 + 1e-9)
        assert math.isfinite(float(r["state_error"]))
    else:
        assert r["reason"].strip('"'), r
for m in names - {"exact"}:
    assert sum(r["method"] == m for r in rows) >= 5, m
exact = [r for r in rows if r["method"] == "exact"]
assert float(exact[0]["state_error"]) <= 1e-12, exact[0]
best_other = min(float(r["state_error"]) for r in rows if r["method"] != "exact" and r["status"] == "completed")
assert float(exact[0]["state_error"]) < best_other
PY
  grep -q "moreau-jean | h |" "$dir/report/report.md" || fail "report.md: no Moreau-Jean slope"
  grep -qi "predictability horizon" "$dir/report/report.md" || fail "report.md: no horizon"
else
  fail "report --quick failed: $(tail -3 "$err")"
fi

# report --masses: any chain of N masses, the same files; the exact rows find every contact
EXPECT_WORD=--state expect_invalid report --quick --out "$dir/x" --masses 1,1,1 --springs 1,1,1
EXPECT_WORD=glo expect_invalid report --quick --out "$dir/x" --masses 1,1,1 --springs 1,1,1 --glo 0.5
EXPECT_WORD=past expect_invalid report --quick --out "$dir/x" --masses 1,1,1 --springs 1,1,1 --state 0,0,2,0,0,0
[ -e "$dir/x/results.csv" ] && fail "an invalid report --masses wrote files"
chain_report() {  # NAME, then the chain's options
  local name="$1"; shift
  if "$cli" report --quick --out "$dir/$name" "$@" 2>"$err"; then
    for f in results.csv work_precision.svg work_precision.png convergence.svg convergence.png report.md; do
      [ -s "$dir/$name/$f" ] || fail "report $name did not write $f"
    done
    grep -q "## Contacts missed and invented" "$dir/$name/report.md" || fail "report $name: no table of missed contacts"
    python3 - "$dir/$name/results.csv" <<'PY' || fail "report $name: results.csv"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert {r["method"] for r in rows} == {"exact", "moreau-jean", "moreau-jean-theta1", "schatzman-paoli",
                                       "dopri5-events", "cvode-adams", "cvode-bdf", "penalty"}
for r in rows:
    assert r["missed_contacts"].isdigit() and r["extra_contacts"].isdigit(), r
exact = [r for r in rows if r["method"] == "exact"]
assert len(exact) == 3
for r in exact:
    assert r["status"] == "completed" and r["missed_contacts"] == "0" and r["extra_contacts"] == "0", r
    assert float(r["state_error"]) <= 1e-9, r
PY
  else
    fail "report $name failed: $(tail -3 "$err")"
  fi
}
chain_report three --masses 3,2,1 --frequencies 3:2:1 --glo-weights 0.2,0.3,0.5 --perturb 0,0,0,0,0.02,-0.05 --contacts 20
chain_report ten --masses 1,1,1,1,1,1,1,1,1,1 --springs 1,1,1,1,1,1,1,1,1,1 --stop-mass 7 \
  --state 0,0,0,0,0,0,0.5,0,0,0,-0.4,0,0,0,0,0,1.5,0,0,0 --contacts 10
grep -q "10 masses" "$dir/ten/report.md" || fail "report ten: the chain is not described"

# stability --quick: every cell has a verdict, and a reason when it is not ok
if "$cli" stability --quick --out "$dir/stability" 2>"$err"; then
  [ -s "$dir/stability/matrix.md" ] || fail "no matrix.md"
  python3 - "$dir/stability/matrix.csv" <<'PY' || fail "matrix.csv"
import csv, sys
header = open(sys.argv[1]).readline().strip().split(",")
assert header == ["case", "method", "seconds", "state_error", "contact_time_error",
                  "missed_contacts", "energy_drift", "verdict", "reason"], header
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) >= 8 * 8, len(rows)
for r in rows:
    assert r["verdict"] in {"ok", "inaccurate", "refused", "budget", "undecided", "failed"}, r
    assert (r["verdict"] == "ok") == (r["reason"].strip('"') == ""), r
    if r["verdict"] == "ok":
        assert r["state_error"] in ("",) or float(r["state_error"]) <= 1e-3, r
    if r["method"] == "exact" and not r["case"].startswith("penalty-"):
        assert r["verdict"] == "ok", r
PY
else
  fail "stability --quick failed: $(tail -3 "$err")"
fi

# stability --masses: the matrix of a chain the note does not have (four masses stopped on the
# second, from a state): the chain and its variants, every cell with a verdict; the exact solver
# ok where its estimate is not contradicted; every lengths scaled by 1e12 the same errors (the
# motion is scale-free); refusals
if "$cli" stability --quick --masses 1,0.6,1.4,0.9 --springs 1,2,0.8,1.1 --stop-mass 2 --gap 0.5 \
    --state 0,0.3,0,-0.2,0.2,0.8,-0.1,0 --out "$dir/stability4" 2>"$err"; then
  python3 - "$dir/stability4/matrix.csv" <<'PY' || fail "stability --masses: matrix.csv"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
cases = sorted({r["case"] for r in rows})
assert cases == sorted(["given", "stopped-mass-x1e-06", "spring-2-x1e+06", "gap-1e+12", "push-1e-15", "right-wall"]), cases
assert len(rows) == 6 * 8, len(rows)
cell = {(r["case"], r["method"]): r for r in rows}
for r in rows:
    assert r["verdict"] in {"ok", "inaccurate", "refused", "budget", "undecided", "failed"}, r
    assert (r["verdict"] == "ok") == (r["reason"].strip('"') == ""), r
for case in ("given", "gap-1e+12", "right-wall", "spring-2-x1e+06"):
    assert cell[(case, "exact")]["verdict"] == "ok", cell[(case, "exact")]
# (fixed steps: the same steps to rounding; an adaptive step size feels the rounding: 25 %)
for method, within in (("moreau-jean", 1e-3), ("schatzman-paoli", 1e-3), ("dopri5-events", 0.25)):
    a, b = cell[("given", method)], cell[("gap-1e+12", method)]
    assert a["missed_contacts"] == b["missed_contacts"], (a, b)
    assert abs(float(a["state_error"]) - float(b["state_error"])) <= within * float(a["state_error"]), (a, b)
PY
  grep -q "4 masses, stop on mass 2" "$dir/stability4/matrix.md" || fail "stability --masses: the chain is not described"
else
  fail "stability --quick --masses failed: $(tail -3 "$err")"
fi
EXPECT_WORD="--masses" expect_invalid stability --quick --out "$dir/x" --springs 1,1
EXPECT_WORD="past the stop" expect_invalid stability --quick --out "$dir/x" --masses 1,1,1 --springs 1,1,1 --state 0,0,2,0,0,0

if [ "$failures" -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "all report and stability checks passed"
