"""Sway and yaw derivatives from Python (pmm_derivatives): the numbers and documents of
`hydrocoef derivatives pmm --json` on the same database (the real OpenFOAM sphere runs read as
sway runs), and its messages."""

import json

import pytest

import hydrocoef
from conftest import SOURCE_DIR, cli_error, cli_json, run_cli

PMM = SOURCE_DIR / "examples" / "openfoam-sphere" / "pmm"


@pytest.fixture(scope="module")
def sway_db(tmp_path_factory):
    path = tmp_path_factory.mktemp("pmm-derivatives") / "pmm.db"
    # The sphere moved along the case's x, read with body y = case x: two sway runs at U = 0.
    run_cli(path, "pmm", str(PMM / "surge-A0.015-T2"), str(PMM / "surge-A0.045-T2"), "--body", "sphere",
            "--axes", "y,x,-z", "--rho", "998.2")
    run_cli(path, "body", "set", "sphere", "--length", "0.3")
    return path


def test_pmm_derivatives_are_the_cli_ones(sway_db):
    with hydrocoef.Database(sway_db, mode="r") as db:
        result = hydrocoef.pmm_derivatives(db, "sphere", speed=0.5)
        matrix = hydrocoef.added_mass_matrix(db, "sphere")
    document = cli_json(sway_db, "derivatives", "pmm", "sphere", "--speed", "0.5")
    assert json.loads(result.json()) == document
    assert result.text() == run_cli(sway_db, "derivatives", "pmm", "sphere", "--speed", "0.5")[1]
    assert [s.motion for s in result.sets] == ["pure sway"]
    assert result.length == 0.3 and result.length_from == "body reference"
    for ours, theirs in zip(result.sets[0].derivatives, document["sets"][0]["derivatives"]):
        assert ours.name == theirs["name"]
        assert ours.value == theirs["value"]
        assert ours.std_error == theirs["std_error"]
        assert ours.prime == theirs["prime"]
    assert result.sets[0].omega_prime == document["sets"][0]["omega_prime"]
    y_vdot = result.sets[0].derivatives[1]
    assert y_vdot.name == "Y_vdot" and y_vdot.value == -matrix.added_mass[1, 1]
    assert [run.id for run in result.runs] == [r["id"] for r in cli_json(sway_db, "pmm-runs")]


def test_pmm_derivatives_refuse_what_the_cli_refuses(sway_db):
    with hydrocoef.Database(sway_db, mode="r") as db:
        for kwargs, args in [(dict(prime=True), ["--prime"]), (dict(runs=[999]), ["--run", "999"]),
                             (dict(length=-1.0), ["--length", "-1"])]:
            with pytest.raises(hydrocoef.InputError) as error:
                hydrocoef.pmm_derivatives(db, "sphere", **kwargs)
            assert str(error.value) == cli_error(sway_db, "derivatives", "pmm", "sphere", *args)
        with pytest.raises(hydrocoef.InputError, match="has no stored forced-oscillation runs"):
            hydrocoef.pmm_derivatives(db, "nobody")


def test_results_come_from_pmm_derivatives_only():
    for cls in (hydrocoef.PmmDerivatives, hydrocoef.PmmFrequencyDerivatives, hydrocoef.PmmDerivative,
                hydrocoef.PmmDerivativeRun):
        with pytest.raises(TypeError, match="come from pmm_derivatives"):
            cls.__new__(cls)
        with pytest.raises(TypeError):
            type("Sub", (cls,), {})
