"""krp-recheck-models: fresh data for trained models, refused when it could not recheck them."""
import json
import shutil

import pytest

from krp_training import recheck
from krp_training.recheck_report import write_report

OFFICE_MODELS = recheck.REPO_ROOT / "models" / "office_two_zone"


def _copy_models(tmp_path, edit):
    models = tmp_path / "models"
    shutil.copytree(OFFICE_MODELS, models)
    m = json.loads((models / "manifest.json").read_text())
    edit(m)
    (models / "manifest.json").write_text(json.dumps(m))
    return models


def test_the_training_seed_is_refused(tmp_path, bin_dir):
    with pytest.raises(SystemExit, match="seed the models were trained with"):
        recheck.main(["--models", str(OFFICE_MODELS), "--seed", "1", "--bin-dir", str(bin_dir),
                      "--out", str(tmp_path / "r"), "--work-dir", str(tmp_path / "w")])
    assert not (tmp_path / "r").exists()


def test_models_of_another_version_of_the_map_are_refused(tmp_path, bin_dir):
    models = _copy_models(tmp_path, lambda m: m["map"].update(image_sha256="0" * 64))
    with pytest.raises(SystemExit, match="image_sha256 .* would not recheck these models"):
        recheck.main(["--models", str(models), "--seed", "2", "--bin-dir", str(bin_dir),
                      "--out", str(tmp_path / "r"), "--work-dir", str(tmp_path / "w")])
    assert not (tmp_path / "r").exists()


def test_models_of_a_map_that_is_not_a_sim_world_need_the_map(tmp_path, bin_dir):
    models = _copy_models(tmp_path, lambda m: m.update(world="my_floor"))
    with pytest.raises(SystemExit, match="not a sim world .* pass the map they were trained on with --map"):
        recheck.main(["--models", str(models), "--seed", "2", "--bin-dir", str(bin_dir),
                      "--out", str(tmp_path / "r"), "--work-dir", str(tmp_path / "w")])


def test_the_shipped_office_models_on_a_few_fresh_samples(tmp_path, bin_dir):
    out, work = tmp_path / "report", tmp_path / "work"
    rc = recheck.main(["--models", str(OFFICE_MODELS), "--seed", "7", "--samples-per-zone", "40",
                       "--changed-per-zone", "3", "--bin-dir", str(bin_dir), "--out", str(out),
                       "--work-dir", str(work), "--keep-dataset"])
    assert rc == 0
    result = json.loads((out / "recheck.json").read_text())
    card = json.loads((work / "dataset" / "dataset_card.json").read_text())
    # New samples, the models' split: the fresh test split is in blocks the models held out.
    assert card["seed"] == 7 and card["split"]["seed"] == 1
    assert "--split-seed 1" in result["dataset_command"]
    for split in ("test", "changed", "train"):
        scores = result["fresh"]["classifier"][split]
        assert scores["images"] == sum(card["counts"][split].values()) > 0, split
        assert 0.0 <= scores["accuracy"] <= 1.0
        assert sum(map(sum, scores["confusion"])) == scores["images"]
        assert "right" not in scores  # per-image outcomes are summed into bands, not written out
    for split in ("test", "changed"):
        bands = result["fresh"]["classifier"][split]["by_border_distance"]
        assert sum(b["images"] for b in bands) == result["fresh"]["classifier"][split]["images"]
        kp = result["fresh"]["keypoints"][split]
        assert 0.0 <= kp["pose"]["map50"] <= 1.0
        assert kp["keypoint_error"]["images"] == sum(card["counts"][split].values())
    report = (out / "RECHECK.md").read_text()
    m = json.loads((OFFICE_MODELS / "manifest.json").read_text())
    shipped_test = f"{100 * m['classifier']['metrics']['accuracy']['test']:.1f} %"
    assert f"| test (held-out blocks) | {shipped_test} | {100 * result['fresh']['classifier']['test']['accuracy']:.1f} %" in report


def test_the_report_sets_each_figure_beside_the_shipped_one(tmp_path):
    result = {
        "world": "w", "models": "models/w", "fresh_seed": 3, "split_seed": 1, "command": "krp-recheck-models --models x --seed 3",
        "dataset_command": "krp-dataset ...", "fresh_counts": {"train": {"a": 5}, "test": {"a": 2}, "changed": {"a": 1}},
        "shipped": {"classifier": {"accuracy": {"test": 0.94, "changed": 0.83}},
                    "keypoints": {"test": {"pose": {"map50": 0.817}, "keypoint_error": {"mean_error_m": 2.78}}}},
        "fresh": {
            "classifier": {"test": {"images": 2, "accuracy": 0.5, "confusion": [[1, 1], [0, 0]],
                                    "by_border_distance": [{"band": "0-1 m", "images": 2, "accuracy": 0.5}]},
                           "changed": {"images": 1, "accuracy": 1.0, "confusion": [[1, 0], [0, 0]]},
                           "train": {"images": 5, "accuracy": 0.8, "confusion": [[4, 1], [0, 0]]}},
            "keypoints": {"test": {"pose": {"map50": 0.6},
                                   "keypoint_error": {"mean_error_m": 1.25, "on_another_landmark": 4,
                                                      "mean_error_not_swapped_m": 0.31, "swap_radius_m": 0.5,
                                                      "unlearned_landmarks": ["a #7"],
                                                      "mean_error_learned_landmarks_m": 0.22}},
                          "changed": {"pose": {"map50": 0.4}}}},
    }
    write_report(result, {"zones": ["a", "b"], "lidar": {"name": "omni_12m"}}, tmp_path / "R.md")
    text = (tmp_path / "R.md").read_text()
    assert text.startswith("# `models/w` (w, lidar omni_12m) rechecked on fresh data (seed 3)")
    assert "| test (held-out blocks) | 94.0 % | 50.0 % | 2 | >= 99.0 % |" in text
    assert "| changed environment | 83.0 % | 100.0 % | 1 | >= 95.0 % |" in text
    assert "| pose mAP@50 | 0.817 | 0.600 | - | 0.400 | >= 0.95 |" in text
    assert "| mean error of observed keypoints | 2.780 m | 1.250 m | - | - | <= 0.15 m |" in text
    assert "| of them on another landmark (identity mistakes) | - | 4 | - | - |  |" in text
    assert "| mean error, identity mistakes apart | - | 0.310 m | - | - |  |" in text
    assert "| landmarks not learned (median error over 1 m) | - | a #7 | - | - |  |" in text
    assert "| mean error, the other landmarks | - | 0.220 m | - | - |  |" in text
    assert "swap radius (0.500 m)" in text
    assert "| **a** | 1 | 1 |" in text
    assert "Images: train 5, val 0, test 2, changed 1." in text
    # Accuracy by distance to another zone, for the split that has it.
    assert "| 0-1 m | 2 | 50.0 % |" in text


def test_a_long_list_of_unlearned_landmarks_is_counted_not_spelled_out(tmp_path):
    many = [f"z{i:02d} #{i % 12}" for i in range(30)]
    result = {
        "world": "w", "models": "models/w", "fresh_seed": 3, "split_seed": 1, "command": "c", "dataset_command": "d",
        "fresh_counts": {"test": {"a": 1}},
        "shipped": {"classifier": {"accuracy": {}}, "keypoints": {}},
        "fresh": {"classifier": {s: {"images": 1, "accuracy": 1.0, "confusion": [[1]]} for s in ("test", "changed", "train")},
                  "keypoints": {"test": {"keypoint_error": {"unlearned_landmarks": many}}}},
    }
    write_report(result, {"zones": ["a"], "lidar": {"name": "omni_12m"}}, tmp_path / "R.md")
    text = (tmp_path / "R.md").read_text()
    named = ", ".join(many[:8])
    assert f"| - | 30 landmarks, among them {named} (all in recheck.json) | - | - |  |" in text
    assert many[8] not in text
