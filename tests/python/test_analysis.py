"""The analyses from Python (grid_convergence, analyse_pmm, store_pmm, pmm_runs,
delete_pmm_runs, added_mass_matrix, suggest_runs): the numbers and documents of
the CLI's --json on the same databases, and its messages."""

import json
import math

import numpy as np
import pytest

import hydrocoef
from conftest import ASR_V, SOURCE_DIR, cli_error, cli_json, run_cli

PMM = SOURCE_DIR / "examples" / "openfoam-sphere" / "pmm"
STUDY = SOURCE_DIR / "data" / "openfoam-sphere" / "converged"
VOLUME = 4.0 / 3.0 * math.pi * 0.15 ** 3
SPHERE_INPUTS = [PMM / "surge-A0.015-T2", PMM / "surge-A0.045-T2"]
SPHERE_OPTIONS = dict(body="sphere", axes="-x,y,-z", rho=998.2, nu=1.004e-6, volume=VOLUME, size=0.3)
SPHERE_CLI = ["pmm", *map(str, SPHERE_INPUTS), "--body", "sphere", "--axes=-x,y,-z", "--rho", "998.2", "--nu",
              "1.004e-6", "--volume", repr(VOLUME), "--size", "0.3"]
SPHERE_MATRIX = ["added-mass", "sphere", "--same", "sway=surge", "--same", "heave=surge", "--zero", "roll,pitch,yaw"]


@pytest.fixture(scope="module")
def pmm_db(tmp_path_factory):
    path = tmp_path_factory.mktemp("pmm") / "pmm.db"
    analysis = hydrocoef.analyse_pmm(SPHERE_INPUTS, **SPHERE_OPTIONS)
    with hydrocoef.Database(path, mode="create") as db:
        hydrocoef.store_pmm(db, analysis)
    return path, analysis


def test_analyse_pmm_is_the_cli_analysis(tmp_path):
    analysis = hydrocoef.analyse_pmm(SPHERE_INPUTS, **SPHERE_OPTIONS)
    db = tmp_path / "none.db"
    document = cli_json(db, *SPHERE_CLI, "--no-store")
    assert json.loads(analysis.json()) == document
    assert analysis.text() == run_cli(db, *SPHERE_CLI, "--no-store")[1]
    assert not db.exists()
    assert [run.dof for run in analysis.runs] == ["surge", "surge"]
    for run, expected in zip(analysis.runs, document["runs"]):
        x = run.components[0]
        assert x.component == "X"
        assert x.added_mass == expected["components"][0]["added_mass"]
        assert x.damping == expected["components"][0]["damping"]
        assert x.added_mass_coefficient == expected["components"][0]["added_mass_coefficient"]
        assert abs(x.added_mass_coefficient - 0.5) < 0.05
        assert run.keulegan_carpenter == expected["keulegan_carpenter"]
        assert run.stored_id == 0


def test_stored_runs_and_the_matrix_are_the_cli_ones(pmm_db, tmp_path):
    path, analysis = pmm_db
    assert analysis.stored and analysis.database == str(path)
    assert [run.stored_id for run in analysis.runs] == [r["id"] for r in cli_json(path, "pmm-runs")]
    with hydrocoef.Database(path, mode="r") as db:
        listing = hydrocoef.pmm_runs(db)
        matrix = hydrocoef.added_mass_matrix(db, "sphere", same={"sway": "surge", "heave": "surge"},
                                             zero=["roll", "pitch", "yaw"])
        assert hydrocoef.pmm_runs(db, "nobody").runs == []
    assert json.loads(listing.json()) == cli_json(path, "pmm-runs")
    assert listing.text() == run_cli(path, "pmm-runs")[1]
    assert listing.runs[0].added_mass == analysis.runs[0].components[0].added_mass
    document = cli_json(path, *SPHERE_MATRIX)
    assert json.loads(matrix.json()) == document
    assert matrix.text() == run_cli(path, *SPHERE_MATRIX)[1]
    assert isinstance(matrix.added_mass, np.ndarray) and matrix.added_mass.shape == (6, 6)
    np.testing.assert_array_equal(matrix.added_mass, np.array(document["added_mass_b"]))
    np.testing.assert_array_equal(matrix.damping, np.array(document["damping_b"]))
    assert matrix.positive_definite and matrix.records == 2
    assert matrix.quadratic_damping[0].quadratic == document["quadratic_damping"][0]["quadratic"]


def test_deleting_runs_is_the_cli_deletion(tmp_path):
    path = tmp_path / "delete.db"
    analysis = hydrocoef.analyse_pmm(SPHERE_INPUTS, **SPHERE_OPTIONS)
    with hydrocoef.Database(path, mode="create") as db:
        hydrocoef.store_pmm(db, analysis)
    copy = tmp_path / "copy.db"
    copy.write_bytes(path.read_bytes())
    first = analysis.runs[0].stored_id
    before = path.read_bytes()
    with hydrocoef.Database(path, mode="r") as db:
        with pytest.raises(hydrocoef.InputError, match="read-only"):
            hydrocoef.delete_pmm_runs(db, [first])
        with pytest.raises(hydrocoef.InputError, match="read-only"):
            hydrocoef.store_pmm(db, analysis)
    assert path.read_bytes() == before
    message = cli_error(path, "pmm-runs", "delete", str(first), "999")
    with hydrocoef.Database(path, mode="rw") as db:
        with pytest.raises(hydrocoef.InputError) as refused:
            hydrocoef.delete_pmm_runs(db, [first, 999])
        assert str(refused.value) == message and "no forced-oscillation run 999" in message
        deletion = hydrocoef.delete_pmm_runs(db, [first])
    ours = json.loads(deletion.json())
    theirs = cli_json(copy, "pmm-runs", "delete", str(first))
    assert ours.pop("database") == str(path) and theirs.pop("database") == str(copy)
    assert ours == theirs
    assert [d.dof for d in deletion.deleted] == ["surge"]


def test_grid_convergence_is_the_cli_study(tmp_path):
    path = tmp_path / "gci.db"
    cases = json.loads((STUDY / "reference.json").read_text())["cases"]
    with hydrocoef.Database(path, mode="create") as db:
        for case in cases.values():
            db.import_files(STUDY / case["case"], body="sphere",
                            settings={"disturbances": {"mesh": case["mesh"], "cells": case["cells"]}})
    with hydrocoef.Database(path, mode="r") as db:
        study = hydrocoef.grid_convergence(db, body="sphere", allow_unconverged=True, store=False)
        with pytest.raises(hydrocoef.InputError) as refused:
            hydrocoef.grid_convergence(db, body="sphere", store=False)
        assert str(refused.value) == cli_error(path, "gci", "--body", "sphere", "--no-store")
    document = cli_json(path, "gci", "--body", "sphere", "--allow-unconverged", "--no-store")
    assert json.loads(study.json()) == document
    assert study.text() == run_cli(path, "gci", "--body", "sphere", "--allow-unconverged", "--no-store")[1]
    assert len(study.keys) == 2 and not study.stored
    for key, expected in zip(study.keys, document["keys"]):
        x = key.components[0]
        assert key.velocity[0] == expected["key"]["u"]
        assert x.apparent_order == expected["components"]["X"]["apparent_order"]
        assert x.gci_fine == expected["components"]["X"]["gci_fine"]
        assert x.numerical_uncertainty == expected["components"]["X"]["numerical_uncertainty"]
    with pytest.raises(hydrocoef.InputError, match="--dimension 4: expected 1, 2 or 3"):
        with hydrocoef.Database(path, mode="r") as db:
            hydrocoef.grid_convergence(db, body="sphere", dimension=4)


def test_suggest_runs_is_the_cli_suggestion(tmp_path):
    path = tmp_path / "gp.db"
    with hydrocoef.Database(path, mode="create") as db:
        db.import_files(ASR_V / "asr-v-surge-damping.csv", body="asr-v", settings={"sign": "opposing", "rho": 998.2})
        db.build_surface("surge-gp", body="asr-v", axes="u", outputs="X", method="gp", gp_starts=2)
    with hydrocoef.Database(path, mode="r") as db:
        suggestion = hydrocoef.suggest_runs(db, "surge-gp", count=3, bounds="u=0.05:0.35")
        with pytest.raises(hydrocoef.InputError) as refused:
            hydrocoef.suggest_runs(db, "surge-gp", count=0)
    assert str(refused.value) == cli_error(path, "suggest", "surge-gp", "--count", "0")
    document = cli_json(path, "suggest", "surge-gp", "--count", "3", "--bounds", "u=0.05:0.35")
    assert json.loads(suggestion.json()) == document
    assert suggestion.text() == run_cli(path, "suggest", "surge-gp", "--count", "3", "--bounds", "u=0.05:0.35")[1]
    assert [run.key[0] for run in suggestion.runs] == [r["key"]["u"] for r in document["runs"]]
    assert [run.sd_before for run in suggestion.runs] == [r["sd_before"] for r in document["runs"]]


def test_options_are_refused_with_the_cli_messages(pmm_db):
    path, _ = pmm_db
    with pytest.raises(hydrocoef.InputError) as refused:
        hydrocoef.analyse_pmm(SPHERE_INPUTS, motion="surge", amplitude=0.05)
    assert str(refused.value) == cli_error(path, "pmm", str(SPHERE_INPUTS[0]), "--motion", "surge",
                                           "--amplitude", "0.05")
    with pytest.raises(hydrocoef.InputError) as refused:
        hydrocoef.analyse_pmm(SPHERE_INPUTS, harmonics=11)
    assert str(refused.value) == cli_error(path, "pmm", str(SPHERE_INPUTS[0]), "--harmonics", "11")
    with hydrocoef.Database(path, mode="r") as db:
        with pytest.raises(hydrocoef.InputError) as refused:
            hydrocoef.added_mass_matrix(db, "sphere", zero="twist")
    assert str(refused.value) == cli_error(path, "added-mass", "sphere", "--zero", "twist")
    for make in (hydrocoef.GciStudy, hydrocoef.PmmAnalysis, hydrocoef.AddedMassMatrix, hydrocoef.Suggestion):
        with pytest.raises(TypeError):
            make()
