#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Sets up what is missing, builds everything (explorer, command line, tests, benchmarks) in
# ./build and runs every test with ctest. UI tests run offscreen: no display is needed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup-debian.sh
# under CI a warning is an error (-DGRAZELAB_WERROR=ON)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release ${CI:+-DGRAZELAB_WERROR=ON}
cmake --build build
QT_QPA_PLATFORM=offscreen ctest --test-dir build --output-on-failure -j "$(nproc)"
