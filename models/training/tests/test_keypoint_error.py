"""Reading YOLO-pose labels for the keypoint error: one object, or none (a background image)."""
import pytest

import numpy as np

from krp_training.keypoint_error import errors_and_swaps, read_label


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


def test_a_keypoint_put_on_another_landmark_is_an_identity_mistake():
    # Three landmarks in a 100 px image at 0.1 m per pixel: 0 and 1 observed, 2 inside but unseen.
    truth = np.array([[0.10, 0.10, 2], [0.50, 0.10, 2], [0.90, 0.90, 1]])
    pred = np.array([[90.0, 88.0],   # keypoint 0 on landmark 2 (2.2 px = 0.22 m away): a swap
                     [52.0, 10.0]])  # keypoint 1 2 px (0.2 m) from its own landmark
    pred = np.vstack([pred, [[0.0, 0.0]]])  # keypoint 2 is not observed: not measured
    errors, swapped = errors_and_swaps(pred, truth, imgsz=100, resolution_m=0.1)
    assert errors.shape == (2,)
    assert errors[0] == pytest.approx(np.hypot(80, 78) * 0.1)
    assert errors[1] == pytest.approx(0.2)
    assert swapped.tolist() == [True, False]


def test_a_far_keypoint_near_no_landmark_is_not_a_swap():
    truth = np.array([[0.10, 0.10, 2], [0.50, 0.10, 2]])
    pred = np.array([[10.0, 60.0], [50.0, 10.0]])  # keypoint 0 5 m off, on nothing
    errors, swapped = errors_and_swaps(pred, truth, imgsz=100, resolution_m=0.1)
    assert errors[0] == pytest.approx(5.0)
    assert swapped.tolist() == [False, False]
