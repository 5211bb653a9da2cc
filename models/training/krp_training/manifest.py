"""manifest.json: everything the runtime needs to check and use the two exported models.

The C++ loader (issue 4) refuses a model whose manifest does not match the map, the lidar or the
model file itself, so every field here is one the runtime can compare against what it has.
"""
import json
import platform
from pathlib import Path

import numpy as np
import yaml

from .export import CLASSIFIER_INPUT, CLASSIFIER_OUTPUT, sha256
from . import classifier_models

FORMAT = "mrpt_krp_plugin-models"
FORMAT_VERSION = 1
# A user's lidar profile (krp-dataset --lidar NAME.yaml), copied beside the models under this name.
LIDAR_PROFILE_FILE = "lidar.yaml"


def map_fingerprint(map_path: Path) -> dict:
    """The map the models were trained on: for a ROS map YAML, its image's hash and geometry."""
    map_path = Path(map_path)
    if map_path.suffix in (".yaml", ".yml"):
        meta = yaml.safe_load(map_path.read_text())
        image = (map_path.parent / meta["image"]).resolve()
        return {"file": map_path.name, "image": image.name, "image_sha256": sha256(image),
                "resolution_m": float(meta["resolution"]), "origin": [float(v) for v in meta["origin"]]}
    return {"file": map_path.name, "sha256": sha256(map_path)}


def read_landmarks(landmarks_yaml: Path) -> dict:
    doc = yaml.safe_load(Path(landmarks_yaml).read_text())
    return {"method": doc["method"], "keypoints_per_zone": int(doc["keypoints_per_zone"]),
            "zones": [{"zone": z["zone"], "points": [[float(x), float(y)] for x, y in z["points"]]}
                      for z in doc["zones"]]}


def lidar_block(card_lidar: dict) -> dict:
    """The manifest's lidar: the dataset card's, plus the profile file kept beside the models when
    the lidar came from the user's own file (no built-in name stands for it)."""
    block = dict(card_lidar)
    if block.get("from_file"):
        block["profile_file"] = LIDAR_PROFILE_FILE
    return block


def rendering_args(m: dict, models_dir=None) -> list:
    """krp-dataset flags that render submaps as the models in `m` (in `models_dir`) were trained on:
    lidar, submap size and orientation, SDT clip (manifests from before orientations were heading
    up). A lidar from a profile file is rendered from the copy in `models_dir`."""
    lidar = m["lidar"]["name"]
    if m["lidar"].get("profile_file"):
        if models_dir is None:
            raise ValueError("rendering_args: the models' lidar is a profile file; pass their folder")
        lidar = str(Path(models_dir) / m["lidar"]["profile_file"])
    return ["--lidar", lidar, "--size-px", str(m["submap"]["size_px"]),
            "--size-m", str(m["submap"]["size_m"]), "--sdt-clip-m", str(m["sdt_clip_m"]),
            "--orientation", m["submap"].get("orientation", "heading_up")]


def classifier_input(m: dict, grey):
    """An occupancy image (H x W grey levels) as the classifier's 1 x 1 x H x W input, normalized
    as the manifest says: what the C++ runtime feeds it."""
    n = m["classifier"]["input"]["normalize"]
    return ((np.asarray(grey, dtype=np.float32) * n["scale"] - n["mean"]) / n["std"])[None, None]


def build(card: dict, card_sha256: str, map_path: Path, landmarks: dict, classifier: dict, keypoints: dict,
          training: dict, zone_outlines: dict) -> dict:
    """zone_outlines: {"file": the zones.yaml copied beside the models, "sha256": its hash}; the
    runtime reads it for the zone search, so users need not pass the zones the models saw."""
    size_px = int(card["submap"]["size_px"])
    return {
        "format": FORMAT,
        "format_version": FORMAT_VERSION,
        "world": card["world"],
        "map": map_fingerprint(map_path),
        "lidar": lidar_block(card["lidar"]),
        "submap": card["submap"],
        "sdt_clip_m": card["sdt_clip_m"],
        "zones": card["zones"],
        "zone_outlines": zone_outlines,
        "landmarks": landmarks,
        "classifier": {
            **classifier,
            "input": {"name": CLASSIFIER_INPUT, "shape": [1, 1, size_px, size_px], "dtype": "float32",
                      "image": "occupancy grey levels: free 255, unknown 128, occupied 0; robot at the centre, "
                               "heading up",
                      "normalize": {"scale": 1.0 / 255.0, "mean": classifier_models.INPUT_MEAN,
                                    "std": classifier_models.INPUT_STD}},
            "output": {"name": CLASSIFIER_OUTPUT, "shape": [1, len(card["zones"])],
                       "meaning": "softmax probability per zone, in the order of 'zones'"},
        },
        "keypoints": {
            **keypoints,
            "input": {"name": "images", "shape": [1, 3, size_px, size_px], "dtype": "float32",
                      "image": "SDT through the seismic colormap, RGB channel order, scaled to 0..1",
                      "normalize": {"scale": 1.0 / 255.0, "mean": 0.0, "std": 1.0}},
            "output": {"name": "output0",
                       "layout": "[1, 4 + zones + 3K, anchors]: box cx, cy, w, h in input pixels; per-zone scores "
                                 "(sigmoid applied); K x (x, y in input pixels, visibility logit after sigmoid)",
                       "keypoint_coordinates": "continuous image coordinates: pixel (i, j) covers [j, j+1) x [i, i+1)"},
            "kpt_shape": [landmarks["keypoints_per_zone"], 3],
        },
        "dataset": {"card_sha256": card_sha256, "seed": card["seed"], "counts": card["counts"],
                    "scenario": card.get("scenario"), "split": card.get("split")},
        "training": {**training, "python": platform.python_version()},
    }


def write(manifest: dict, path: Path) -> None:
    tmp = Path(str(path) + ".partial")
    tmp.write_text(json.dumps(manifest, indent=2) + "\n")
    tmp.replace(path)
