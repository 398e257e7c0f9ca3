#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Instructions per short Python call (docs/python.md): a 10-contact simulate of the note's chain
# and of a prepared 3:2:1 chain of three masses, counted by valgrind's callgrind as the difference
# between 2200 and 200 calls over 2000 (exact, whatever else the machine runs; wall-clock figures
# on a shared 2-core machine move by half from one run to the next). The core's own share is
# runChain's inclusive count in the same profile. Needs valgrind (Debian: valgrind).
#     PYTHONPATH=build/python bash tools/count-python-instructions.sh
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/calls.py" <<'PY'
import sys
import grazelab as gl
calls, which = int(sys.argv[1]), sys.argv[2]
if which == "note":
    run = lambda: gl.simulate(glo=0.5, perturb=(0, 0, 0, -0.05), contacts=10, trust="off")
else:
    chain = gl.Chain(masses=(1, 0.7, 0.4), frequencies=(3, 2, 1))
    run = lambda: chain.simulate(glo_weights=(0.2, 0.3, 0.5), perturb=(0, 0, 0, 0, 0, -0.05), contacts=10,
                                 trust="off")
run()
for _ in range(calls):
    run()
PY
count() {  # total instructions and runChain's, of `calls` calls of `which`
  valgrind --tool=callgrind --callgrind-out-file="$work/out" /usr/bin/python3 "$work/calls.py" "$1" "$2" \
    > /dev/null 2>&1
  local total core
  total=$(callgrind_annotate "$work/out" | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
  core=$(callgrind_annotate --inclusive=yes "$work/out" |
         awk '/BasicChainRun<double> grazelab::core::runChain<double>/ {gsub(",", "", $1); s += $1} END {print s + 0}')
  echo "$total $core"
}
for which in note chain3; do
  read -r total0 core0 < <(count 200 "$which")
  read -r total1 core1 < <(count 2200 "$which")
  echo "$which: $(( (total1 - total0) / 2000 )) instructions a call, the core's run $(( (core1 - core0) / 2000 )):" \
       "$(( (total1 - total0 - core1 + core0) / 2000 )) over it"
done
