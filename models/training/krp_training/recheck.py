"""krp-recheck-models: re-measures a model folder's reported numbers on freshly simulated data.

A model folder's REPORT.md is measured on the test split of the dataset the models were trained
with. Here krp-dataset draws new poses, clutter, occlusions and noise with another seed, with the
models' own rendering parameters and landmarks, and with their dataset's split seed: the fresh
test split lies only in floor blocks the models never trained on. The fresh train split (blocks
the models trained on, new poses there) is measured too, to show what a seen place is worth.
Both exported ONNX files are measured, as the robot runs them.
"""
import argparse
import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import yaml
from tqdm import tqdm

from . import keypoint_error, manifest as manifest_io, train_keypoints, zone_border
from .cli_help import DefaultsHelpFormatter
from .command_line import invocation, quoted
from .image_folders import read_split
from .recheck_report import write_report

REPO_ROOT = Path(__file__).resolve().parents[3]
DEFAULT_BIN_DIR = REPO_ROOT / "build" / "mrpt_krp_plugin" / "apps"
# krp-dataset's floor block when a manifest predates recording it (the block has always been 2 m).
DEFAULT_BLOCK_M = 2.0
# Fresh poses per zone: 15 % of them form the held-out test split, ~150 per zone by default.
DEFAULT_SAMPLES_PER_ZONE = 1000
DEFAULT_CHANGED_PER_ZONE = 150
# Landmark coordinates are written with 10 digits; a fresh card must give the models' own points.
LANDMARK_TOLERANCE_M = 1e-6
# Submap sizes and the SDT clip in a fresh card against the manifest's [m].
FLOAT_TOLERANCE = 1e-9


class RecheckError(Exception):
    """A model folder that cannot be rechecked as asked; the message says why."""


def parse_args(argv):
    p = argparse.ArgumentParser(prog="krp-recheck-models", description=__doc__.splitlines()[0],
                                formatter_class=DefaultsHelpFormatter)
    p.add_argument("--models", required=True, type=Path, help="a krp-train-map model folder (manifest.json)")
    p.add_argument("--seed", required=True, type=int, help="sampling seed of the fresh data (not the training seed)")
    p.add_argument("--map", type=Path, help="the map file, for models trained with --map (default: the sim world "
                                            "the manifest names)")
    p.add_argument("--samples-per-zone", type=int, default=DEFAULT_SAMPLES_PER_ZONE)
    p.add_argument("--changed-per-zone", type=int, default=DEFAULT_CHANGED_PER_ZONE)
    p.add_argument("--out", type=Path, help="report folder (default: reports/model_recheck/<models folder>/seed<N>)")
    p.add_argument("--work-dir", type=Path, help="fresh dataset (default: out/recheck/<models folder>_seed<N>)")
    p.add_argument("--bin-dir", type=Path, default=DEFAULT_BIN_DIR, help="where the built C++ apps are")
    p.add_argument("--keep-dataset", action="store_true", help="keep the fresh dataset after the run")
    return p.parse_args(argv)


def _world_source(m: dict, map_arg) -> tuple:
    """(krp-dataset arguments naming the map, the map file): the given map, else the sim world."""
    if map_arg is not None:
        return ["--map", map_arg], Path(map_arg)
    world_file = REPO_ROOT / "sim_worlds" / m["world"] / f"{m['world']}.world.yaml"
    if not world_file.exists():
        raise RecheckError(f"the models were trained on '{m['world']}', which is not a sim world under "
                           f"{REPO_ROOT / 'sim_worlds'}: pass the map they were trained on with --map")
    world = yaml.safe_load(world_file.read_text())
    return ["--world", m["world"], "--world-dir", REPO_ROOT / "sim_worlds"], world_file.parent / world["map"]


def check_map(m: dict, map_path: Path) -> None:
    """The fresh data must come from the map the models learnt: same image, cell size and origin."""
    have = manifest_io.map_fingerprint(map_path)
    want = m["map"]
    for key, value in want.items():
        if have.get(key) != value:
            raise RecheckError(f"{map_path}: its {key} is {have.get(key)!r}, the models were trained with "
                               f"{value!r}: fresh data from another map (or another version of it) would not "
                               "recheck these models")


def write_landmarks_yaml(m: dict, path: Path) -> None:
    """The models' own landmarks, so the fresh keypoint labels number the same points."""
    lm = m["landmarks"]
    path.write_text(yaml.safe_dump({"method": lm["method"], "keypoints_per_zone": lm["keypoints_per_zone"],
                                    "zones": lm["zones"]}, sort_keys=False))


def dataset_command(m: dict, args, source: list, landmarks_yaml: Path, dataset_dir: Path) -> list:
    d = m["dataset"]
    scenario = d.get("scenario") or {}
    block_m = (d.get("split") or {}).get("block_m", DEFAULT_BLOCK_M)
    cmd = [Path(args.bin_dir) / "krp-dataset", *source, *manifest_io.rendering_args(m, args.models),
           "--out", dataset_dir, "--samples-per-zone", args.samples_per_zone,
           "--changed-per-zone", args.changed_per_zone, "--strength", scenario.get("strength", 1.0),
           "--landmarks", landmarks_yaml, "--block-m", block_m, "--seed", args.seed, "--split-seed", d["seed"]]
    if args.map is not None and (Path(args.models) / "zones.yaml").exists():
        cmd += ["--zones", Path(args.models) / "zones.yaml"]
    return [str(c) for c in cmd]


def shown(cmd: list) -> str:
    """The command as the report prints it: paths inside the repository relative to its root."""
    root = str(REPO_ROOT) + "/"
    return quoted(c[len(root):] if c.startswith(root) else c for c in cmd)


def _same(have, want) -> bool:
    """Equal, or for lengths in metres equal to well below any cell (JSON round trips floats)."""
    if isinstance(want, float) and isinstance(have, (int, float)):
        return abs(have - want) < FLOAT_TOLERANCE
    return have == want


def check_card(m: dict, card: dict) -> None:
    """What krp-dataset rendered must be what the models were trained on, field by field."""
    problems = []
    if card["zones"] != m["zones"]:
        problems.append(f"zones {card['zones']} (the models: {m['zones']})")
    if card["lidar"]["name"] != m["lidar"]["name"]:
        problems.append(f"lidar {card['lidar']['name']} (the models: {m['lidar']['name']})")
    for key in ("size_px", "size_m", "resolution_m", "orientation"):
        if key in m["submap"] and not _same(card["submap"].get(key), m["submap"][key]):
            problems.append(f"submap {key} {card['submap'].get(key)} (the models: {m['submap'][key]})")
    if not _same(card["sdt_clip_m"], m["sdt_clip_m"]):
        problems.append(f"SDT clip {card['sdt_clip_m']} m (the models: {m['sdt_clip_m']} m)")
    if problems:
        raise RecheckError("the fresh dataset does not render what the models were trained on: " + "; ".join(problems))


def check_landmarks(m: dict, landmarks_yaml: Path) -> None:
    fresh = manifest_io.read_landmarks(landmarks_yaml)["zones"]
    for want, have in zip(m["landmarks"]["zones"], fresh):
        a, b = np.asarray(want["points"]), np.asarray(have["points"])
        if want["zone"] != have["zone"] or a.shape != b.shape or np.abs(a - b).max() > LANDMARK_TOLERANCE_M:
            raise RecheckError(f"{landmarks_yaml}: zone {have['zone']}'s landmarks differ from the models' "
                               f"({want['zone']})")


def classifier_scores(onnx_path: Path, m: dict, images: "ImageSet", label: str) -> dict:
    """Accuracy and confusion (rows: true zone) of the exported classifier on one split, one image
    at a time through onnxruntime, normalized as the manifest says (what the C++ runtime does)."""
    import onnxruntime as ort

    n = len(m["zones"])
    confusion = np.zeros((n, n), dtype=np.int64)
    if len(images) == 0:
        return {"images": 0, "accuracy": None, "confusion": confusion.tolist()}
    session = ort.InferenceSession(str(onnx_path), providers=["CPUExecutionProvider"])
    name = m["classifier"]["input"]["name"]
    right = []
    for img, zone in tqdm(zip(images.images.numpy(), images.labels.tolist()), total=len(images),
                          desc=f"classifier {label}", unit="img"):
        probs = session.run(None, {name: manifest_io.classifier_input(m, img[0])})[0][0]
        predicted = int(np.argmax(probs))
        confusion[zone, predicted] += 1
        right.append(predicted == zone)
    return {"images": int(confusion.sum()), "accuracy": float(np.trace(confusion) / confusion.sum()),
            "confusion": confusion.tolist(), "right": right}


def measure(models: Path, m: dict, dataset_dir: Path, work: Path) -> dict:
    zones = m["zones"]
    cls_onnx = models / m["classifier"]["file"]
    kp_onnx = models / m["keypoints"]["file"]
    img_px = int(m["submap"]["size_px"])
    k = int(m["landmarks"]["keypoints_per_zone"])
    out = {"classifier": {}, "keypoints": {}}
    # 'train' here is fresh poses in the blocks the models trained on: the seen-place contrast.
    for split in ("test", "changed", "train"):
        images = read_split(dataset_dir, split, zones)
        scores = classifier_scores(cls_onnx, m, images, split)
        right = scores.pop("right", [])
        if split != "train" and len(images):
            scores["by_border_distance"] = zone_border.split_by_band(dataset_dir, images.ids, images.labels.tolist(),
                                                                     right)
        out["classifier"][split] = scores
    for split in ("test", "changed"):
        scores = train_keypoints.evaluate(kp_onnx, dataset_dir / "keypoints", split, img_px, work)
        scores["keypoint_error"] = keypoint_error.mean_keypoint_error(
            kp_onnx, dataset_dir, split, img_px, float(m["submap"]["resolution_m"]), k, work, zone_names=zones)
        out["keypoints"][split] = scores
    return out


def main(argv=None) -> int:
    args = parse_args(argv)
    command = invocation("krp-recheck-models", argv)
    models = Path(args.models)
    try:
        m = json.loads((models / "manifest.json").read_text())
    except FileNotFoundError:
        raise SystemExit(f"krp-recheck-models: {models}/manifest.json not found (is it a krp-train-map folder?)")
    if args.seed == int(m["dataset"]["seed"]):
        raise SystemExit(f"krp-recheck-models: --seed {args.seed} is the seed the models were trained with; it "
                         "would draw their own samples again: pick another")
    if args.samples_per_zone < 1 or args.changed_per_zone < 0:
        raise SystemExit("krp-recheck-models: --samples-per-zone must be >= 1 and --changed-per-zone >= 0")
    if not (Path(args.bin_dir) / "krp-dataset").exists():
        raise SystemExit(f"krp-recheck-models: {args.bin_dir}/krp-dataset not found; build the C++ apps first "
                         "(scripts/build.sh) or pass --bin-dir")
    world = m["world"]
    # Named after the model folder: one world can have models for several lidars.
    name = models.resolve().name
    out = Path(args.out or REPO_ROOT / "reports" / "model_recheck" / name / f"seed{args.seed}")
    work = Path(args.work_dir or REPO_ROOT / "out" / "recheck" / f"{name}_seed{args.seed}")
    try:
        source, map_path = _world_source(m, args.map)
        check_map(m, map_path)
        if work.exists():
            shutil.rmtree(work)
        work.mkdir(parents=True)
        landmarks_yaml = work / "models_landmarks.yaml"
        write_landmarks_yaml(m, landmarks_yaml)
        dataset_dir = work / "dataset"
        cmd = dataset_command(m, args, source, landmarks_yaml, dataset_dir)
        print("[krp-recheck-models] $ " + quoted(cmd), file=sys.stderr, flush=True)
        subprocess.run(cmd, check=True)
        card = json.loads((dataset_dir / "dataset_card.json").read_text())
        check_card(m, card)
        check_landmarks(m, dataset_dir / "landmarks.yaml")
        fresh = measure(models, m, dataset_dir, work)
    except RecheckError as e:
        raise SystemExit(f"krp-recheck-models: {e}")
    result = {"command": command, "models": str(models), "world": world, "fresh_seed": args.seed,
              "split_seed": int(m["dataset"]["seed"]), "dataset_command": shown(cmd),
              "fresh_counts": card["counts"], "fresh": fresh,
              "shipped": {"classifier": m["classifier"].get("metrics", {}), "keypoints": m["keypoints"].get("metrics", {})}}
    out.mkdir(parents=True, exist_ok=True)
    (out / "recheck.json").write_text(json.dumps(result, indent=2) + "\n")
    write_report(result, m, out / "RECHECK.md")
    if not args.keep_dataset:
        shutil.rmtree(work)
    print(f"recheck: {out / 'RECHECK.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
