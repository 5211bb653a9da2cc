"""PNG figures for the training report: learning curves and confusion matrices."""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # headless: training runs on servers and in CI
import matplotlib.pyplot as plt  # noqa: E402


def classifier_curves(history: list, title: str, path: Path) -> None:
    epochs = [h["epoch"] for h in history]
    fig, (ax_loss, ax_acc) = plt.subplots(1, 2, figsize=(9, 3.5))
    ax_loss.plot(epochs, [h["train_loss"] for h in history], label="train")
    ax_loss.plot(epochs, [h["val_loss"] for h in history], label="val")
    ax_loss.set_xlabel("epoch")
    ax_loss.set_ylabel("cross-entropy")
    ax_loss.legend()
    ax_acc.plot(epochs, [h["train_acc"] for h in history], label="train (augmented)")
    ax_acc.plot(epochs, [h["val_acc"] for h in history], label="val")
    ax_acc.set_xlabel("epoch")
    ax_acc.set_ylabel("accuracy")
    ax_acc.set_ylim(0, 1.02)
    ax_acc.legend()
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


VAL_LOSS_KEYS = ("val/box_loss", "val/pose_loss")


def validated_rows(rows: list) -> list:
    """The rows of epochs that were validated. Without validation each epoch (krp-train-map's
    default: KeypointParams.validate_each_epoch), ultralytics writes zeros into an epoch's val
    columns; a measured loss is never exactly 0, so a row with every val loss 0 was not measured."""
    keys = [k for k in VAL_LOSS_KEYS if k in (rows[0] if rows else {})]
    if not keys:
        return rows
    return [r for r in rows if any(float(r[k]) != 0.0 for k in keys)]


def keypoint_curves(results_csv: Path, title: str, path: Path) -> None:
    """ultralytics' results.csv: losses per epoch, and the val losses and pose mAP at the epochs
    that were validated (drawn as points, so a lone final validation shows as one)."""
    import csv

    rows = list(csv.DictReader(open(results_csv)))
    if not rows:
        return
    rows = [{k.strip(): v for k, v in r.items()} for r in rows]
    epochs = [int(float(r["epoch"])) for r in rows]
    measured = validated_rows(rows)
    measured_epochs = [int(float(r["epoch"])) for r in measured]
    fig, (ax_loss, ax_map) = plt.subplots(1, 2, figsize=(9, 3.5))
    for key in ("train/box_loss", "train/pose_loss"):
        if key in rows[0]:
            ax_loss.plot(epochs, [float(r[key]) for r in rows], label=key)
    for key in VAL_LOSS_KEYS:
        if key in rows[0]:
            ax_loss.plot(measured_epochs, [float(r[key]) for r in measured], marker="o", label=key)
    ax_loss.set_xlabel("epoch")
    ax_loss.set_ylabel("loss")
    ax_loss.legend(fontsize=7)
    for key in ("metrics/mAP50(P)", "metrics/mAP50-95(P)", "metrics/mAP50(B)"):
        if key in rows[0]:
            ax_map.plot(measured_epochs, [float(r[key]) for r in measured], marker="o",
                        label=key.replace("metrics/", "val "))
    ax_map.set_xlabel("epoch")
    ax_map.set_xlim(ax_loss.get_xlim())
    ax_map.set_ylim(0, 1.02)
    ax_map.legend(fontsize=7)
    if len(measured) < len(rows):
        ax_map.set_title(f"validated at {len(measured)} of {len(rows)} epochs", fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def confusion(matrix: list, names: list, title: str, path: Path) -> None:
    n = len(names)
    size = max(3.5, 0.5 * n + 2)
    fig, ax = plt.subplots(figsize=(size, size))
    ax.imshow(matrix, cmap="Blues")
    ax.set_xticks(range(n), names, rotation=60, ha="right", fontsize=7)
    ax.set_yticks(range(n), names, fontsize=7)
    ax.set_xlabel("predicted zone")
    ax.set_ylabel("true zone")
    peak = max(max(r) for r in matrix) if matrix else 0
    for i in range(n):
        for j in range(n):
            if matrix[i][j]:
                ax.text(j, i, str(matrix[i][j]), ha="center", va="center", fontsize=7,
                        color="white" if matrix[i][j] > peak / 2 else "black")
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
