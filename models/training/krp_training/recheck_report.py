"""RECHECK.md: a model folder's reported numbers beside the same numbers on fresh data."""
from pathlib import Path

from .keypoint_error import UNLEARNED_MEDIAN_M
from .report import border_band_table

# The targets of the learning pipeline (issue 3), printed beside the measurements.
TARGET_TEST_ACCURACY = 0.99
TARGET_CHANGED_ACCURACY = 0.95
TARGET_POSE_MAP50 = 0.95
TARGET_MEAN_KEYPOINT_ERROR_M = 0.15


def _pct(v) -> str:
    return "-" if v is None else f"{100.0 * v:.1f} %"


def _num(v, digits=3) -> str:
    return "-" if v is None else f"{v:.{digits}f}"


def _metres(v) -> str:
    return "-" if v is None else f"{v:.3f} m"


def _count(v) -> str:
    return "-" if v is None else str(v)


def _images(counts: dict, split: str) -> int:
    return sum((counts.get(split) or {}).values())


def _classifier_table(result: dict) -> list:
    shipped = (result["shipped"]["classifier"].get("accuracy") or {})
    fresh = result["fresh"]["classifier"]
    rows = [
        ("test (held-out blocks)", shipped.get("test"), fresh["test"], f">= {_pct(TARGET_TEST_ACCURACY)}"),
        ("changed environment", shipped.get("changed"), fresh["changed"], f">= {_pct(TARGET_CHANGED_ACCURACY)}"),
        ("train blocks, new poses (places the models trained on)", None, fresh["train"], ""),
    ]
    lines = ["| split | shipped report | fresh | fresh images | target |", "|---|---|---|---|---|"]
    for name, old, new, target in rows:
        lines.append(f"| {name} | {_pct(old)} | {_pct(new['accuracy'])} | {new['images']} | {target} |")
    return lines


def _border_section(result: dict) -> list:
    """The fresh splits' accuracy by distance to another zone; nothing for a result measured before."""
    by_split = {s: result["fresh"]["classifier"][s].get("by_border_distance")
                for s in ("test", "changed")}
    table = border_band_table(by_split)
    if not table:
        return []
    return ["Fresh accuracy by how far the pose lies from another zone (`krp_training/zone_border.py`; a border "
            "across open floor has nothing to mark it):", "", *table, ""]


# A table cell names at most this many landmarks: a map of 26 zones can leave a hundred and more
# unlearned, and a cell that long makes the table unreadable. recheck.json lists them all.
MAX_LANDMARKS_NAMED = 8


def _names(v) -> str:
    """A list of landmark names; '-' for a result measured before landmarks were told apart."""
    if v is None:
        return "-"
    if len(v) > MAX_LANDMARKS_NAMED:
        return f"{len(v)} landmarks, among them " + ", ".join(v[:MAX_LANDMARKS_NAMED]) + " (all in recheck.json)"
    return ", ".join(v) if v else "none"


def _keypoint_rows(result: dict) -> list:
    shipped = result["shipped"]["keypoints"]
    fresh = result["fresh"]["keypoints"]

    def get(side: dict, split: str, *path):
        v = side.get(split) or {}
        for key in path:
            v = (v or {}).get(key)
        return v

    metrics = [
        ("box precision", ("box", "precision"), _num, ""),
        ("box recall", ("box", "recall"), _num, ""),
        ("box mAP@50", ("box", "map50"), _num, ""),
        ("box mAP@50-95", ("box", "map50_95"), _num, ""),
        ("pose precision", ("pose", "precision"), _num, ""),
        ("pose recall", ("pose", "recall"), _num, ""),
        ("pose mAP@50", ("pose", "map50"), _num, f">= {TARGET_POSE_MAP50}"),
        ("pose mAP@50-95", ("pose", "map50_95"), _num, ""),
        ("mean error of observed keypoints", ("keypoint_error", "mean_error_m"), _metres,
         f"<= {TARGET_MEAN_KEYPOINT_ERROR_M} m"),
        ("median error", ("keypoint_error", "median_error_m"), _metres, ""),
        ("90th percentile error", ("keypoint_error", "p90_error_m"), _metres, ""),
        ("observed keypoints measured", ("keypoint_error", "observed_keypoints"), _count, ""),
        ("of them on another landmark (identity mistakes)", ("keypoint_error", "on_another_landmark"), _count, ""),
        ("mean error, identity mistakes apart", ("keypoint_error", "mean_error_not_swapped_m"), _metres, ""),
        ("median error, identity mistakes apart", ("keypoint_error", "median_error_not_swapped_m"), _metres, ""),
        (f"landmarks not learned (median error over {UNLEARNED_MEDIAN_M:g} m)", ("keypoint_error", "unlearned_landmarks"), _names, ""),
        ("mean error, the other landmarks", ("keypoint_error", "mean_error_learned_landmarks_m"), _metres, ""),
        ("median error, the other landmarks", ("keypoint_error", "median_error_learned_landmarks_m"), _metres, ""),
    ]
    lines = ["| metric | test: shipped report | test: fresh | changed: shipped report | changed: fresh | target |",
             "|---|---|---|---|---|---|"]
    for name, path, fmt, target in metrics:
        cells = [fmt(get(side, split, *path)) for split in ("test", "changed") for side in (shipped, fresh)]
        lines.append(f"| {name} | " + " | ".join(cells) + f" | {target} |")
    return lines


def _confusion(zones: list, matrix: list) -> list:
    lines = ["| | " + " | ".join(zones) + " |", "|---|" + "---|" * len(zones)]
    for zone, row in zip(zones, matrix):
        lines.append(f"| **{zone}** | " + " | ".join(str(v) for v in row) + " |")
    return lines


def _swap_radius(result: dict) -> str:
    e = (result["fresh"]["keypoints"].get("test") or {}).get("keypoint_error") or {}
    return _metres(e.get("swap_radius_m"))


def write_report(result: dict, m: dict, path: Path) -> None:
    counts = result["fresh_counts"]
    lines = [
        f"# `{result['models']}` ({result['world']}, lidar {m['lidar']['name']}) rechecked on fresh data "
        f"(seed {result['fresh_seed']})",
        "",
        f"Command: `{result['command']}` (by hand: `scripts/krp-recheck-models` with the same arguments).",
        "",
        f"Fresh data: `{result['dataset_command']}`: new poses, clutter, occlusions and noise (seed "
        f"{result['fresh_seed']}), rendered with the models' own submap, SDT and landmark parameters and split "
        f"by floor block with the models' split seed ({result['split_seed']}), so the fresh test split lies only in "
        "blocks the models never trained on. Images: " +
        ", ".join(f"{s} {_images(counts, s)}" for s in ("train", "val", "test", "changed")) + ".",
        "",
        "'Shipped report' is the model folder's own REPORT.md figure (its training dataset's test split); "
        "'fresh' is measured here on the exported ONNX files: the classifier through onnxruntime one image at a "
        "time, normalized as manifest.json says, the keypoint model with ultralytics' validator and the "
        "keypoint error as krp-train-map measures it.",
        "",
        "## Zone classifier accuracy",
        "",
        *_classifier_table(result),
        "",
        *_border_section(result),
        "Confusion matrix, fresh test split (rows: true zone, columns: predicted):",
        "",
        *_confusion(m["zones"], result["fresh"]["classifier"]["test"]["confusion"]),
        "",
        "## Keypoint model",
        "",
        *_keypoint_rows(result),
        "",
        "An identity mistake is an observed keypoint more than the swap radius "
        f"({_swap_radius(result)}) from its own landmark and within it of another landmark in the image: "
        "the model named the wrong corner. The rows without them say how precise the rest are; "
        "the target is on all observed keypoints.",
        "",
    ]
    Path(path).write_text("\n".join(lines))
