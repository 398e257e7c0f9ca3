# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""A PEP 517 build backend for `pip install .`: configures the project's CMake for the Python
module alone (no explorer, tests or benchmarks), builds it for the interpreter pip runs, and
packs build/python/grazelab into a wheel. It imports nothing outside the standard library, so
pip's isolated build environment needs no download.

The CMake build directory is kept (build-python/ in the source tree, or GRAZELAB_PIP_BUILD_DIR):
a second `pip install .` rebuilds only what changed.
"""

import base64
import hashlib
import os
import re
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

_SOURCE = Path(__file__).resolve().parents[2]


def _version():
    text = (_SOURCE / "CMakeLists.txt").read_text(encoding="utf-8")
    found = re.search(r"project\(GrazeLab VERSION ([0-9.]+)", text)
    if not found:
        raise RuntimeError("grazelab: no project(GrazeLab VERSION ...) in CMakeLists.txt")
    return found.group(1)


def _tag():
    # the module is built for this interpreter and platform
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = re.sub(r"[-.]", "_", sysconfig.get_platform())
    return f"{python}-{python}-{platform}"


def _metadata():
    return (f"Metadata-Version: 2.1\nName: grazelab\nVersion: {_version()}\n"
            "Summary: Exact simulation of mass-spring chains against a rigid stop\n"
            "License: MIT\nRequires-Python: >=3.9\nRequires-Dist: numpy\n")


def _build_module():
    build = Path(os.environ.get("GRAZELAB_PIP_BUILD_DIR", _SOURCE / "build-python"))
    configure = ["cmake", "-S", str(_SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                 "-DGRAZELAB_BUILD_UI=OFF", "-DGRAZELAB_BUILD_TESTS=OFF",
                 "-DGRAZELAB_BUILD_BENCHMARKS=OFF", "-DGRAZELAB_BUILD_PYTHON=ON",
                 f"-DGRAZELAB_PYTHON={sys.executable}"]
    if not (build / "CMakeCache.txt").exists() and _has("ninja"):
        configure += ["-G", "Ninja"]
    jobs = str(os.cpu_count() or 1)
    for command in (configure, ["cmake", "--build", str(build), "--target", "grazelab_native",
                                "--parallel", jobs]):
        print("grazelab:", " ".join(command), file=sys.stderr, flush=True)
        subprocess.run(command, check=True, stdout=sys.stderr)
    package = build / "python" / "grazelab"
    if not any(package.glob("_native*.so")):
        raise RuntimeError(f"grazelab: the build made no {package}/_native*.so")
    return package


def _has(program):
    return any((Path(p) / program).exists() for p in os.environ.get("PATH", "").split(os.pathsep))


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    info = Path(metadata_directory) / f"grazelab-{_version()}.dist-info"
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(_metadata(), encoding="utf-8")
    return info.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    package = _build_module()
    version = _version()
    name = f"grazelab-{version}-{_tag()}.whl"
    info = f"grazelab-{version}.dist-info"
    files = {}
    for path in sorted(package.iterdir()):
        if path.is_file() and (path.suffix in (".py", ".pyi", ".so") or path.name == "py.typed"):
            files[f"grazelab/{path.name}"] = path.read_bytes()
    files[f"{info}/METADATA"] = _metadata().encode()
    files[f"{info}/WHEEL"] = (f"Wheel-Version: 1.0\nGenerator: grazelab_build\n"
                              f"Root-Is-Purelib: false\nTag: {_tag()}\n").encode()
    record = [_record_line(n, d) for n, d in files.items()] + [f"{info}/RECORD,,"]
    files[f"{info}/RECORD"] = ("\n".join(record) + "\n").encode()
    target = Path(wheel_directory) / name
    partial = target.with_suffix(".partial")
    with zipfile.ZipFile(partial, "w", zipfile.ZIP_DEFLATED) as wheel:
        for entry, data in files.items():
            wheel.writestr(entry, data)
    os.replace(partial, target)
    return name
