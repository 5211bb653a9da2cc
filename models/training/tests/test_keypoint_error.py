"""Reading YOLO-pose labels for the keypoint error: one object, or none (a background image)."""
import pytest

from krp_training.keypoint_error import read_label


def test_a_label_gives_the_zone_and_the_keypoints(tmp_path):
    path = tmp_path / "a.txt"
    path.write_text("1 0.5 0.5 0.2 0.2 0.1 0.2 2 0.3 0.4 0\n")
    zone, kpts = read_label(path, 2)
    assert zone == 1
    assert kpts.shape == (2, 3)
    assert kpts[0].tolist() == [0.1, 0.2, 2.0]


def test_an_empty_label_is_a_background_image(tmp_path):
    path = tmp_path / "b.txt"
    path.write_text("")
    assert read_label(path, 12) is None


def test_a_label_with_the_wrong_keypoint_count_is_refused(tmp_path):
    path = tmp_path / "c.txt"
    path.write_text("1 0.5 0.5 0.2 0.2 0.1 0.2 2\n")
    with pytest.raises(ValueError, match="expected 11"):
        read_label(path, 2)
