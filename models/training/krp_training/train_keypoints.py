"""Trains the YOLOv8-pose keypoint model on krp-dataset's SDT images, fully offline.

Augmentations that would break the image's meaning are off: colour shifts (the seismic colours
encode distance), scaling (pixels have a fixed metric size) and mirroring (it would swap landmarks
in a way no robot sees). Rotation and shifts stay on: they are other headings and positions.
"""
import random
import shutil
import time
from dataclasses import dataclass, asdict
from pathlib import Path
from typing import Optional

import yaml

from . import offline


# The share of the epochs that train with the fine sigma when a command does not say.
FINE_EPOCHS_SHARE = 0.25


def default_fine_epochs(epochs: int) -> int:
    """KeypointParams.fine_epochs for `epochs` epochs: the last quarter (10 of the default 40)."""
    return int(epochs * FINE_EPOCHS_SHARE)


@dataclass
class KeypointParams:
    model_yaml: str = "yolov8n-pose.yaml"  # built from its yaml, never a .pt (which would be downloaded)
    epochs: int = 40
    batch_size: int = 32
    patience: int = 30
    rotation_deg: float = 180.0
    translate: float = 0.05
    mosaic: float = 0.0  # one zone per submap: a 4-image mosaic is a scene that cannot occur
    seed: int = 1
    device: str = "cpu"
    workers: int = 2
    threads: int = 2  # ultralytics sets 1 torch thread on a 2-core machine; this restores the cores
    # The width of the keypoint loss's bump, as a share of the object's size (ultralytics' OKS sigma,
    # the same for every landmark; 0 = ultralytics' own 1/K). The loss is 1 - exp(-d^2 / (8 sigma^2
    # area)): with 1/K for K = 12 a keypoint predicted a third of the box away from its label gets
    # almost no gradient, and a landmark the network starts far from is never learned (in the
    # office models of commit 40fb26e, 3 of 24 landmarks sat 18 m off at the median, on the
    # training images too). With 0.25 on the same 600 office images (40 epochs) 1 landmark was
    # off by over 1 m at the median instead of 7, the mean keypoint error fell from 2.74 to 0.82 m
    # and pose mAP@50 rose from 0.75 to 0.83; the median error rose from 0.39 to 0.45 m, the price
    # of a flatter bump. Only training uses it: the reported pose mAP keeps ultralytics' sigma.
    oks_sigma: float = 0.25
    # Coarse to fine: the last `fine_epochs` epochs train with this sharper sigma (0 = ultralytics'
    # 1/K). For small errors the loss is about d^2 / (8 sigma^2 area), so 0.25 weighs a keypoint's
    # last pixels 9 times less than 1/12 does: the broad bump finds every landmark, the sharp one
    # then places it. On the office dataset (600 images, 40 epochs, the same seed; the runs are
    # identical up to the switch) 0.25 and then 1/12 for the last 10 epochs, against 0.25
    # throughout: mean keypoint error 0.61 against 0.76 m, median 0.32 against 0.42 m, landmarks
    # not learned 0 against 1, pose mAP@50 0.836 against 0.839
    # (reports/keypoint_loss_sigma/office_two_zone_fine). 0 fine epochs: one sigma throughout;
    # None: default_fine_epochs(epochs).
    fine_oks_sigma: float = 0.0
    fine_epochs: Optional[int] = None
    # Validating every epoch costs a third of a CPU epoch; the exported model is evaluated on the
    # held-out splits at the end anyway, so by default the last epoch's weights are kept.
    validate_each_epoch: bool = False

    def __post_init__(self):
        if self.fine_epochs is None:
            self.fine_epochs = default_fine_epochs(self.epochs)


@dataclass
class KeypointResult:
    weights: Path
    run_dir: Path
    seconds: float
    params: dict


def _set_threads(threads: int):
    def callback(_trainer):
        import torch  # here, not at the top: REPORT.md's writer imports this module and needs no torch

        torch.set_num_threads(threads)

    return callback


def _progress_bar(total_epochs: int):
    """ultralytics is quiet with verbose=False; one bar per run tells the user how far it is."""
    from tqdm import tqdm

    state = {}

    def on_train_start(_trainer):
        state["bar"] = tqdm(total=total_epochs, desc="keypoint model", unit="epoch")

    def on_train_epoch_end(trainer):
        losses = getattr(trainer, "tloss", None)
        if losses is not None and hasattr(losses, "tolist"):
            names = getattr(trainer, "loss_names", [])
            state["bar"].set_postfix({n: f"{v:.3f}" for n, v in zip(names, losses.tolist()) if n in ("box_loss", "pose_loss")})
        state["bar"].update(1)

    def on_train_end(_trainer):
        state["bar"].close()

    return {"on_train_start": on_train_start, "on_train_epoch_end": on_train_epoch_end, "on_train_end": on_train_end}


def limit_training_images(data_yaml: Path, work_dir: Path, max_images: int, seed: int) -> tuple:
    """(data yaml, training images in it): a copy of krp-dataset's data.yaml whose training split
    is at most `max_images` images drawn with `seed`, or the yaml itself when the split is no
    larger or `max_images` is 0.

    The classifier learns from every image, but a YOLO epoch on a 2-core CPU costs 0.015 to 0.08 s
    per image, by machine (train_map.SECONDS_PER_IMAGE_EPOCH):
    the cap keeps krp-train-map's keypoint stage inside its time budget however large the dataset.
    """
    doc = yaml.safe_load(Path(data_yaml).read_text())
    root = Path(doc["path"])
    images = sorted((root / doc["train"]).glob("*.png"))
    if max_images <= 0 or len(images) <= max_images:
        return Path(data_yaml), len(images)
    chosen = sorted(random.Random(seed).sample(images, max_images))
    listing = Path(work_dir) / "keypoint_train_images.txt"
    listing.write_text("".join(f"{p.resolve()}\n" for p in chosen))
    doc["train"] = str(listing.resolve())
    limited = Path(work_dir) / "keypoints_data.yaml"
    limited.write_text(yaml.safe_dump(doc, sort_keys=False))
    return limited, max_images


def with_loss_sigma(data_yaml: Path, work_dir: Path, sigma: float) -> Path:
    """The data yaml training reads: `data_yaml` itself, or for sigma > 0 a copy that gives every
    keypoint that OKS sigma (ultralytics' `kpt_oks_sigmas`). Evaluation reads the dataset's own
    data.yaml, so the mAP it reports is measured as before."""
    if sigma < 0 or sigma != sigma:
        raise ValueError(f"keypoint loss sigma must be >= 0 (0 = ultralytics' default), not {sigma}")
    if sigma == 0:
        return Path(data_yaml)
    doc = yaml.safe_load(Path(data_yaml).read_text())
    doc["kpt_oks_sigmas"] = [float(sigma)] * int(doc["kpt_shape"][0])
    out = Path(work_dir) / "keypoints_train.yaml"
    out.write_text(yaml.safe_dump(doc, sort_keys=False))
    return out


def sigma_schedule_name(params: dict) -> str:
    """The loss sigma schedule of KeypointParams as a dict (as manifests record it), in words."""
    def one(sigma):
        return "ultralytics' 1/K" if sigma == 0 else f"{sigma:g}"

    name = one(params.get("oks_sigma", 0.0))
    if params.get("fine_epochs", 0) > 0:
        name += f", then {one(params['fine_oks_sigma'])} for the last {params['fine_epochs']} epochs"
    return name


def validate_sigma_schedule(params: KeypointParams):
    """Refuses a schedule that cannot run, before any training."""
    for name in ("oks_sigma", "fine_oks_sigma"):
        value = getattr(params, name)
        if not value >= 0:
            raise ValueError(f"keypoint loss {name} must be >= 0 (0 = ultralytics' default), not {value}")
    if not 0 <= params.fine_epochs <= params.epochs:
        raise ValueError(f"keypoint fine_epochs must be in [0, epochs = {params.epochs}], not {params.fine_epochs}")


def _sharpen_sigma(params: KeypointParams, nkpt: int):
    """A callback that switches the keypoint loss to the fine sigma when the fine epochs begin.
    ultralytics builds its criterion from the model's `kpt_oks_sigmas` on first use, so dropping
    the criterion makes it build one with the new value."""
    first_fine_epoch = params.epochs - params.fine_epochs

    def callback(trainer):
        if trainer.epoch != first_fine_epoch:
            return
        model = trainer.model.module if hasattr(trainer.model, "module") else trainer.model
        model.kpt_oks_sigmas = None if params.fine_oks_sigma == 0 else [float(params.fine_oks_sigma)] * nkpt
        model.criterion = None

    return callback


def train(data_yaml: Path, work_dir: Path, params: KeypointParams, imgsz: int) -> KeypointResult:
    validate_sigma_schedule(params)
    nkpt = int(yaml.safe_load(Path(data_yaml).read_text())["kpt_shape"][0])
    data_yaml = with_loss_sigma(data_yaml, work_dir, params.oks_sigma)
    offline.configure(work_dir / "ultralytics-config")
    from ultralytics import YOLO  # after offline.configure: ultralytics reads the environment on import

    model = YOLO(params.model_yaml, task="pose")
    model.add_callback("on_pretrain_routine_start", _set_threads(params.threads))
    if params.fine_epochs > 0:
        model.add_callback("on_train_epoch_start", _sharpen_sigma(params, nkpt))
    for event, callback in _progress_bar(params.epochs).items():
        model.add_callback(event, callback)
    run_dir = Path(work_dir) / "yolo"
    if run_dir.exists():
        shutil.rmtree(run_dir)
    start = time.perf_counter()
    model.train(data=str(Path(data_yaml).resolve()), epochs=params.epochs, imgsz=imgsz, batch=params.batch_size,
                patience=params.patience, device=params.device, workers=params.workers, seed=params.seed,
                deterministic=True, pretrained=False, amp=False, plots=True, project=str(Path(work_dir).resolve()),
                name="yolo", exist_ok=True, verbose=False,
                degrees=params.rotation_deg, translate=params.translate, scale=0.0, shear=0.0, perspective=0.0,
                fliplr=0.0, flipud=0.0, mosaic=params.mosaic, mixup=0.0, hsv_h=0.0, hsv_s=0.0, hsv_v=0.0,
                close_mosaic=0, val=params.validate_each_epoch)
    weights = run_dir / "weights" / ("best.pt" if params.validate_each_epoch else "last.pt")
    if not weights.exists():
        raise RuntimeError(f"ultralytics finished without {weights}")
    return KeypointResult(weights, run_dir, time.perf_counter() - start, asdict(params))


def evaluate(weights_or_onnx: Path, keypoints_dir: Path, split: str, imgsz: int, work_dir: Path) -> dict:
    """Box and pose precision, recall, mAP@50, mAP@50-95 on one split of krp-dataset's keypoints folder."""
    offline.configure(work_dir / "ultralytics-config")
    from ultralytics import YOLO

    # ultralytics validates only its own split names, so the split under evaluation is named 'test'.
    doc = yaml.safe_load((Path(keypoints_dir) / "data.yaml").read_text())
    doc.update({"path": str(Path(keypoints_dir).resolve()), "test": f"images/{split}"})
    eval_yaml = Path(work_dir) / f"eval-{split}.yaml"
    eval_yaml.write_text(yaml.safe_dump(doc))
    model = YOLO(str(weights_or_onnx), task="pose")
    m = model.val(data=str(eval_yaml.resolve()), split="test", imgsz=imgsz, batch=16, device="cpu",
                  plots=False, verbose=False, project=str(Path(work_dir).resolve()), name=f"val-{split}",
                  exist_ok=True)
    return {
        "box": {"precision": float(m.box.mp), "recall": float(m.box.mr), "map50": float(m.box.map50),
                "map50_95": float(m.box.map)},
        "pose": {"precision": float(m.pose.mp), "recall": float(m.pose.mr), "map50": float(m.pose.map50),
                 "map50_95": float(m.pose.map)},
    }
