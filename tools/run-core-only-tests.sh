#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Builds the core library alone, without Qt (-DGRAZELAB_CORE_ONLY=ON), in ./build-core, with its
# tests, and runs them: what a C++ user of the simulator builds. (The benchmarks, built by
# tools/run-tests.sh, are left out here: CI's time goes to what this build alone can show.)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup-debian.sh
cmake -S . -B build-core -G Ninja -DCMAKE_BUILD_TYPE=Release -DGRAZELAB_CORE_ONLY=ON -DGRAZELAB_BUILD_BENCHMARKS=OFF \
  ${CI:+-DGRAZELAB_WERROR=ON}
cmake --build build-core
ctest --test-dir build-core --output-on-failure -j "$(nproc)"
