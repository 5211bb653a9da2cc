"""The keypoint loss's OKS sigma goes into the yaml training reads, never into the dataset's own."""
import math
from types import SimpleNamespace

import pytest
import yaml

from krp_training.train_keypoints import with_loss_sigma


def _data_yaml(tmp_path):
    data = tmp_path / "data.yaml"
    data.write_text(yaml.safe_dump({"path": str(tmp_path), "train": "images/train", "val": "images/val",
                                    "kpt_shape": [4, 3], "names": {0: "a"}}))
    return data


def test_a_sigma_gives_every_keypoint_that_sigma_in_a_copy(tmp_path):
    data = _data_yaml(tmp_path)
    before = data.read_text()
    (tmp_path / "work").mkdir()
    out = with_loss_sigma(data, tmp_path / "work", 0.25)
    assert out != data
    doc = yaml.safe_load(out.read_text())
    assert doc["kpt_oks_sigmas"] == [0.25] * 4
    assert doc["train"] == "images/train" and doc["kpt_shape"] == [4, 3]
    assert data.read_text() == before  # evaluation reads this one: its mAP keeps ultralytics' sigma


def test_zero_keeps_ultralytics_default(tmp_path):
    data = _data_yaml(tmp_path)
    assert with_loss_sigma(data, tmp_path, 0.0) == data


@pytest.mark.parametrize("bad", [-0.1, math.nan])
def test_a_negative_or_nan_sigma_is_refused(tmp_path, bad):
    with pytest.raises(ValueError, match="sigma"):
        with_loss_sigma(_data_yaml(tmp_path), tmp_path, bad)


def _run(sigma, unlearned):
    split = {"box": {"map50": 0.9}, "pose": {"map50": 0.8, "map50_95": 0.6},
             "keypoint_error": {"mean_error_m": 2.5, "median_error_m": 0.4, "right_zone": 90, "images": 100,
                                "unlearned_landmarks": unlearned}}
    return {"oks_sigma": sigma, "seconds": 12.0, "test": split, "changed": split}


def test_the_comparison_names_each_sigma_and_the_landmarks_it_left_unlearned():
    from krp_training.compare_loss_sigma import markdown

    text = markdown({"world": "w", "command": "python -m krp_training.compare_loss_sigma --world w",
                     "dataset_command": "krp-dataset --world w", "train_images": 600, "epochs": 40, "seed": 1,
                     "runs": [_run(0.0, ["a #7", "b #1"]), _run(0.25, [])]})
    assert "| ultralytics' 1/K | test | 0.900 | 0.800 | 0.600 | 2.500 m | 0.400 m | 90 of 100 | 2: a #7, b #1 | 12 |" in text
    assert "| 0.25 | changed |" in text and "| 0: none |" in text


@pytest.mark.parametrize("sigmas", ["0,-1", "0,x"])
def test_the_comparison_refuses_bad_sigmas(sigmas, capsys):
    from krp_training.compare_loss_sigma import parse_args

    with pytest.raises(SystemExit):
        parse_args(["--world", "w", "--out", "o", "--sigmas", sigmas])
    assert "--sigmas" in capsys.readouterr().err


def _trainer_at(epoch):
    model = SimpleNamespace(kpt_oks_sigmas=[0.25] * 3, criterion="built with 0.25")
    return SimpleNamespace(epoch=epoch, model=model)


def test_the_fine_sigma_takes_over_when_the_fine_epochs_begin():
    from krp_training.train_keypoints import KeypointParams, _sharpen_sigma

    switch = _sharpen_sigma(KeypointParams(epochs=10, oks_sigma=0.25, fine_oks_sigma=0.05, fine_epochs=3), nkpt=3)
    before, first_fine = _trainer_at(6), _trainer_at(7)
    switch(before)
    switch(first_fine)
    assert before.model.kpt_oks_sigmas == [0.25] * 3 and before.model.criterion == "built with 0.25"
    assert first_fine.model.kpt_oks_sigmas == [0.05] * 3
    assert first_fine.model.criterion is None  # rebuilt from the new sigmas on the next batch


def test_ultralytics_builds_its_keypoint_loss_from_the_models_sigmas(tmp_path):
    """What the switch relies on: a pose model's criterion, rebuilt, takes `kpt_oks_sigmas`."""
    from krp_training import offline

    offline.configure(tmp_path / "ultralytics-config")
    from ultralytics.nn.tasks import PoseModel

    model = PoseModel("yolov8n-pose.yaml", nc=1, data_kpt_shape=(3, 3), verbose=False)
    model.args = SimpleNamespace(box=7.5, cls=0.5, dfl=1.5, pose=12.0, kobj=1.0)
    model.kpt_oks_sigmas = [0.05] * 3
    criterion = model.init_criterion()
    assert criterion.keypoint_loss.sigmas.tolist() == pytest.approx([0.05] * 3)


@pytest.mark.parametrize("params", [dict(epochs=10, fine_epochs=11), dict(epochs=10, fine_epochs=-1),
                                    dict(fine_oks_sigma=-0.1), dict(oks_sigma=float("nan"))])
def test_a_schedule_that_cannot_run_is_refused_before_training(params):
    from krp_training.train_keypoints import KeypointParams, validate_sigma_schedule

    with pytest.raises(ValueError, match="fine_epochs|sigma"):
        validate_sigma_schedule(KeypointParams(**params))


@pytest.mark.parametrize("text, schedule", [("0.25", (0.25, 0.0, 0)), ("0.25:0.0833:10", (0.25, 0.0833, 10))])
def test_a_run_is_one_sigma_or_a_coarse_then_fine_schedule(text, schedule):
    from krp_training.compare_loss_sigma import parse_schedule

    s = parse_schedule(text)
    assert (s["oks_sigma"], s["fine_oks_sigma"], s["fine_epochs"]) == schedule


@pytest.mark.parametrize("sigmas", ["0.25:0.1", "0.25:0.1:0", "0.25:0.1:50"])
def test_the_comparison_refuses_a_schedule_it_cannot_run(sigmas, capsys):
    from krp_training.compare_loss_sigma import parse_args

    with pytest.raises(SystemExit):
        parse_args(["--world", "w", "--out", "o", "--epochs", "40", "--sigmas", sigmas])
    assert "--sigmas" in capsys.readouterr().err


@pytest.mark.parametrize("epochs, fine", [("40", 10), ("8", 2), ("3", 0)])
def test_krp_train_map_sharpens_the_last_quarter_of_the_epochs_unless_told(epochs, fine):
    from krp_training.train_keypoints import KeypointParams
    from krp_training.train_map import parse_args

    args = parse_args(["--world", "w", "--out", "o", "--keypoint-epochs", epochs])
    assert args.keypoint_fine_epochs == fine
    assert args.keypoint_fine_sigma == KeypointParams.fine_oks_sigma == 0.0  # ultralytics' 1/K
    assert parse_args(["--world", "w", "--out", "o", "--keypoint-fine-epochs", "0"]).keypoint_fine_epochs == 0


def test_the_params_default_schedule_is_the_commands_default():
    from krp_training.train_keypoints import KeypointParams, default_fine_epochs

    assert KeypointParams().fine_epochs == default_fine_epochs(KeypointParams().epochs) == 10
