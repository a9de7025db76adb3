"""Runtime files from Python (hydrocoef.RuntimeModel): a file `hydrocoef export --format runtime` wrote, loaded
through libhydrocoef_runtime, gives `hydrocoef query --json`'s values, gradients and standard deviations exactly;
a missing, a foreign and a tampered file, a point outside an "error" axis and a wrong number of coordinates raise
hydrocoef.InputError with the runtime library's message."""

import numpy as np
import pytest

import hydrocoef
from conftest import cli_json, run_cli


def export_runtime(db_path, surface, path):
    run_cli(db_path, "export", surface, "--format", "runtime", "-o", str(path))
    return hydrocoef.RuntimeModel(path)


@pytest.mark.parametrize("name", ["grid-linear", "grid-pchip"])
def test_values_and_gradients_are_the_cli_querys(db_path, tmp_path, name):
    model = export_runtime(db_path, name, tmp_path / "model.hcrt")
    assert model.surfaces == [name]
    assert model.axes(name) == ["u", "v"]
    assert model.outputs(name) == ["X", "Y"]
    assert not model.has_vehicle
    for u, v in [(0.234, -0.0567), (0.01, 0.19), (0.37, 0.0), (0.2, 0.1)]:
        expected = cli_json(db_path, "query", name, f"u={u!r}", f"v={v!r}", "--gradient")
        result = model.evaluate(name, [u, v])
        assert result["gradients"].shape == (2, 2)
        for k, output in enumerate(("X", "Y")):
            assert result["values"][k] == expected["values"][output]
            for a, axis in enumerate(("u", "v")):
                assert result["gradients"][k, a] == expected["gradient"][output][axis]
        if result["sigma"] is not None:
            stated = cli_json(db_path, "query", name, f"u={u!r}", f"v={v!r}", "--uncertainty")
            for k, output in enumerate(("X", "Y")):
                assert result["sigma"][k] == stated["standard_deviation"][output]


def test_a_one_axis_surface_with_linear_extrapolation_is_the_cli_querys(db_path, tmp_path):
    model = export_runtime(db_path, "asr-v-surge", tmp_path / "surge.hcrt")
    for u in (0.05, 0.4321, 5.0):
        expected = cli_json(db_path, "query", "asr-v-surge", f"u={u!r}", "--gradient")
        result = model.evaluate("asr-v-surge", np.array([u]))
        assert result["values"][0] == expected["values"]["X"]
        assert result["gradients"][0, 0] == expected["gradient"]["X"]["u"]


def test_refusals_raise_input_error_with_the_runtime_message(db_path, tmp_path):
    with pytest.raises(hydrocoef.InputError, match="cannot open"):
        hydrocoef.RuntimeModel(tmp_path / "missing.hcrt")
    (tmp_path / "foreign.hcrt").write_bytes(b"not a runtime file at all" * 8)
    with pytest.raises(hydrocoef.InputError) as error:
        hydrocoef.RuntimeModel(str(tmp_path / "foreign.hcrt"))
    assert str(error.value).startswith(str(tmp_path / "foreign.hcrt") + ": runtime file, header, byte 0: not a "
                                       "hydrocoef runtime file"), str(error.value)
    path = tmp_path / "tampered.hcrt"
    export_runtime(db_path, "grid-linear", path)
    data = bytearray(path.read_bytes())
    data[-9] ^= 0x01
    path.write_bytes(bytes(data))
    with pytest.raises(hydrocoef.InputError, match="changed or damaged after it was written"):
        hydrocoef.RuntimeModel(path)
    model = export_runtime(db_path, "grid-linear", tmp_path / "good.hcrt")
    # grid-linear's policy is "error": u = 0.7 is beyond its axis [0, 0.38].
    outside = r"^HC_RUNTIME_E_OUTSIDE: surface 'grid-linear': axis 'u' = 0\.(7|69+\d*) is outside \[0, 0\.38\]"
    with pytest.raises(hydrocoef.InputError, match=outside):
        model.evaluate("grid-linear", [0.7, 0.0])
    with pytest.raises(hydrocoef.InputError, match="x has 3 entries; expected 2"):
        model.evaluate("grid-linear", [0.1, 0.0, 0.0])
    with pytest.raises(hydrocoef.InputError, match="no surface 'nope'"):
        model.evaluate("nope", [0.1, 0.0])
    with pytest.raises(hydrocoef.InputError, match="HC_RUNTIME_E_NO_VEHICLE"):
        model.vehicle_step_rk4([0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0], [0] * 6, None, 0.01)
