"""The surface and export commands from Python (Database.surface_show,
surface_list, surface_build, surface_rebuild, query_surface, export_surface,
export_gazebo; Surface.table, tabulate, largest_standard_deviations): each
gives what the CLI prints, byte for byte, on the same database, and the same
numbers; bad options raise InputError with the CLI's message."""

import json
import shutil

import numpy as np
import pytest

import hydrocoef
from conftest import ASR_V, cli_error, cli_json, run_cli


@pytest.fixture(scope="module")
def gp_db(tmp_path_factory):
    """The ASR-V tables with a GP surface of X(u), a PCHIP one of N(r) and two fits, made by the CLI."""
    path = tmp_path_factory.mktemp("surfaces") / "surfaces.db"
    with hydrocoef.Database(path, mode="create") as db:
        for table, sign in (("asr-v-surge-damping.csv", "opposing"), ("asr-v-yaw-damping.csv", "on-body")):
            db.import_files(ASR_V / table, body="asr-v", settings={"sign": sign, "rho": 998.2, "nu": 1.004e-6})
        db.fit(body="asr-v", output="X", terms="u,u|u|")
        db.fit(body="asr-v", output="N", terms="r,r|r|")
    run_cli(path, "surface", "build", "gp", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method", "gp",
            "--starts", "2", "--extrapolate", "clamp")
    run_cli(path, "surface", "build", "yaw", "--body", "asr-v", "--outputs", "N", "--axes", "r", "--method", "pchip",
            "--extrapolate", "linear")
    return path


def test_show_list_and_query_print_what_the_cli_prints(gp_db):
    with hydrocoef.Database(gp_db, mode="r") as db:
        for name in ("gp", "yaw"):
            report = db.surface_show(name)
            assert report.text() == run_cli(gp_db, "surface", "show", name)[1]
            assert report.json() == run_cli(gp_db, "surface", "show", name, "--json")[1]
        listed = db.surface_list()
        assert listed.text() == run_cli(gp_db, "surface", "list")[1]
        assert listed.json() == run_cli(gp_db, "surface", "list", "--json")[1]
        assert [s.name for s in listed.surfaces] == ["gp", "yaw"]

        answer = db.query_surface("gp", {"u": 0.21}, uncertainty=True, gradient=True)
        printed = run_cli(gp_db, "query", "gp", "u=0.21", "--uncertainty", "--gradient", "--json")[1]
        assert answer.json() == printed
        assert answer.text() == run_cli(gp_db, "query", "gp", "u=0.21", "--uncertainty", "--gradient")[1]
        expected = json.loads(printed)
        assert answer.values == [expected["values"]["X"]]
        assert answer.standard_deviation == [expected["standard_deviation"]["X"]]
        assert answer.gradient == [expected["gradient"]["X"]["u"]]
        assert answer.standard_deviation[0] > 0

        # The GP's largest standard deviations are show's.
        shown = cli_json(gp_db, "surface", "show", "gp")
        peaks = db.surface("gp").largest_standard_deviations()
        assert [p["sd"] for p in peaks["X"]] == [p["sd"] for p in shown["gp"]["outputs"]["X"]["largest_sd"]]
        assert [p["point"]["u"] for p in peaks["X"]] == \
               [p["point"]["u"] for p in shown["gp"]["outputs"]["X"]["largest_sd"]]
        assert db.surface_show("gp").outputs[0].largest_sd[0][1] == peaks["X"][0]["sd"]


def test_tables_of_a_grid_and_of_a_gp_are_the_cli_numbers(gp_db):
    with hydrocoef.Database(gp_db, mode="r") as db:
        yaw = db.surface("yaw")
        assert yaw.gridded
        table = yaw.table()
        shown = cli_json(gp_db, "surface", "show", "yaw")
        assert table["r"].tolist() == shown["axes"][0]["breakpoint_values"]
        runs = db.runs(body="asr-v", where="u=0")
        order = np.argsort(runs["r"])
        np.testing.assert_array_equal(table["N"], runs["N"][order])  # a table through the runs

        gp = db.surface("gp")
        assert not gp.gridded
        with pytest.raises(hydrocoef.InputError, match="is not gridded"):
            gp.table()
        u = np.linspace(0.0, 0.4, 5)
        tabulated = gp.tabulate(u=u)
        assert tabulated["X"].shape == (5,)
        for i, x in enumerate(u):
            at = cli_json(gp_db, "query", "gp", f"u={x!r}", "--uncertainty")
            assert tabulated["X"][i] == at["values"]["X"]
            assert tabulated["sigma_X"][i] == at["standard_deviation"]["X"]
        with pytest.raises(hydrocoef.InputError, match="strictly increasing"):
            gp.tabulate(u=[0.2, 0.1])


def test_build_and_rebuild_report_what_the_cli_prints(gp_db, tmp_path):
    path = tmp_path / "copy.db"
    shutil.copy(gp_db, path)
    with hydrocoef.Database(path) as db:
        built = db.surface_build("api-gp", body="asr-v", axes="u", outputs="X", method="gp", gp_starts=2,
                                 extrapolate="clamp")
        mine = json.loads(built.json())
        theirs = cli_json(path, "surface", "show", "gp")
        for key in ("gp", "quality", "build_spec", "runs", "axes"):
            assert mine[key] == theirs[key], key
        assert built.surface.name == "api-gp"
        rebuilt = db.surface_rebuild("api-gp")
        assert [r.surface.name for r in rebuilt.rebuilt] == ["api-gp"]
        assert db.surface_rebuild(stale_only=True).text() == "no surface to rebuild\n"
        with pytest.raises(hydrocoef.InputError) as refused:
            db.surface_build("x", body="asr-v", axes="u", outputs="X", method="gp", gp_starts=0)
        assert str(refused.value) == cli_error(path, "surface", "build", "x", "--body", "asr-v", "--outputs", "X",
                                               "--axes", "u", "--method", "gp", "--starts", "0")


def test_exports_write_the_cli_files(gp_db, tmp_path):
    (tmp_path / "cli").mkdir()
    (tmp_path / "api").mkdir()
    with hydrocoef.Database(gp_db, mode="r") as db:
        for fmt in ("csv", "c", "json"):
            run_cli(gp_db, "export", "yaw", "--format", fmt, "-o", str(tmp_path / "cli" / f"yaw.{fmt}"))
            result = db.export_surface("yaw", format=fmt, output=tmp_path / "api" / f"yaw.{fmt}")
            assert (tmp_path / "api" / f"yaw.{fmt}").read_bytes() == (tmp_path / "cli" / f"yaw.{fmt}").read_bytes()
            printed = cli_json(gp_db, "export", "yaw", "--format", fmt, "-o", str(tmp_path / "api" / f"yaw.{fmt}"))
            assert json.loads(result.json()) == printed
        with pytest.raises(hydrocoef.InputError) as refused:
            db.export_surface("yaw", format="csv", output=tmp_path / "t.csv", single_precision=True)
        assert str(refused.value) == cli_error(gp_db, "export", "yaw", "--format", "csv", "-o", "t.csv", "--float")

        sdf = tmp_path / "api" / "model.sdf"
        result = db.export_gazebo("asr-v", flavor="uuv", output=sdf, allow_missing=True,
                                  added_mass=[1, 2, 3, 4, 5, 6])
        printed = cli_json(gp_db, "export-gazebo", "asr-v", "--flavor", "uuv", "-o", str(tmp_path / "cli.sdf"),
                           "--allow-missing", "--added-mass", "1,2,3,4,5,6")
        assert sdf.read_bytes() == (tmp_path / "cli.sdf").read_bytes()
        mine = json.loads(result.json())
        del mine["file"], printed["file"]
        assert mine == printed
        assert [f.dof for f in result.fits] == ["X", "N"]
        assert result.fits[0].quadratic < 0  # on the body
        assert result.added_mass_b[0] == 1.0 and result.added_mass_b[35] == 6.0
