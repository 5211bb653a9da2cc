"""The keypoint loss's OKS sigma goes into the yaml training reads, never into the dataset's own."""
import math

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
