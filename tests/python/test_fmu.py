"""FMUs from Python (export_fmu): the variables and identifier `hydrocoef export-fmu --json` states on
the same database, the file a zip with the model description, the binary and the runtime file, and the
command's messages for bad input."""

import json
import zipfile

import pytest

import hydrocoef
from conftest import ASR_V, cli_error, cli_json


def test_export_fmu_is_the_cli_one(db, db_path, tmp_path):
    result = hydrocoef.export_fmu(db, "grid", surface="grid-pchip", output=str(tmp_path / "python.fmu"))
    document = cli_json(db_path, "export-fmu", "grid", "--surface", "grid-pchip", "-o", str(tmp_path / "cli.fmu"))
    ours = json.loads(result.json())
    for key in ("body", "surface", "kind", "model_identifier", "binary_bytes", "variables"):
        assert ours[key] == document[key], key
    assert result.model_identifier == "hc_grid_pchip"
    assert [v.name for v in result.variables] == [v["name"] for v in document["variables"]]
    assert [v.causality for v in result.variables][:2] == ["input", "input"]
    assert result.variables[0].start == document["variables"][0]["start"]
    with zipfile.ZipFile(tmp_path / "python.fmu") as archive:
        assert archive.testzip() is None
        assert sorted(archive.namelist()) == ["binaries/linux64/hc_grid_pchip.so", "modelDescription.xml",
                                              "resources/model.hcr"]
        assert f'guid="{result.guid}"' in archive.read("modelDescription.xml").decode()
    assert result.fmu_bytes == (tmp_path / "python.fmu").stat().st_size


def test_export_vehicle_fmu_is_the_cli_one(db, db_path, tmp_path):
    vehicle = str(ASR_V / "vehicle.json")
    result = hydrocoef.export_fmu(db, "asr-v", vehicle=vehicle, output=str(tmp_path / "python.fmu"))
    document = cli_json(db_path, "export-fmu", "asr-v", "--vehicle", vehicle, "-o", str(tmp_path / "cli.fmu"))
    ours = json.loads(result.json())
    for key in ("body", "vehicle", "kind", "model_identifier", "binary_bytes", "variables"):
        assert ours[key] == document[key], key
    assert result.kind == "vehicle"
    assert [v.causality for v in result.variables].count("parameter") == 13
    assert [v.start for v in result.variables if v.name == "step"] == [0.001]


def test_export_fmu_refuses_what_the_cli_refuses(db, db_path, tmp_path):
    for kwargs, args in [(dict(surface="nope", output=str(tmp_path / "x.fmu")), ["--surface", "nope", "-o",
                                                                              str(tmp_path / "x.fmu")]),
                         (dict(surface="grid-pchip", output=str(tmp_path / "x.zip")), ["--surface", "grid-pchip",
                                                                                     "-o", str(tmp_path / "x.zip")])]:
        with pytest.raises(hydrocoef.InputError) as error:
            hydrocoef.export_fmu(db, "grid", **kwargs)
        assert str(error.value) == cli_error(db_path, "export-fmu", "grid", *args)
    assert not (tmp_path / "x.fmu").exists()


def test_results_come_from_export_fmu_only():
    for cls in (hydrocoef.FmuExportResult, hydrocoef.FmuVariable):
        with pytest.raises(TypeError, match="come from export_fmu"):
            cls.__new__(cls)
