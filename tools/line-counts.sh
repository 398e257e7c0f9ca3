#!/bin/bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Lines of C++ and Python per folder at a revision (default HEAD), and those of the N-mass stack
# beside the two-mass one (core's chain_* files and the commands of --masses), for docs/design.md.
# usage: tools/line-counts.sh [REV]
set -eu
rev=${1:-HEAD}
count() {  # lines of the tracked files under $1 whose names match the regex $2
  git ls-tree -r --name-only "$rev" -- "$1" | grep -E "$2" | while read -r f; do git show "$rev:$f"; done | wc -l
}
printf '%-34s %8s\n' "at $(git rev-parse --short "$rev")" lines
for d in core ui app python tests/core tests/ui tests/cli tests/python; do
  printf '%-34s %8s\n' "$d/" "$(count "$d" '\.(h|cpp|py|sh)$')"
done
printf '%-34s %8s\n' "core/ chain_*, mass_chain*, sinusoid*" "$(count core '/(chain_[a-z_]*|mass_chain|sinusoid_zero)\.(h|cpp)$')"
printf '%-34s %8s\n' "app/ chain_* and prepared_chain" "$(count app '/(chain_[a-z_]*|prepared_chain)\.(h|cpp)$')"
