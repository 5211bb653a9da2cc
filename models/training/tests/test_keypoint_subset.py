"""The keypoint model's training-image cap: a seeded subset listed for ultralytics, or the yaml as is."""
from pathlib import Path

import yaml

from krp_training.train_keypoints import limit_training_images


def _dataset(root: Path, n: int) -> Path:
    (root / "images" / "train").mkdir(parents=True)
    for i in range(n):
        (root / "images" / "train" / f"z00_{i:05d}.png").write_bytes(b"")
    data = root / "data.yaml"
    data.write_text(yaml.safe_dump({"path": str(root), "train": "images/train", "val": "images/val",
                                    "kpt_shape": [3, 3], "names": {0: "a"}}))
    return data


def test_a_split_within_the_cap_is_used_as_it_is(tmp_path):
    data = _dataset(tmp_path / "kp", 5)
    assert limit_training_images(data, tmp_path, 5, seed=1) == (data, 5)
    assert limit_training_images(data, tmp_path, 0, seed=1) == (data, 5)


def test_a_larger_split_is_cut_to_a_seeded_subset_and_the_rest_of_the_yaml_kept(tmp_path):
    data = _dataset(tmp_path / "kp", 20)
    limited, count = limit_training_images(data, tmp_path, 7, seed=3)
    assert count == 7
    doc = yaml.safe_load(limited.read_text())
    listed = Path(doc["train"]).read_text().split()
    assert len(listed) == 7 and len(set(listed)) == 7
    assert all(Path(p).is_file() and "/images/train/" in p for p in listed)
    assert doc["val"] == "images/val" and doc["kpt_shape"] == [3, 3]
    (tmp_path / "again").mkdir()
    again = yaml.safe_load(limit_training_images(data, tmp_path / "again", 7, seed=3)[0].read_text())
    assert Path(again["train"]).read_text().split() == listed
    other = yaml.safe_load(limit_training_images(data, tmp_path, 7, seed=4)[0].read_text())
    assert Path(other["train"]).read_text().split() != listed
