"""The training report's figures draw what was measured, and only that."""
import csv

import pytest

from krp_training import plots

COLUMNS = ["epoch", "train/box_loss", "train/pose_loss", "val/box_loss", "val/pose_loss", "metrics/mAP50(B)",
           "metrics/mAP50(P)", "metrics/mAP50-95(P)"]


def _results_csv(path, validated_epochs, epochs=5):
    # ultralytics pads its column names with spaces; the reader strips them.
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow([f"{c:>20}" for c in COLUMNS])
        for e in range(1, epochs + 1):
            measured = e in validated_epochs
            w.writerow([e, 1.0 / e, 2.0 / e] + ([0.5, 0.4, 0.9, 0.8, 0.7] if measured else [0, 0, 0, 0, 0]))
    return path


def _drawn_figure(monkeypatch):
    drawn = {}
    monkeypatch.setattr(plots.plt, "close", lambda fig: drawn.setdefault("fig", fig))
    return drawn


def _line(ax, label):
    return next(line for line in ax.lines if line.get_label() == label)


def test_an_epoch_that_was_not_validated_draws_no_val_point(tmp_path, monkeypatch):
    drawn = _drawn_figure(monkeypatch)
    plots.keypoint_curves(_results_csv(tmp_path / "results.csv", {5}), "t", tmp_path / "k.png")
    assert (tmp_path / "k.png").stat().st_size > 0
    ax_loss, ax_map = drawn["fig"].axes
    assert list(_line(ax_loss, "train/pose_loss").get_xdata()) == [1, 2, 3, 4, 5]
    assert list(_line(ax_loss, "val/pose_loss").get_xdata()) == [5]  # not zeros at epochs 1 to 4
    assert list(_line(ax_map, "val mAP50(P)").get_ydata()) == [pytest.approx(0.8)]
    assert ax_map.get_title() == "validated at 1 of 5 epochs"


def test_every_epoch_validated_draws_every_val_point(tmp_path, monkeypatch):
    drawn = _drawn_figure(monkeypatch)
    plots.keypoint_curves(_results_csv(tmp_path / "results.csv", {1, 2, 3, 4, 5}), "t", tmp_path / "k.png")
    ax_loss, ax_map = drawn["fig"].axes
    assert list(_line(ax_loss, "val/box_loss").get_xdata()) == [1, 2, 3, 4, 5]
    assert ax_map.get_title() == ""


def test_rows_without_val_columns_are_all_kept():
    rows = [{"epoch": "1", "train/box_loss": "1.0"}]
    assert plots.validated_rows(rows) == rows
