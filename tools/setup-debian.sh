#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Installs what GrazeLab needs on Debian 12 from Debian's own packages, non-interactively.
# Packages already present are not touched; nothing is installed when all are there.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config          # compiler and build
  libeigen3-dev                             # linear algebra (core)
  libboost-dev                              # binary128, exact rationals, Odeint (core)
  libsundials-dev                           # CVODE: the comparison methods (core)
  qt6-base-dev qt6-charts-dev qt6-svg-dev   # explorer and command line
  libqt6opengl6-dev                         # Qt Charts needs Qt6OpenGL (only recommended)
  libgl-dev libvulkan-dev libxkbcommon-dev  # headers Qt6's CMake packages look for
  fonts-dejavu-core                         # text in offscreen snapshots
  libtbb-dev                                # oneTBB: maps on all cores
  parallel                                  # GNU parallel: the sharded-map test
  libgtest-dev libbenchmark-dev             # tests and benchmarks
  poppler-utils                             # pdftotext: tests read the text of PDF snapshots
  python3 python3-mpmath                    # the independent high-precision reference
  python3-dev pybind11-dev                  # the Python module (python/)
  python3-numpy python3-pytest              # its arrays and its tests
  python3-venv                              # `pip install .` into a venv (README, its test)
)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$package")
done
if [ "${#missing[@]}" -eq 0 ]; then
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
echo "Installing: ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
