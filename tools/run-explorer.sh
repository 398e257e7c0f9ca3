#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Sets up what is missing, builds the explorer in ./build and opens it on its default scene.
# Arguments are passed to the explorer (try --help).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup-debian.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target grazelab grazelab-cli
exec ./build/app/grazelab/grazelab "$@"
