"""Mean keypoint error in metres of an exported keypoint model on one split, on observed keypoints."""
from pathlib import Path

import numpy as np

from . import offline

OBSERVED = 2  # YOLO-pose visibility written by krp-dataset for a landmark the scan saw
INSIDE = 1  # inside the image but not seen: its label position is still the landmark's
# A keypoint further than this from its own landmark but within it of another landmark in the image
# has been given the other landmark's name: an identity mistake, not an imprecise position [m].
SWAP_RADIUS_M = 0.5
# A landmark whose observed keypoints are off by more than this at the median has not been learned:
# the model puts it somewhere else on nearly every image, rather than imprecisely on some [m].
UNLEARNED_MEDIAN_M = 1.0
# Fewer observed keypoints of one landmark than this say too little to call it unlearned.
MIN_OBSERVED_PER_LANDMARK = 10


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


def errors_and_swaps(pred_px: np.ndarray, truth: np.ndarray, imgsz: int, resolution_m: float,
                     swap_radius_m: float = SWAP_RADIUS_M) -> tuple:
    """(error in metres of each observed keypoint, whether it sits on another landmark instead).

    pred_px: K x 2 predicted image positions; truth: K x 3 normalized x, y, visibility.
    """
    truth_px = truth[:, :2] * imgsz
    seen = np.flatnonzero(truth[:, 2] == OBSERVED)
    in_image = np.flatnonzero(truth[:, 2] >= INSIDE)
    errors, swapped = [], []
    for i in seen:
        own = np.hypot(*(pred_px[i] - truth_px[i])) * resolution_m
        others = [j for j in in_image if j != i]
        nearest_other = min((np.hypot(*(pred_px[i] - truth_px[j])) * resolution_m for j in others), default=np.inf)
        errors.append(own)
        swapped.append(bool(own > swap_radius_m and nearest_other <= swap_radius_m))
    return np.asarray(errors, dtype=np.float64), np.asarray(swapped, dtype=bool)


def per_landmark(zones, indices, errors_m, zone_names) -> list:
    """Error of each landmark's observed keypoints, worst median first: [{zone, keypoint, observed,
    median_m, mean_m, unlearned}] from parallel sequences of zone index, keypoint index and error.

    A mean over all keypoints hides whether a few landmarks are never found or all are imprecise;
    which of the two it is decides what to fix."""
    groups = {}
    for z, k, e in zip(zones, indices, errors_m):
        groups.setdefault((int(z), int(k)), []).append(float(e))
    rows = []
    for (z, k), errs in groups.items():
        median = float(np.median(errs))
        rows.append({"zone": zone_names[z], "keypoint": k, "observed": len(errs), "median_m": median,
                     "mean_m": float(np.mean(errs)),
                     "unlearned": bool(len(errs) >= MIN_OBSERVED_PER_LANDMARK and median > UNLEARNED_MEDIAN_M)})
    return sorted(rows, key=lambda r: -r["median_m"])


def mean_keypoint_error(model_path: Path, dataset_dir: Path, split: str, imgsz: int, resolution_m: float,
                        num_keypoints: int, work_dir: Path, conf: float = 0.25, zone_names=None) -> dict:
    """Runs the model on every image of the split; the highest-scoring detection is the answer.

    Errors count only images whose top detection names the right zone (a wrong zone's keypoints are
    other landmarks), and only keypoints labelled observed; background images (no object) are
    counted apart. "detected" counts the labelled images with any detection.
    """
    offline.configure(Path(work_dir) / "ultralytics-config")
    from ultralytics import YOLO

    model = YOLO(str(model_path), task="pose")
    images = sorted((Path(dataset_dir) / "keypoints" / "images" / split).glob("*.png"))
    errors, swaps, right_zone, detected, background = [], [], 0, 0, 0
    error_zone, error_keypoint = [], []  # which landmark each error belongs to
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
            e, sw = errors_and_swaps(res.keypoints.xy[top].cpu().numpy(), truth, imgsz, resolution_m)
            errors.extend(e.tolist())
            swaps.extend(sw.tolist())
            error_zone.extend([zone] * len(e))
            error_keypoint.extend(np.flatnonzero(truth[:, 2] == OBSERVED).tolist())
    errors_m, swaps = np.asarray(errors), np.asarray(swaps, dtype=bool)
    rest = errors_m[~swaps]
    names = list(zone_names) if zone_names is not None else [str(z) for z in range(max(error_zone, default=-1) + 1)]
    landmarks = per_landmark(error_zone, error_keypoint, errors_m, names)
    unlearned = [r for r in landmarks if r["unlearned"]]
    learned = np.ones(errors_m.size, dtype=bool)
    for r in unlearned:
        z = names.index(r["zone"])
        learned &= ~((np.asarray(error_zone) == z) & (np.asarray(error_keypoint) == r["keypoint"]))
    return {
        "images": len(images),
        "background_images": background,
        "detected": detected,
        "right_zone": right_zone,
        "observed_keypoints": int(errors_m.size),
        "mean_error_m": float(errors_m.mean()) if errors_m.size else None,
        "median_error_m": float(np.median(errors_m)) if errors_m.size else None,
        "p90_error_m": float(np.percentile(errors_m, 90)) if errors_m.size else None,
        # Identity mistakes apart: how precise the keypoints are where the model named them right.
        "swap_radius_m": SWAP_RADIUS_M,
        "on_another_landmark": int(swaps.sum()),
        "mean_error_not_swapped_m": float(rest.mean()) if rest.size else None,
        "median_error_not_swapped_m": float(np.median(rest)) if rest.size else None,
        # Landmarks the model puts elsewhere on nearly every image, and the error of all the others.
        "unlearned_median_m": UNLEARNED_MEDIAN_M,
        "per_landmark": landmarks,
        "unlearned_landmarks": [f"{r['zone']} #{r['keypoint']}" for r in unlearned],
        "mean_error_learned_landmarks_m": float(errors_m[learned].mean()) if learned.any() else None,
        "median_error_learned_landmarks_m": float(np.median(errors_m[learned])) if learned.any() else None,
    }
