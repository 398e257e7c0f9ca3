#!/bin/bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# One version everywhere (issue "One architecture…", item 3): the CMake project's, in
# grazelab-cli --version, the files it writes, grazelab --version and grazelab.__version__.
# usage: version_test.sh VERSION CLI APP|- PYTHON|- PYTHONPATH|-
set -u
version=$1 cli=$2 app=$3 python=$4 pythonpath=$5
fail() { echo "FAIL: $*"; exit 1; }
[ "$("$cli" --version)" = "grazelab-cli $version" ] || fail "grazelab-cli --version: $("$cli" --version)"
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
"$cli" orbit --onepp --period 6 > "$dir/orbit.json" || fail "orbit"
grep -q "\"generator\": \"grazelab-cli $version\"" "$dir/orbit.json" || fail "orbit's generator: $(grep generator "$dir/orbit.json")"
# the pictures it draws name it too (PNG text "Software", from the one picture writer)
env -u DISPLAY -u WAYLAND_DISPLAY "$cli" map --glo 0.5 --x u1:-0.2:0.2:3 --y v1:-0.2:0.2:2 --out "$dir/m" 2> /dev/null || fail "map"
grep -aq "GrazeLab $version" "$dir/m.png" || fail "the map's PNG does not name GrazeLab $version"
if [ "$app" != - ]; then
  got=$(env -u DISPLAY -u WAYLAND_DISPLAY QT_QPA_PLATFORM=offscreen "$app" --version)
  [ "$got" = "grazelab $version" ] || fail "grazelab --version: $got"
fi
if [ "$python" != - ]; then
  got=$(PYTHONPATH="$pythonpath" "$python" -c 'import grazelab; print(grazelab.__version__)')
  [ "$got" = "$version" ] || fail "grazelab.__version__: $got"
fi
echo "one version: $version"
