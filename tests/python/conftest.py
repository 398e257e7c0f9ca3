# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""Shared fixtures: the command line the module must agree with."""

import json
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli_path():
    path = os.environ.get("GRAZELAB_CLI")
    if not path or not os.path.exists(path):
        pytest.fail("GRAZELAB_CLI must name the grazelab-cli the module is compared with")
    return path


@pytest.fixture(scope="session")
def cli(cli_path):
    """cli(*arguments) -> CompletedProcess (text); never raises on a non-zero exit."""

    def run(*arguments, cwd=None):
        return subprocess.run([cli_path, *arguments], capture_output=True, text=True, cwd=cwd,
                              env=dict(os.environ, QT_QPA_PLATFORM="offscreen"), timeout=300)

    return run


@pytest.fixture(scope="session")
def cli_json(cli):
    """cli_json(*arguments, exact=False): the command's JSON on stdout; with exact its numbers
    as the decimal text written."""

    def run(*arguments, exact=False):
        done = cli(*arguments)
        assert done.returncode == 0, done.stderr
        if exact:
            return json.loads(done.stdout, parse_float=str, parse_int=str)
        return json.loads(done.stdout)

    return run
