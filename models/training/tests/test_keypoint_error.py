"""Reading YOLO-pose labels for the keypoint error: one object, or none (a background image)."""
import pytest

import numpy as np

from krp_training.keypoint_error import UNLEARNED_MEDIAN_M, errors_and_swaps, per_landmark, read_label


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


def test_a_landmark_put_elsewhere_on_every_image_is_unlearned():
    # Landmark 0 of zone 0: 12 observations 0.1 m off; landmark 3 of zone 1: 12 observations 15 m off;
    # landmark 5 of zone 1: 3 observations 15 m off, too few to judge.
    zones = [0] * 12 + [1] * 12 + [1] * 3
    keypoints = [0] * 12 + [3] * 12 + [5] * 3
    errors = [0.1] * 12 + [15.0] * 12 + [15.0] * 3
    rows = per_landmark(zones, keypoints, errors, ["west", "east"])
    by_name = {(r["zone"], r["keypoint"]): r for r in rows}
    assert by_name[("east", 3)]["unlearned"] and by_name[("east", 3)]["observed"] == 12
    assert not by_name[("west", 0)]["unlearned"]
    assert not by_name[("east", 5)]["unlearned"]
    assert by_name[("west", 0)]["median_m"] == pytest.approx(0.1)
    assert rows[-1]["zone"] == "west"  # worst median first


def test_one_imprecise_observation_does_not_make_a_landmark_unlearned():
    errors = [0.2] * 11 + [UNLEARNED_MEDIAN_M * 20]
    rows = per_landmark([0] * 12, [2] * 12, errors, ["only"])
    assert not rows[0]["unlearned"]
    assert rows[0]["mean_m"] > UNLEARNED_MEDIAN_M
