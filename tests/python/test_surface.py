"""Surface calls: values against the C++ point evaluation (`hydrocoef query`)
and the table's own numbers; shapes, dtypes, strides, threads."""

import sqlite3

import numpy as np
import pytest

import hydrocoef
from conftest import GRID_U, GRID_V, cli_json, grid_function


def test_a_surface_knows_its_axes_outputs_and_units(db):
    s = db.surface("grid-linear")
    assert s.name == "grid-linear" and s.body == "grid" and s.method == "linear" and not s.stale
    assert s.axes == ["u", "v"] and s.outputs == ["X", "Y"]
    assert s.axis_units == ["m/s", "m/s"] and s.output_units == ["N", "N"]
    assert s.bounds == {"u": (0.0, GRID_U[-1]), "v": (GRID_V[0], GRID_V[-1])}
    assert s.out_of_range == {"u": "error", "v": "error"}
    assert "grid-linear" in repr(s)
    infos = {info.name: info for info in db.surfaces()}
    assert infos["grid-pchip"].axes == ["u", "v"] and infos["grid-pchip"].run_count == 400
    assert [info.name for info in db.surfaces(body="asr-v")] == ["asr-v-surge", "asr-v-yaw"]


def test_at_the_nodes_a_surface_gives_the_table(db):
    uu, vv = np.meshgrid(GRID_U, GRID_V, indexing="ij")
    x, y = grid_function(uu, vv)
    for name in ("grid-linear", "grid-pchip"):
        out = db.surface(name)(u=uu, v=vv)
        assert out["X"].shape == uu.shape
        np.testing.assert_allclose(out["X"], x, rtol=0, atol=1e-12)
        np.testing.assert_allclose(out["Y"], y, rtol=0, atol=1e-12)


@pytest.mark.parametrize("name", ["grid-linear", "grid-pchip"])
def test_values_and_gradients_are_the_cli_querys(db, db_path, name):
    s = db.surface(name)
    for u, v in [(0.234, -0.0567), (0.01, 0.19), (0.37, 0.0)]:
        expected = cli_json(db_path, "query", name, f"u={u!r}", f"v={v!r}", "--gradient")
        scalar = s(u=u, v=v, gradient=True)
        array = s(u=np.array([u, 0.1]), v=np.array([v, 0.1]), gradient=True)
        for output in ("X", "Y"):
            assert scalar[output] == expected["values"][output]
            assert isinstance(scalar[output], np.float64)
            assert array[output][0] == expected["values"][output]
            for axis in ("u", "v"):
                assert scalar[f"d{output}/d{axis}"] == expected["gradient"][output][axis]
                assert array[f"d{output}/d{axis}"][0] == expected["gradient"][output][axis]


def test_linear_is_bilinear_between_nodes(db):
    s = db.surface("grid-linear")
    u0, u1, v0, v1 = GRID_U[3], GRID_U[4], GRID_V[7], GRID_V[8]
    tu, tv = 0.3, 0.8
    corners = [grid_function(a, b)[0] for a, b in [(u0, v0), (u1, v0), (u0, v1), (u1, v1)]]
    expected = ((1 - tu) * (1 - tv) * corners[0] + tu * (1 - tv) * corners[1] + (1 - tu) * tv * corners[2]
                + tu * tv * corners[3])
    assert s(u=u0 + tu * (u1 - u0), v=v0 + tv * (v1 - v0))["X"] == pytest.approx(expected, abs=1e-13)


def reference(s, u, v):
    """Point by point, through the scalar path (the C++ point evaluation)."""
    return np.array([[s(u=a, v=b)[k] for k in s.outputs] for a, b in zip(np.ravel(u), np.ravel(v))])


def test_views_dtypes_and_layouts_give_the_same_numbers(db):
    s = db.surface("grid-pchip")
    rng = np.random.default_rng(1)
    base = np.column_stack([rng.uniform(0, 0.38, 64), rng.uniform(-0.2, 0.2, 64)])  # C order: columns are strided
    expected = reference(s, base[:, 0], base[:, 1])
    cases = {
        "strided columns": (base[:, 0], base[:, 1]),
        "every other, reversed": (base[::-2, 0], base[::-2, 1]),
        "fortran 2-D": (np.asfortranarray(base[:, 0].reshape(8, 8)), np.asfortranarray(base[:, 1].reshape(8, 8))),
        "2-D non-contiguous": (np.repeat(base[:, :1], 2, axis=1)[::2, :], np.repeat(base[:, 1:], 2, axis=1)[::2, :]),
        "lists": (list(base[:, 0]), list(base[:, 1])),
        "big-endian": (base[:, 0].astype(">f8"), base[:, 1].astype(">f8")),
        "read-only": (np.frombuffer(base[:, 0].tobytes()), np.frombuffer(base[:, 1].tobytes())),
    }
    for label, (u, v) in cases.items():
        out = s(u=u, v=v)
        assert out["X"].shape == np.shape(u), label
        np.testing.assert_array_equal(np.stack([out["X"].ravel(), out["Y"].ravel()], axis=1),
                                      reference(s, u, v), err_msg=label)
    np.testing.assert_array_equal(s(u=base[:, 0].copy(), v=base[:, 1].copy())["X"], expected[:, 0])
    # Other dtypes are converted: float32 values are those float32 numbers.
    u32, v32 = base[:, 0].astype(np.float32), base[:, 1].astype(np.float32)
    np.testing.assert_array_equal(s(u=u32, v=v32)["X"], reference(s, u32.astype(float), v32.astype(float))[:, 0])
    ints = s(u=np.zeros(3, dtype=np.int64), v=np.zeros(3, dtype=np.int32))["X"]
    np.testing.assert_array_equal(ints, np.full(3, s(u=0.0, v=0.0)["X"]))
    # A misaligned float64 view is copied, not read across its alignment.
    raw = np.zeros(8 * 64 + 1, dtype=np.uint8)
    misaligned = raw[1:].view(np.float64)
    misaligned[:] = base[:, 0]
    np.testing.assert_array_equal(s(u=misaligned, v=base[:, 1])["X"], expected[:, 0])


def test_scalars_stand_for_every_point_and_a_mapping_may_hold_the_axes(db):
    s = db.surface("grid-linear")
    u = np.linspace(0, 0.38, 11)
    out = s(u=u, v=0.05)
    np.testing.assert_array_equal(out["X"], [s(u=a, v=0.05)["X"] for a in u])
    table = {"u": u, "v": np.full(11, 0.05), "comment": "ignored: not an axis"}
    np.testing.assert_array_equal(s(table)["Y"], out["Y"])
    assert s(u=np.zeros((0, 3)), v=0.0)["X"].shape == (0, 3)


def test_outputs_are_new_arrays(db):
    s = db.surface("grid-linear")
    u = np.full(5, 0.1)
    out = s(u=u, v=u)
    out["X"][:] = 7.0
    assert s(u=u, v=u)["X"][0] != 7.0
    assert not np.shares_memory(out["X"], u)


def test_threads_do_not_change_the_numbers(db):
    s = db.surface("grid-pchip")
    rng = np.random.default_rng(2)
    u, v = rng.uniform(0, 0.38, 200_000), rng.uniform(-0.2, 0.2, 200_000)
    one = s(u=u, v=v, threads=1, gradient=True)
    for threads in (2, 3, 0):
        many = s(u=u, v=v, threads=threads, gradient=True)
        for key in one:
            np.testing.assert_array_equal(one[key], many[key], err_msg=f"{key}, {threads} threads")


def test_one_axis_surface_extrapolates_as_built(db):
    s = db.surface("asr-v-yaw")
    assert s.axes == ["r"] and s.outputs == ["N"] and s.out_of_range == {"r": "linear"}
    r = np.array([0.0, 0.15, 0.5])
    assert np.all(np.isfinite(s(r=r)["N"]))
    assert s(r=0.0)["N"] == -0.00006  # the run at rest, a node


def test_float64_columns_are_read_in_place(db):
    """numpy reports its allocations to tracemalloc: the call allocates its
    outputs and nothing for float64 inputs, contiguous or strided; other dtypes
    are converted into new arrays."""
    import tracemalloc
    s = db.surface("grid-linear")
    n = 500_000
    uv = np.column_stack([np.full(n, 0.1), np.full(n, 0.05)])  # each column has a stride of 2 doubles
    outputs = 2 * 8 * n

    def peak(u, v):
        tracemalloc.start()
        try:
            s(u=u, v=v)
            return tracemalloc.get_traced_memory()[1]
        finally:
            tracemalloc.stop()

    assert peak(uv[:, 0], uv[:, 1]) < outputs + 100_000
    assert peak(np.ascontiguousarray(uv[:, 0]), 0.05) < outputs + 100_000
    assert peak(uv[:, 0].astype(np.float32), uv[:, 1]) > outputs + 8 * n * 0.9


def test_a_gp_surface_states_its_standard_deviation_as_the_cli_does(tmp_path):
    rng = np.random.default_rng(3)
    u, v = rng.uniform(0.0, 0.5, 25), rng.uniform(-0.2, 0.2, 25)
    rows = "".join(f"{a!r},{b!r},{-20 * a * abs(a) + 3 * b * b!r}\n" for a, b in zip(u, v))
    (tmp_path / "scattered.csv").write_text("u [m s^-1],v [m s^-1],X [N]\n" + rows)
    path = tmp_path / "gp.db"
    with hydrocoef.Database(path) as db:
        db.import_files([tmp_path / "scattered.csv"], body="blob")
        info = db.build_surface("gp", body="blob", axes=["u", "v"], outputs=["X"], method="gp", gp_starts=2)
        assert info.method == "gp"
        s = db.surface("gp")
        (u_low, _), (_, v_high) = s.bounds["u"], s.bounds["v"]
        uq, vq = np.array([u_low, 0.3, u[4]]), np.array([v_high, -0.15, v[4]])
        out = s(u=uq, v=vq, uncertainty=True)
        assert list(out) == ["X", "sigma_X"]
        # At a run (noise-free) only the jitter on the diagonal is left, 1e-10 sigma^2 (gp_surface.hpp);
        # in a corner of the range, away from the runs, the surface is less sure.
        signal_sd = cli_json(path, "surface", "show", "gp")["gp"]["outputs"]["X"]["signal_sd"]
        assert out["sigma_X"][2] <= 1e-5 * signal_sd * (1 + 1e-6)
        assert out["sigma_X"][0] > 3 * out["sigma_X"][2]
        strided = s(u=np.repeat(uq, 2)[::2], v=vq, uncertainty=True, threads=2)
        np.testing.assert_array_equal(strided["sigma_X"], out["sigma_X"])
        for k in range(2):
            expected = cli_json(path, "query", "gp", f"u={uq[k]!r}", f"v={vq[k]!r}", "--uncertainty")
            scalar = s(u=float(uq[k]), v=float(vq[k]), uncertainty=True)
            assert scalar["X"] == expected["values"]["X"] == out["X"][k]
            assert scalar["sigma_X"] == expected["standard_deviation"]["X"] == out["sigma_X"][k]
        db.build_surface("rbf", body="blob", axes=["u", "v"], outputs=["X"], method="rbf")
        # An RBF surface states one too: the runs' (none here) interpolated and its leave-one-out RMS.
        rbf = db.surface("rbf")(u=uq, v=vq, uncertainty=True)
        loo = cli_json(path, "surface", "show", "rbf")["quality"]["outputs"]["X"]["loo_rms"]
        np.testing.assert_allclose(rbf["sigma_X"], loo, rtol=1e-12)
        for k in range(2):
            expected = cli_json(path, "query", "rbf", f"u={uq[k]!r}", f"v={vq[k]!r}", "--uncertainty")
            assert rbf["sigma_X"][k] == expected["standard_deviation"]["X"]
        # Stored as an older hydrocoef stored it (no uncertainty), it states none.
        raw = sqlite3.connect(path)
        with raw:
            raw.execute("UPDATE surface SET definition = json_remove(definition, '$.uncertainty') WHERE name = 'rbf'")
        raw.close()
        with pytest.raises(hydrocoef.InputError, match="states no standard deviation"):
            db.surface("rbf")(u=uq, v=vq, uncertainty=True)
        with pytest.raises(hydrocoef.InputError, match="expected a GP surface"):
            db.surface("rbf")(u=0.1, v=0.0, uncertainty=True)
