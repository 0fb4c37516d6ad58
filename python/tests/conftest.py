"""pytest setup: the module built in <build>/python (ctest sets PYTHONPATH and LAC_BINARY_DIR)."""
import os
import pathlib
import shutil

import pytest


@pytest.fixture(scope="session")
def lac_cli():
    """Path of the lac command-line tool of this build (the C++ reference of the bindings)."""
    build = os.environ.get("LAC_BINARY_DIR")
    candidates = [pathlib.Path(build) / "lac"] if build else []
    candidates.append(pathlib.Path(__file__).resolve().parents[2] / "build" / "lac")
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK):
            return str(c)
    found = shutil.which("lac")
    if found:
        return found
    pytest.skip("the lac command-line tool is not built (ninja lac_tool)")
