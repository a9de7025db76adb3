"""examples/python/pmm_analysis.py and gci_study.py run as a user runs them (the
same interpreter, the module of this build), their printed numbers checked
against physics and against the CLI's --json on the database each made."""

import os
import pathlib
import re
import subprocess
import sys

import hydrocoef
from conftest import SOURCE_DIR, cli_json

EXAMPLES = SOURCE_DIR / "examples" / "python"
NUMBER = r"(-?[0-9.]+(?:e[-+]?[0-9]+)?)"


def run_example(name, db):
    environment = dict(os.environ, PYTHONPATH=str(pathlib.Path(hydrocoef.__file__).resolve().parents[1]))
    result = subprocess.run([sys.executable, str(EXAMPLES / name), "--db", str(db)], capture_output=True, text=True,
                            env=environment)
    assert result.returncode == 0, result.stderr
    return result.stdout


def close(printed, exact):
    """A number printed with 6 significant digits is the exact one."""
    return abs(float(printed) - exact) <= 5e-6 * abs(exact)


def test_pmm_example_gives_half_the_displaced_mass(tmp_path):
    db = tmp_path / "pmm.db"
    out = run_example("pmm_analysis.py", db)
    runs = re.findall(r"run (\S+): .*M_A = " + NUMBER + r" kg \(C_A = " + NUMBER + r"\), D = " + NUMBER, out)
    assert [name for name, *_ in runs] == ["surge-A0.015-T2", "surge-A0.045-T2"], out
    for _, _, coefficient, damping in runs:
        assert 0.45 < float(coefficient) < 0.55
        assert float(damping) > 0  # the boundary layer dissipates
    matrix = cli_json(db, "added-mass", "sphere", "--same", "sway=surge", "--same", "heave=surge", "--zero",
                      "roll,pitch,yaw")
    diagonal = re.search(r"M_A diagonal \[kg, kg m\^2\]: (.*)", out).group(1).split()
    assert len(diagonal) == 6
    for i in range(6):
        assert close(diagonal[i], matrix["added_mass_b"][i][i]), (diagonal, matrix["added_mass_b"])
    c_a = float(re.search(r"C_A = M_A / \(rho V\) = " + NUMBER, out).group(1))
    assert 0.5 < c_a < 0.55  # potential flow's 0.5 and a few per cent of boundary layer
    b2 = re.search(r"quadratic damping of surge: b1 = " + NUMBER + r" N s/m, b2 = " + NUMBER, out)
    assert close(b2.group(2), matrix["quadratic_damping"][0]["quadratic"])
    # Run again on the same database: the analyses replace the stored ones.
    assert run_example("pmm_analysis.py", db) == out
    assert len(cli_json(db, "pmm-runs")) == 2


def test_gci_example_gives_the_cli_study(tmp_path):
    db = tmp_path / "gci.db"
    out = run_example("gci_study.py", db)
    lines = re.findall(r"u = " + NUMBER + r" m/s, mesh levels 3,2,1: X fine to coarse " + NUMBER +
                       r" .*, (monotonic|oscillatory), p = " + NUMBER +
                       r", X_ext = " + NUMBER + r" N, GCI_fine = " + NUMBER + r", u_num = " + NUMBER, out)
    assert len(lines) == 2, out
    study = cli_json(db, "gci", "--body", "sphere", "--allow-unconverged", "--no-store")
    for (u, fine, convergence, p, extrapolated, gci, u_num), key in zip(lines, study["keys"]):
        x = key["components"]["X"]
        assert float(u) == key["key"]["u"] and float(u) < 0  # the body moves against the free stream
        assert convergence == x["convergence"]
        for printed, exact in ((p, x["apparent_order"]), (extrapolated, x["extrapolated"]),
                               (gci, x["gci_fine"]), (u_num, x["numerical_uncertainty"])):
            assert close(printed, exact), (printed, exact)
        assert close(fine, x["phi"][0])
        # u_num = GCI_fine |phi1| / 2, and the drag converges towards a smaller value on finer meshes.
        assert abs(float(u_num) - float(gci) * float(fine) / 2) <= 2e-5 * float(u_num)
        assert 0 < float(gci) < 1 and 0 < float(extrapolated) < float(fine)
    # Stored: the finest runs carry the numerical uncertainty.
    assert study["stored"] is False and cli_json(db, "gci", "--body", "sphere", "--allow-unconverged")["stored"]
