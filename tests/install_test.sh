#!/bin/bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# What `cmake --install` gives (issue "One architecture…", item 4): the programs, the core
# library with its headers, a CMake package and a pkg-config file. A program of someone else's
# (examples/core-consumer) builds against the installed package, and again from pkg-config, and
# its contacts equal grazelab-cli's for the same start.
# The example is configured with this project's own generator and compiler (Ninja, g++): a fresh
# Debian root set up by tools/setup-debian.sh has no `make` for CMake's default generator.
# usage: install_test.sh BUILD_DIR SOURCE_DIR VERSION GENERATOR CXX_COMPILER
set -eu
build=$1 source=$2 version=$3 generator=$4 cxx=$5
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
cmake --install "$build" --prefix "$dir/prefix" > "$dir/install.log"
prefix=$dir/prefix
[ "$("$prefix/bin/grazelab-cli" --version)" = "grazelab-cli $version" ] || { echo "FAIL: installed grazelab-cli"; exit 1; }
for f in include/grazelab/core/solver/simulate.h include/grazelab/core/model/linear_modes.h include/grazelab/core/version.h lib/cmake/GrazeLab/GrazeLabConfig.cmake \
         lib/pkgconfig/grazelab-core.pc; do
  [ -f "$prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done
ls "$prefix"/lib/libgrazelab_core.a > /dev/null
# the public headers only, each whole with the installed ones: one file including them all
# compiles against the installed tree alone (no source tree, no SUNDIALS headers)
for f in methods/cvode_integrator.h methods/runners.h solver/impact_law.h; do
  [ ! -e "$prefix/include/grazelab/core/$f" ] || { echo "FAIL: the private header core/$f is installed"; exit 1; }
done
(cd "$prefix/include/grazelab" && find core -name '*.h' | sort | sed 's/.*/#include "&"/') > "$dir/all_headers.cpp"
[ "$(wc -l < "$dir/all_headers.cpp")" -gt 20 ] || { echo "FAIL: too few headers installed"; exit 1; }
(cd "$dir" && "$cxx" -std=c++20 -fsyntax-only -I"$prefix/include/grazelab" -I/usr/include/eigen3 all_headers.cpp) \
  || { echo "FAIL: an installed header needs one that is not installed"; exit 1; }
# the CMake package
cmake -S "$source/examples/core-consumer" -B "$dir/example" -G "$generator" \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release > "$dir/configure.log" || { cat "$dir/configure.log"; exit 1; }
cmake --build "$dir/example" > "$dir/build.log" || { cat "$dir/build.log"; exit 1; }
"$dir/example/impacts" > "$dir/cmake.out"
head -1 "$dir/cmake.out" | grep -q "^GrazeLab $version: 5 contacts" || { echo "FAIL: $(head -1 "$dir/cmake.out")"; exit 1; }
# pkg-config
PKG_CONFIG_PATH="$prefix/lib/pkgconfig" "$cxx" -O2 "$source/examples/core-consumer/main.cpp" \
  $(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs grazelab-core) -o "$dir/impacts-pc"
"$dir/impacts-pc" > "$dir/pc.out"
cmp "$dir/cmake.out" "$dir/pc.out" || { echo "FAIL: the pkg-config build differs"; exit 1; }
# the same core as the command line: the same contact times to the last digit
"$prefix/bin/grazelab-cli" simulate --glo 0.5 --perturb 0,0,0,-0.05 --contacts 5 --precision double \
  --trust off > "$dir/cli.json"
python3 - "$dir/cli.json" "$dir/cmake.out" <<'PY'
import json, sys
cli = [e["t"] for e in json.load(open(sys.argv[1]))["events"]]
mine = [float(line.split()[2]) for line in open(sys.argv[2]).read().splitlines()[1:]]
assert cli == mine, (cli, mine)
PY
echo "installed and used: $prefix"
