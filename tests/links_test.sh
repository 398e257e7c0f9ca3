#!/bin/bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Libraries by what they need (issue "One architecture…", item 1): the command line and the
# Python module link no Qt Widgets, Charts, OpenGL or Print Support (their pictures are drawn
# with QPainter, Qt Gui and Svg), and the command line still draws them.
# usage: links_test.sh CLI PYTHON_MODULE|-
set -u
cli=$1 module=$2
# a build of some targets only (the sanitizer build: the core's tests and the CLI) has no module
if [ "$module" != - ] && [ ! -e "$module" ]; then echo "(the Python module is not built here)"; module=-; fi
fail() { echo "FAIL: $*"; exit 1; }
for binary in "$cli" $([ "$module" != - ] && echo "$module"); do
  needed=$(readelf -d "$binary" | grep NEEDED) || fail "readelf $binary"
  for library in Widgets Charts OpenGL PrintSupport; do
    if grep -q "libQt6$library" <<< "$needed"; then fail "$(basename "$binary") links Qt $library"; fi
  done
  grep -q libQt6Core <<< "$needed" || fail "$(basename "$binary"): no Qt Core among $needed"
done
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
env -u DISPLAY -u WAYLAND_DISPLAY "$cli" map --glo 0.5 --x u1:-0.2:0.2:4 --y v1:-0.2:0.2:3 --out "$dir/m" 2> /dev/null ||
  fail "map"
for suffix in png svg json; do [ -s "$dir/m.$suffix" ] || fail "map wrote no $suffix"; done
head -c 8 "$dir/m.png" | od -An -c | grep -q 'P   N   G' || fail "m.png is not a PNG"
grep -q '<svg' "$dir/m.svg" || fail "m.svg is not an SVG"
echo "no widgets in $(basename "$cli")$([ "$module" != - ] && echo " nor $(basename "$module")"), pictures drawn"
