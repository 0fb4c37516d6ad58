"""The example scripts run as documented and write what they say (python/examples/)."""
import os
import pathlib
import subprocess
import sys

import ezdxf

EXAMPLES = pathlib.Path(__file__).resolve().parents[1] / "examples"


def test_g1_figure_writes_its_figure_and_a_dxf_that_reads_back(tmp_path):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    out = tmp_path / "fig.png"
    run = subprocess.run([sys.executable, str(EXAMPLES / "g1_figure.py"), str(out)], env=env, cwd=tmp_path,
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert out.stat().st_size > 10000
    dxf = tmp_path / "fig_g2.dxf"
    splines = [e for e in ezdxf.readfile(dxf).modelspace() if e.dxftype() == "SPLINE"]
    assert len(splines) == 1
    assert "ok wrote" in run.stdout
