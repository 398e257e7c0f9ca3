#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Builds the core library alone, without Qt (-DGRAZELAB_CORE_ONLY=ON), in ./build-core, with its
# tests and benchmarks, and runs its tests: what a C++ user of the simulator builds.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup-debian.sh
cmake -S . -B build-core -G Ninja -DCMAKE_BUILD_TYPE=Release -DGRAZELAB_CORE_ONLY=ON ${CI:+-DGRAZELAB_WERROR=ON}
cmake --build build-core
ctest --test-dir build-core --output-on-failure -j "$(nproc)"
