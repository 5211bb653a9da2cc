"""krp-train-map: one command from a map (or a sim world) to exported, documented models.

map/world -> krp-dataset (the C++ code the robot runs renders every image) -> zone classifier ->
YOLOv8-pose keypoint model -> ONNX + manifest.json + metrics.json + REPORT.md in --out.
The output folder is written as <out>.partial and renamed at the end, so an interrupted run
never leaves a half-written model folder where a robot would look for one.
"""
import argparse
import json
import shutil
import subprocess
import sys
import time
from pathlib import Path

import torch
import yaml

from . import (classifier_models, export, keypoint_error, machine_speed, manifest, plots, report, train_classifier,
               train_keypoints, zone_border)
from .augment import AugmentParams, max_rotation_deg
from .cli_help import DefaultsHelpFormatter
from .command_line import invocation, quoted
from .image_folders import SPLITS, read_split
from .stage_timer import StageTimer, duration

REPO_ROOT = Path(__file__).resolve().parents[3]
DEFAULT_BIN_DIR = REPO_ROOT / "build" / "mrpt_krp_plugin" / "apps"

# Per-image costs for a first time estimate, before the progress bars take over with their own:
# the large_floor models' stage times (1,000 poses per zone, 2 idle CPU cores): 296 s for
# 15,478 classifier images x 15 epochs, 362 s for 600 keypoint images x 40 epochs. On the same
# machine machine_speed.probe_step_seconds() read 0.049 s (0.047 to 0.056 in three runs); the
# estimate scales the costs by this machine's probe against that (see machine_speed.py).
SECONDS_PER_IMAGE_EPOCH = {"compact": 0.0013, "yolo": 0.015}
REFERENCE_PROBE_S = 0.049
# The keypoint model's training images: 600 x 40 epochs took 6 to 30 min of a 2-core CPU.
KEYPOINT_TRAIN_IMAGES = 600
# ultralytics' per-epoch losses and metrics of the keypoint training, copied beside its figure.
KEYPOINT_RESULTS_CSV = "keypoint_results.csv"


# The smallest value each whole-number option takes, checked before any work starts: a bad one
# would otherwise surface only after the dataset (minutes) or the classifier (tens of minutes).
_MINIMUM = {"samples_per_zone": 1, "changed_per_zone": 0, "classifier_epochs": 1, "keypoint_epochs": 1,
            "keypoint_train_images": 0, "seed": 0}


def parse_args(argv):
    p = argparse.ArgumentParser(prog="krp-train-map", description=__doc__.splitlines()[0],
                                formatter_class=DefaultsHelpFormatter)
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("--world", help="a sim world name under sim_worlds/ or a *.world.yaml")
    src.add_argument("--map", help="a map file (ROS map .yaml, .gridmap, OctoMap .bt/.ot)")
    p.add_argument("--zones", help="zones.yaml for --map (default: automatic zoning)")
    p.add_argument("--lidar", help="lidar profile: a built-in name (lds01, omni_12m, safety_270) or your scanner's "
                                   "NAME.yaml (fov_deg, beams, max_range_m; see the README) (default: the world's "
                                   "default; omni_12m for --map)")
    p.add_argument("--out", required=True, help="model folder to write (replaced at the end if it exists)")
    p.add_argument("--work-dir", help="dataset and training runs (default: out/train/<name>)")
    p.add_argument("--samples-per-zone", type=int, default=4000,
                   help="poses per zone; the classifier trains on all, the keypoint model on a subset")
    p.add_argument("--changed-per-zone", type=int, default=150,
                   help="poses per zone of the changed-environment test split (heavier clutter, moved furniture)")
    p.add_argument("--strength", type=float, default=1.0, help="scenario generation strength (0 = off)")
    p.add_argument("--classifier", default="compact", choices=classifier_models.ARCHITECTURES)
    p.add_argument("--classifier-epochs", type=int, default=15)
    p.add_argument("--keypoint-epochs", type=int, default=40)
    p.add_argument("--keypoint-train-images", type=int, default=KEYPOINT_TRAIN_IMAGES,
                   help="at most this many training images for the keypoint model, drawn with --seed "
                        "(0 = all); the classifier always gets all of them")
    p.add_argument("--keypoint-loss-sigma", type=float, default=train_keypoints.KeypointParams.oks_sigma,
                   help="OKS sigma of the keypoint model's training loss (0 = ultralytics' 1/K; see "
                        "train_keypoints.KeypointParams.oks_sigma)")
    p.add_argument("--keypoint-fine-sigma", type=float, default=train_keypoints.KeypointParams.fine_oks_sigma,
                   help="a sharper OKS sigma for the keypoint model's last --keypoint-fine-epochs epochs "
                        "(0 = ultralytics' 1/K; see train_keypoints.KeypointParams.fine_oks_sigma)")
    p.add_argument("--keypoint-fine-epochs", type=int,
                   help="how many of the last --keypoint-epochs train with --keypoint-fine-sigma (0 = none; "
                        "default: a quarter of them)")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--device", default="auto", help="auto (GPU when there is one), cpu or cuda")
    p.add_argument("--bin-dir", default=str(DEFAULT_BIN_DIR), help="where the built C++ apps are")
    p.add_argument("--keep-work", action="store_true", help="keep the dataset and runs after success")
    args = p.parse_args(argv)
    for name, least in _MINIMUM.items():
        if getattr(args, name) < least:
            p.error(f"--{name.replace('_', '-')} must be {least} or more, not {getattr(args, name)}")
    if not args.strength >= 0:
        p.error(f"--strength must be >= 0 (0 = off), not {args.strength}")
    if not args.keypoint_loss_sigma >= 0:  # refused now, not after the dataset and the classifier
        p.error(f"--keypoint-loss-sigma must be >= 0 (0 = ultralytics' default), not {args.keypoint_loss_sigma}")
    if not args.keypoint_fine_sigma >= 0:
        p.error(f"--keypoint-fine-sigma must be >= 0 (0 = ultralytics' default), not {args.keypoint_fine_sigma}")
    if args.keypoint_fine_epochs is None:
        args.keypoint_fine_epochs = train_keypoints.default_fine_epochs(args.keypoint_epochs)
    if not 0 <= args.keypoint_fine_epochs <= args.keypoint_epochs:
        p.error(f"--keypoint-fine-epochs must be in [0, --keypoint-epochs = {args.keypoint_epochs}], "
                f"not {args.keypoint_fine_epochs}")
    return args


def _run(cmd):
    print("[krp-train-map] $ " + quoted(cmd), file=sys.stderr, flush=True)
    subprocess.run([str(c) for c in cmd], check=True)


def _app(bin_dir: Path, name: str) -> Path:
    exe = Path(bin_dir) / name
    if not exe.exists():
        raise SystemExit(f"krp-train-map: {exe} not found; build the C++ apps first (scripts/build.sh) "
                         "or pass --bin-dir")
    return exe


def _dataset_command(args, bin_dir: Path, dataset_dir: Path) -> list:
    cmd = [_app(bin_dir, "krp-dataset"), "--out", dataset_dir, "--samples-per-zone", args.samples_per_zone,
           "--changed-per-zone", args.changed_per_zone, "--strength", args.strength, "--seed", args.seed]
    if args.world:
        cmd += ["--world", args.world, "--world-dir", REPO_ROOT / "sim_worlds"]
    else:
        cmd += ["--map", args.map] + (["--zones", args.zones] if args.zones else [])
    if args.lidar:
        cmd += ["--lidar", args.lidar]
    return cmd


def estimate_rest_s(n_classifier_images: int, classifier_epochs: int, n_keypoint_images: int,
                    keypoint_epochs: int, slowdown: float = 1.0) -> dict:
    """Seconds the two training stages should take on a CPU `slowdown` times slower than the one that
    measured the per-image costs."""
    if not slowdown > 0:
        raise ValueError(f"estimate_rest_s: slowdown must be > 0, not {slowdown}")
    return {"classifier": n_classifier_images * classifier_epochs * SECONDS_PER_IMAGE_EPOCH["compact"] * slowdown,
            "keypoints": n_keypoint_images * keypoint_epochs * SECONDS_PER_IMAGE_EPOCH["yolo"] * slowdown}


def _print_estimate(est: dict, slowdown: float) -> None:
    """Once the dataset is made the image counts are known: the whole wait, before it starts."""
    parts = ", ".join(f"{k} {duration(v)}" for k, v in est.items())
    print(f"[krp-train-map] estimate for the rest on this CPU (measured {slowdown:.2g}x the time of the machine "
          f"the costs come from): {parts}, about {duration(sum(est.values()))} in all (--samples-per-zone, "
          "--classifier-epochs, --keypoint-train-images and --keypoint-epochs trade accuracy for time)",
          file=sys.stderr, flush=True)


def _device(choice: str) -> str:
    if choice == "auto":
        return "cuda" if torch.cuda.is_available() else "cpu"
    if choice == "cuda" and not torch.cuda.is_available():
        raise SystemExit("krp-train-map: --device cuda but torch sees no GPU")
    return choice


def _map_path(args) -> Path:
    if args.map:
        return Path(args.map)
    world_file = Path(args.world) if args.world.endswith(".yaml") else \
        REPO_ROOT / "sim_worlds" / args.world / f"{args.world}.world.yaml"
    return world_file.parent / yaml.safe_load(world_file.read_text())["map"]


def main(argv=None) -> int:
    args = parse_args(argv)
    command = invocation("krp-train-map", argv)
    device = _device(args.device)
    name = args.world or Path(args.map).stem
    out = Path(args.out)
    work = Path(args.work_dir or REPO_ROOT / "out" / "train" / Path(name).stem)
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    partial = Path(str(out) + ".partial")
    if partial.exists():
        shutil.rmtree(partial)
    (partial / "figures").mkdir(parents=True)
    timer = StageTimer()
    dataset_dir = work / "dataset"
    print(f"[krp-train-map] {name}: device {device}, work dir {work}, output {out}", file=sys.stderr)

    with timer.stage("dataset"):
        _run(_dataset_command(args, Path(args.bin_dir), dataset_dir))
    card_path = dataset_dir / "dataset_card.json"
    card = json.loads(card_path.read_text())
    zones = card["zones"]
    sets = {s: read_split(dataset_dir, s, zones) for s in SPLITS}
    n_train = len(sets["train"])
    print(f"[krp-train-map] {len(zones)} zones; images: " + ", ".join(f"{s} {len(v)}" for s, v in sets.items()),
          file=sys.stderr)

    rotation = max_rotation_deg(card)
    cp = train_classifier.ClassifierParams(architecture=args.classifier, epochs=args.classifier_epochs,
                                           seed=args.seed, device=device,
                                           augment=AugmentParams(max_rotation_deg=rotation))
    # The keypoint model's images are drawn now, so that one estimate counts what it will train on.
    kp_yaml, n_kp_train = train_keypoints.limit_training_images(dataset_dir / "keypoints" / "data.yaml", work,
                                                                args.keypoint_train_images, args.seed)
    rest = None  # a GPU's progress bars are estimate enough
    if device == "cpu":
        slowdown = machine_speed.probe_step_seconds(input_px=sets["train"].images.shape[-1]) / REFERENCE_PROBE_S
        rest = estimate_rest_s(n_train, cp.epochs, n_kp_train, args.keypoint_epochs, slowdown)
        _print_estimate(rest, slowdown)
    with timer.stage("classifier", rest["classifier"] if rest else None):
        cls = train_classifier.train(sets["train"], sets["val"], len(zones), cp)
    evaluated = {s: train_classifier.evaluate(cls.model, sets[s], len(zones), device)
                 for s in ("val", "test", "changed")}
    cls_metrics = {
        "architecture": args.classifier, "best_epoch": cls.best_epoch, "train_seconds": cls.seconds,
        "accuracy": {s: evaluated[s][0] for s in ("val", "test", "changed")},
        "confusion": {s: evaluated[s][1] for s in ("test", "changed")},
        "images": {s: len(sets[s]) for s in SPLITS},
        "by_border_distance": {s: zone_border.split_by_band(dataset_dir, sets[s].ids, sets[s].labels.tolist(),
                                                            evaluated[s][2]) if len(sets[s]) else []
                               for s in ("test", "changed")},
    }
    plots.classifier_curves(cls.history, f"{name}: zone classifier ({args.classifier})",
                            partial / "figures" / "classifier_curves.png")
    for s in ("test", "changed"):
        plots.confusion(cls_metrics["confusion"][s], zones, f"{name}: classifier, {s} split",
                        partial / "figures" / f"confusion_{s}.png")

    kp = train_keypoints.KeypointParams(epochs=args.keypoint_epochs, seed=args.seed, rotation_deg=rotation,
                                        oks_sigma=args.keypoint_loss_sigma, fine_oks_sigma=args.keypoint_fine_sigma,
                                        fine_epochs=args.keypoint_fine_epochs,
                                        device="0" if device == "cuda" else "cpu")
    img_px = int(card["submap"]["size_px"])
    with timer.stage("keypoints", rest["keypoints"] if rest else None):
        kpr = train_keypoints.train(kp_yaml, work, kp, img_px)
    if (kpr.run_dir / "results.csv").exists():
        # Kept beside the figure, so that it can be drawn again without training again.
        shutil.copyfile(kpr.run_dir / "results.csv", partial / "figures" / KEYPOINT_RESULTS_CSV)
        plots.keypoint_curves(partial / "figures" / KEYPOINT_RESULTS_CSV, f"{name}: keypoint model (YOLOv8n-pose)",
                              partial / "figures" / "keypoint_curves.png")

    with timer.stage("export"):
        cls_onnx = export.export_classifier(cls.model, img_px, partial / "zone_classifier.onnx")
        kp_onnx = export.export_keypoints(kpr.weights, img_px, partial / "keypoints.onnx", work)

    with timer.stage("evaluate"):
        kp_metrics = {"train_seconds": kpr.seconds, "epochs": kp.epochs, "train_images": n_kp_train}
        for s in ("test", "changed"):
            kp_metrics[s] = train_keypoints.evaluate(partial / "keypoints.onnx", dataset_dir / "keypoints", s,
                                                     img_px, work)
            kp_metrics[s]["keypoint_error"] = keypoint_error.mean_keypoint_error(
                partial / "keypoints.onnx", dataset_dir, s, img_px, card["submap"]["resolution_m"],
                int(card["landmarks"]["keypoints_per_zone"]), work, zone_names=zones)

    landmarks = manifest.read_landmarks(dataset_dir / "landmarks.yaml")
    training = {"command": command, "device": device, "torch": torch.__version__,
                "stage_seconds": dict(timer.seconds), "classifier_params": cls.params,
                "keypoint_params": kpr.params}
    # The zones the dataset was made with (given or automatic), for the runtime's zone search.
    shutil.copyfile(dataset_dir / "zones.yaml", partial / "zones.yaml")
    zone_outlines = {"file": "zones.yaml", "sha256": export.sha256(partial / "zones.yaml")}
    # A user's own lidar goes with the models: fresh submaps for them (krp-recheck-models, the
    # parity check) need its profile, which no built-in name stands for.
    if card["lidar"].get("from_file"):
        shutil.copyfile(dataset_dir / "lidar.yaml", partial / manifest.LIDAR_PROFILE_FILE)
    m = manifest.build(card, export.sha256(card_path), _map_path(args), landmarks,
                       {"file": "zone_classifier.onnx", "sha256": export.sha256(partial / "zone_classifier.onnx"),
                        "architecture": args.classifier, **cls_onnx, "metrics": cls_metrics},
                       {"file": "keypoints.onnx", "sha256": export.sha256(partial / "keypoints.onnx"),
                        "architecture": "yolov8n-pose", **kp_onnx, "metrics": kp_metrics},
                       training, zone_outlines)
    shutil.copyfile(dataset_dir / "DATASET_CARD.md", partial / "DATASET_CARD.md")
    shutil.copyfile(dataset_dir / "preview.png", partial / "figures" / "dataset_preview.png")
    # Written once, after every stage, so the manifest and report carry all the stage times.
    m["training"]["stage_seconds"] = dict(timer.seconds)
    m["training"]["total_seconds"] = timer.total()
    manifest.write(m, partial / "manifest.json")
    report.write(partial, m, previous=out, name=str(out))

    if out.exists():
        backup = Path(str(out) + ".previous")
        if backup.exists():
            shutil.rmtree(backup)
        out.rename(backup)
        partial.rename(out)
        shutil.rmtree(backup)
    else:
        partial.rename(out)
    if not args.keep_work:
        shutil.rmtree(work)
    print(f"[krp-train-map] done in {timer.total() / 60:.1f} min: " +
          ", ".join(f"{k} {v:.0f} s" for k, v in timer.seconds.items()), file=sys.stderr)
    print(f"models: {out} (REPORT.md, manifest.json)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
