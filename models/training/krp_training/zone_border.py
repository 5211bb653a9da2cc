"""The zone classifier's accuracy by how far each submap's pose lies from another zone.

A zone border that crosses open floor (a corridor split in the middle) has nothing on the floor to
mark it: a submap taken 0.3 m on one side differs from one taken 0.3 m on the other by two
pixels. Accuracy on a split therefore mixes two things: mistakes at such borders, which no
classifier can avoid and the relocalizer absorbs by running the keypoint model on its top zones,
and mistakes away from any border, which are the classifier's own. This table keeps them apart.

Poses come from krp-dataset's samples.csv and zones from its zones.yaml; both are in map metres.
"""
import csv
from pathlib import Path

import numpy as np
import yaml

# Upper edges of the distance bands [m]. 1 m: a submap within it differs from one across the border
# by under 7 pixels at the default 0.15 m/px. 3 m: beyond it the submap's own room usually shows
# walls the other zone lacks.
BORDER_BANDS_M = (1.0, 3.0)


def read_zone_polygons(zones_yaml: Path) -> list:
    """One (K x 2) array of polygon vertices per zone, in the zones file's order."""
    doc = yaml.safe_load(Path(zones_yaml).read_text()) or {}
    zones = doc.get("zones") or []
    if not zones:
        raise ValueError(f"{zones_yaml}: no zones")
    return [np.asarray(z["polygon"], dtype=float).reshape(-1, 2) for z in zones]


def read_positions(dataset_dir: Path, ids: list) -> np.ndarray:
    """(N x 2) sample positions in metres, in the order of `ids` (krp-dataset's image ids)."""
    with open(Path(dataset_dir) / "samples.csv", newline="") as f:
        by_id = {r["id"]: (float(r["x_m"]), float(r["y_m"])) for r in csv.DictReader(f)}
    missing = [i for i in ids if i not in by_id]
    if missing:
        raise ValueError(f"{dataset_dir}/samples.csv has no row for {len(missing)} images (first: {missing[0]})")
    return np.asarray([by_id[i] for i in ids], dtype=float).reshape(-1, 2)


def _distance_to_outline(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
    """Distance from each point to the nearest point of the polygon's outline."""
    a = polygon
    b = np.roll(polygon, -1, axis=0)
    ab = b - a  # E x 2
    ap = points[:, None, :] - a[None, :, :]  # N x E x 2
    length2 = np.maximum((ab ** 2).sum(axis=1), 1e-18)
    t = np.clip((ap * ab[None]).sum(axis=2) / length2[None], 0.0, 1.0)
    nearest = a[None] + t[..., None] * ab[None]
    return np.sqrt(((points[:, None, :] - nearest) ** 2).sum(axis=2)).min(axis=1)


def distance_to_other_zones(points: np.ndarray, own_zone: np.ndarray, polygons: list) -> np.ndarray:
    """Per point, the distance [m] to the outline of the nearest zone other than its own (inf with
    one zone). A point inside its own zone is outside the others, so the outline is the zone."""
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    own_zone = np.asarray(own_zone).reshape(-1)
    if len(points) != len(own_zone):
        raise ValueError(f"{len(points)} points but {len(own_zone)} zone labels")
    out = np.full(len(points), np.inf)
    for z, polygon in enumerate(polygons):
        others = own_zone != z
        if others.any():
            out[others] = np.minimum(out[others], _distance_to_outline(points[others], polygon))
    return out


def accuracy_by_band(correct, distance_m, bands_m=BORDER_BANDS_M) -> list:
    """Rows {"band", "from_m", "to_m" (None = no upper edge), "images", "accuracy" (None when empty)}."""
    correct = np.asarray(correct, dtype=bool).reshape(-1)
    distance_m = np.asarray(distance_m, dtype=float).reshape(-1)
    if len(correct) != len(distance_m):
        raise ValueError(f"{len(correct)} outcomes but {len(distance_m)} distances")
    if list(bands_m) != sorted(bands_m) or any(b <= 0 for b in bands_m):
        raise ValueError(f"band edges must be positive and increasing, not {list(bands_m)}")
    edges = [0.0, *bands_m, None]
    rows = []
    for low, high in zip(edges[:-1], edges[1:]):
        inside = (distance_m >= low) & ((distance_m < high) if high is not None else True)
        n = int(inside.sum())
        label = f"{low:g}-{high:g} m" if high is not None else f">= {low:g} m"
        rows.append({"band": label, "from_m": low, "to_m": high, "images": n,
                     "accuracy": float(correct[inside].mean()) if n else None})
    return rows


def split_by_band(dataset_dir: Path, ids: list, labels, correct, zones_yaml: Path = None) -> list:
    """accuracy_by_band for one split of a krp-dataset folder (zones from its zones.yaml by default)."""
    polygons = read_zone_polygons(zones_yaml or Path(dataset_dir) / "zones.yaml")
    distance = distance_to_other_zones(read_positions(dataset_dir, ids), np.asarray(labels), polygons)
    return accuracy_by_band(correct, distance)
