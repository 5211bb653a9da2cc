"""The classifier's accuracy by distance to another zone (zone_border.py)."""
import numpy as np
import pytest

from krp_training import report, zone_border

# Two 10 m squares side by side: west [0, 10] x [0, 10], east [10, 20] x [0, 10].
WEST = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], float)
EAST = WEST + [10, 0]


def test_the_distance_is_to_the_other_zone_not_to_the_own_outline():
    points = np.array([[9.5, 5.0], [1.0, 5.0], [12.0, 1.0]])
    d = zone_border.distance_to_other_zones(points, [0, 0, 1], [WEST, EAST])
    # [1, 5] is 1 m from its own zone's outline but 9 m from the east zone.
    np.testing.assert_allclose(d, [0.5, 9.0, 2.0])


def test_one_zone_has_no_other_zone_to_be_near():
    d = zone_border.distance_to_other_zones([[5.0, 5.0]], [0], [WEST])
    assert np.isinf(d).all()


def test_mismatched_points_and_labels_are_refused():
    with pytest.raises(ValueError, match="2 points but 1 zone labels"):
        zone_border.distance_to_other_zones([[1, 1], [2, 2]], [0], [WEST, EAST])


def test_bands_count_every_image_and_their_accuracy():
    rows = zone_border.accuracy_by_band([False, True, True, True, False], [0.2, 0.9, 1.5, 7.0, np.inf], (1.0, 3.0))
    assert [r["band"] for r in rows] == ["0-1 m", "1-3 m", ">= 3 m"]
    assert [r["images"] for r in rows] == [2, 1, 2]
    assert [r["accuracy"] for r in rows] == [0.5, 1.0, 0.5]


def test_an_empty_band_has_no_accuracy():
    rows = zone_border.accuracy_by_band([True], [5.0], (1.0, 3.0))
    assert rows[0]["images"] == 0 and rows[0]["accuracy"] is None


@pytest.mark.parametrize("bands", [(3.0, 1.0), (0.0, 1.0), (-1.0,)])
def test_band_edges_must_be_positive_and_increasing(bands):
    with pytest.raises(ValueError, match="positive and increasing"):
        zone_border.accuracy_by_band([True], [1.0], bands)


def test_a_split_is_read_from_the_dataset_folder(tmp_path):
    (tmp_path / "zones.yaml").write_text(
        "zones:\n  - name: west\n    polygon: " + str(WEST.tolist()) + "\n  - name: east\n    polygon: " +
        str(EAST.tolist()) + "\n")
    (tmp_path / "samples.csv").write_text("id,split,zone,x_m,y_m\na,test,west,9.8,5\nb,test,east,15,5\n")
    rows = zone_border.split_by_band(tmp_path, ["b", "a"], [1, 0], [True, False])
    assert [(r["images"], r["accuracy"]) for r in rows] == [(1, 0.0), (0, None), (1, 1.0)]


def test_an_image_missing_from_the_samples_is_named(tmp_path):
    (tmp_path / "samples.csv").write_text("id,x_m,y_m\na,1,1\n")
    with pytest.raises(ValueError, match="first: z"):
        zone_border.read_positions(tmp_path, ["a", "z"])


def test_the_report_prints_one_row_per_band_and_a_column_pair_per_split():
    test = zone_border.accuracy_by_band([False, True], [0.5, 4.0])
    lines = report.border_band_table({"test": test, "changed": []})
    assert lines[0].startswith("| distance to another zone | test images | test accuracy |")
    assert "changed" not in lines[0]  # an empty split has no column
    assert lines[2] == "| 0-1 m | 1 | 0.0 % |" and lines[4] == "| >= 3 m | 1 | 100.0 % |"
    assert report.border_band_table({}) == []
