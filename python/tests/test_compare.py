"""unfold.compare: the rows of unfold_compare's CSV."""

import csv

import pytest
from conftest import run_cli

import unfold

CONFIGS = {
    "fast": {"simplify": {"target_vertices": 300}, "cascade": {"k_iter": 5}},
    "ceres": {"simplify": {"target_vertices": 300}, "method": "ceres"},
}


def write_configs(tmp_path):
    paths = []
    for name, config in CONFIGS.items():
        path = tmp_path / f"{name}.yaml"
        path.write_text("\n".join(
            f"{k}: {v}" if not isinstance(v, dict) else f"{k}:\n" + "".join(
                f"  {kk}: {vv}\n" for kk, vv in v.items()) for k, v in config.items()) + "\n")
        paths.append(path)
    return paths


@pytest.mark.parametrize("fixed_beta", [None, 2.0])
def test_rows_equal_the_command_lines_csv(tmp_path, demo, demo_file, fixed_beta):
    paths = write_configs(tmp_path)
    args = ["--input", demo_file, "--configs", ",".join(map(str, paths)),
            "--csv", tmp_path / "rows.csv"]
    if fixed_beta:
        args += ["--fixed_beta", fixed_beta]
    run = run_cli("unfold_compare", *args)
    assert run.returncode == 0, run.stderr
    with open(tmp_path / "rows.csv") as f:
        cli_rows = list(csv.DictReader(f))
    for configs in (paths, list(CONFIGS.items())):
        rows = unfold.compare(*demo, configs=configs, fixed_beta=fixed_beta)
        assert [list(row) for row in rows] == [list(row) for row in cli_rows]
        for row, cli_row in zip(rows, cli_rows):
            assert row["config"] == cli_row["config"]
            assert row["iterations"] == int(cli_row["iterations"])
            for key in ("final_energy", "E_rig", "E_str", "E_geo"):
                assert row[key] == pytest.approx(float(cli_row[key]), rel=1e-11), key


def test_unnamed_dicts_and_bad_fixed_beta(demo):
    rows = unfold.compare(*demo, configs=[CONFIGS["fast"]])
    assert rows[0]["config"] == "config1"
    with pytest.raises(unfold.ConfigError, match="fixed_beta must be > 0"):
        unfold.compare(*demo, configs=[CONFIGS["fast"]], fixed_beta=-1)
    with pytest.raises(unfold.ConfigError, match="no configs"):
        unfold.compare(*demo, configs=[])
