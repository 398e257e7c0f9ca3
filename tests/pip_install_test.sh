#!/bin/bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# `pip install .` as the README gives it (issue "One architecture…", item 7): in a fresh venv
# made with --system-site-packages (Debian's NumPy), the in-tree build backend runs the
# project's CMake; the installed module imports from anywhere, names the project's version,
# and its contact times equal grazelab-cli's to the last digit.
# usage: pip_install_test.sh SOURCE_DIR VERSION GRAZELAB_CLI PYTHON
set -eu
source=$1 version=$2 cli=$3 python=$4
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
"$python" -m venv --system-site-packages "$dir/venv"
# the CMake build inside the temporary folder: nothing of a developer's build-python/ reused
GRAZELAB_PIP_BUILD_DIR="$dir/build" "$dir/venv/bin/pip" install --quiet "$source" > "$dir/pip.log" 2>&1 \
  || { tail -30 "$dir/pip.log"; echo "FAIL: pip install"; exit 1; }
"$cli" simulate --glo 0.5 --perturb 0,0,0,-0.05 --contacts 5 --precision double --trust off > "$dir/cli.json"
cd "$dir"
"$dir/venv/bin/python" - "$version" "$dir/cli.json" "$dir/venv" <<'PY'
import json, sys
import grazelab as gl
version, cli_json, venv = sys.argv[1:]
assert gl.__version__ == version, (gl.__version__, version)
assert gl.__file__.startswith(venv), gl.__file__
run = gl.simulate(glo=0.5, perturb=(0, 0, 0, -0.05), contacts=5, precision="double", trust="off")
cli = [event["t"] for event in json.load(open(cli_json))["events"]]
assert list(run.events["t"]) == cli, (list(run.events["t"]), cli)
PY
echo "pip install . in a venv: grazelab $version imports and agrees with grazelab-cli"
