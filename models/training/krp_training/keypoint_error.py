"""Mean keypoint error in metres of an exported keypoint model on one split, on observed keypoints."""
from pathlib import Path

import numpy as np

from . import offline

OBSERVED = 2  # YOLO-pose visibility written by krp-dataset for a landmark the scan saw


def read_label(path: Path, num_keypoints: int):
    """(zone index, K x 3 array of normalized x, y, visibility) of the one object in a label file,
    or None for an empty one: krp-dataset writes no object when none of the zone's landmarks falls
    inside the image (a background sample; common with a short-range lidar's small submaps)."""
    values = [float(v) for v in Path(path).read_text().split()]
    if not values:
        return None
    expected = 5 + 3 * num_keypoints
    if len(values) != expected:
        raise ValueError(f"{path}: {len(values)} numbers, expected {expected} (one object, {num_keypoints} keypoints)")
    return int(values[0]), np.asarray(values[5:], dtype=np.float64).reshape(num_keypoints, 3)


def mean_keypoint_error(model_path: Path, dataset_dir: Path, split: str, imgsz: int, resolution_m: float,
                        num_keypoints: int, work_dir: Path, conf: float = 0.25) -> dict:
    """Runs the model on every image of the split; the highest-scoring detection is the answer.

    Errors count only images whose top detection names the right zone (a wrong zone's keypoints are
    other landmarks), and only keypoints labelled observed; background images (no object) are
    counted apart. "detected" counts the labelled images with any detection.
    """
    offline.configure(Path(work_dir) / "ultralytics-config")
    from ultralytics import YOLO

    model = YOLO(str(model_path), task="pose")
    images = sorted((Path(dataset_dir) / "keypoints" / "images" / split).glob("*.png"))
    errors_px, right_zone, detected, background = [], 0, 0, 0
    for start in range(0, len(images), 32):
        chunk = images[start:start + 32]
        for img, res in zip(chunk, model.predict([str(p) for p in chunk], imgsz=imgsz, conf=conf, device="cpu",
                                                 verbose=False)):
            label = read_label(Path(dataset_dir) / "keypoints" / "labels" / split / (img.stem + ".txt"),
                               num_keypoints)
            if label is None:  # no landmark in view: no keypoint error to measure
                background += 1
                continue
            zone, truth = label
            if len(res.boxes) == 0:
                continue
            detected += 1
            top = int(res.boxes.conf.argmax())
            if int(res.boxes.cls[top]) != zone:
                continue
            right_zone += 1
            pred = res.keypoints.xy[top].cpu().numpy()
            seen = truth[:, 2] == OBSERVED
            d = pred[seen] - truth[seen, :2] * imgsz
            errors_px.extend(np.hypot(d[:, 0], d[:, 1]).tolist())
    errors_m = np.asarray(errors_px) * resolution_m
    return {
        "images": len(images),
        "background_images": background,
        "detected": detected,
        "right_zone": right_zone,
        "observed_keypoints": int(errors_m.size),
        "mean_error_m": float(errors_m.mean()) if errors_m.size else None,
        "median_error_m": float(np.median(errors_m)) if errors_m.size else None,
        "p90_error_m": float(np.percentile(errors_m, 90)) if errors_m.size else None,
    }
