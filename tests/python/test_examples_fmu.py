"""The FMU example (examples/python/export_fmu.py) run as a user runs it, on a database of its own: the FMU
it writes is a zip with the model description, the binary and the runtime file, and the variables it prints
are the yaw surface's."""

import os
import pathlib
import subprocess
import sys
import zipfile

import hydrocoef
from conftest import SOURCE_DIR


def test_export_fmu_writes_the_yaw_surface_as_an_fmu(tmp_path):
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(hydrocoef.__file__).resolve().parents[1]))
    result = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "python" / "export_fmu.py"), "--db",
                             str(tmp_path / "fmu.db")], capture_output=True, text=True, env=env)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[-3:] == ["0 r input rad/s", "1 N output N m", "2 sigma(N) output N m"]
    assert "modelIdentifier hc_yaw" in result.stdout
    with zipfile.ZipFile(tmp_path / "asr-v-yaw.fmu") as archive:
        assert archive.testzip() is None
        assert sorted(archive.namelist()) == ["binaries/linux64/hc_yaw.so", "modelDescription.xml",
                                              "resources/model.hcr"]
