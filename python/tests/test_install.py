"""`import lac` after `cmake --install`: the package installed under a temporary prefix imports and
solves, without the build folder on the path."""
import os
import pathlib
import shutil
import subprocess
import sys

import pytest


def test_import_after_cmake_install(tmp_path):
    build = os.environ.get("LAC_BINARY_DIR")
    cmake = shutil.which("cmake")
    if not build or not cmake or not (pathlib.Path(build) / "cmake_install.cmake").exists():
        pytest.skip("needs LAC_BINARY_DIR (set by ctest) and cmake")
    prefix = tmp_path / "prefix"
    out = subprocess.run([cmake, "--install", build, "--prefix", str(prefix)], capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr
    inits = list(prefix.glob("lib*/python3*/*-packages/lac/__init__.py"))
    assert len(inits) == 1, inits
    assert list(inits[0].parent.glob("_lac*.so")) and (inits[0].parent / "__init__.pyi").exists()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(inits[0].parent.parent)
    code = ("import lac; r = lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0); "
            "print(lac.__file__, r.status, r.curve.length)")
    run = subprocess.run([sys.executable, "-c", code], env=env, cwd=tmp_path, capture_output=True, text=True,
                         timeout=60)
    assert run.returncode == 0, run.stderr
    where, status, length = run.stdout.split()
    assert where.startswith(str(prefix)) and status == "ok" and abs(float(length) - 1.02096027) < 1e-6
