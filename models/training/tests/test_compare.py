"""compare's datasets are of the lidar the compared models were trained for."""
import json
import stat

import pytest

from krp_training import compare


def fake_dataset_app(tmp_path, lidar_name):
    """A krp-dataset that records its arguments and writes a card naming `lidar_name`."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    app = bin_dir / "krp-dataset"
    app.write_text("#!/bin/sh\n"
                   f"echo \"$@\" > {tmp_path / 'args.txt'}\n"
                   "while [ \"$1\" != --out ]; do shift; done\n"
                   "mkdir -p \"$2\"\n"
                   f"echo '{{\"lidar\": {{\"name\": \"{lidar_name}\"}}, \"zones\": [\"a\", \"b\"]}}' "
                   "> \"$2/dataset_card.json\"\n")
    app.chmod(app.stat().st_mode | stat.S_IEXEC)
    return bin_dir


def test_the_dataset_is_made_for_the_lidar_asked(tmp_path):
    bin_dir = fake_dataset_app(tmp_path, "lds01")
    compare.make_dataset(bin_dir, "office_two_zone", 1.0, 10, 3, tmp_path / "d", lidar="lds01")
    args = (tmp_path / "args.txt").read_text().split()
    assert args[args.index("--lidar") + 1] == "lds01"
    compare.make_dataset(bin_dir, "office_two_zone", 1.0, 10, 3, tmp_path / "e")
    assert "--lidar" not in (tmp_path / "args.txt").read_text().split()


def models_for(tmp_path, lidar_name):
    folder = tmp_path / "models"
    folder.mkdir()
    (folder / "manifest.json").write_text(json.dumps({"lidar": {"name": lidar_name}}))
    return folder


def test_datasets_of_another_lidar_than_the_models_are_named(tmp_path):
    folder = models_for(tmp_path, "lds01")
    why = compare.lidar_mismatch(folder, {"lidar": {"name": "omni_12m"}})
    assert "trained for lidar 'lds01'" in why and "--lidar lds01" in why
    assert compare.lidar_mismatch(folder, {"lidar": {"name": "lds01"}}) is None
    assert compare.lidar_mismatch(tmp_path / "no_models_yet", {"lidar": {"name": "lds01"}}) is None


def test_compare_refuses_before_training_when_the_lidar_is_not_the_models(tmp_path, capsys):
    folder = models_for(tmp_path, "lds01")
    bin_dir = fake_dataset_app(tmp_path, "omni_12m")
    code = compare.main(["--world", "office_two_zone", "--out", str(folder), "--architectures", "compact",
                         "--bin-dir", str(bin_dir)])
    assert code == 2
    assert "--lidar lds01" in capsys.readouterr().err
    assert sorted(p.name for p in folder.iterdir()) == ["manifest.json"]


def test_a_dataset_that_cannot_be_made_is_a_clear_error_and_writes_nothing(tmp_path, capsys):
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    app = bin_dir / "krp-dataset"
    app.write_text("#!/bin/sh\necho 'krp-dataset: error: no such world' >&2\nexit 2\n")
    app.chmod(app.stat().st_mode | stat.S_IEXEC)
    out = tmp_path / "models"
    code = compare.main(["--world", "nosuchworld", "--out", str(out), "--architectures", "compact",
                         "--bin-dir", str(bin_dir)])
    assert code == 2
    assert "could not make the datasets" in capsys.readouterr().err
    assert not out.exists()


def test_one_side_of_scenario_generation_is_trained_and_the_other_added_later(tmp_path, bin_dir):
    out = tmp_path / "models"
    common = ["--world", "office_two_zone", "--out", str(out), "--architectures", "compact", "--epochs", "1",
              "--samples-per-zone", "40", "--skip-loo", "--bin-dir", str(bin_dir)]
    assert compare.main(common + ["--scenario-generation", "with"]) == 0
    record = json.loads((out / "comparison.json").read_text())
    assert [(r["architecture"], r["strength"]) for r in record["runs"]] == [("compact", 1.0)]
    assert record["ratios"] == {}
    assert compare.main(common + ["--add", "--scenario-generation", "without"]) == 0
    record = json.loads((out / "comparison.json").read_text())
    assert sorted(r["strength"] for r in record["runs"]) == [0.0, 1.0]
    assert list(record["ratios"]) == ["compact"]
    assert record["commands"][1].endswith("--add --scenario-generation without")
