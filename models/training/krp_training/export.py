"""ONNX export of both models, pinned to what the project's onnxruntime (1.22) loads."""
import hashlib
import shutil
from pathlib import Path

import onnx
import torch
from torch import nn

from . import offline

OPSET = 17
MAX_IR_VERSION = 10  # onnxruntime 1.21/1.22 refuse newer IR versions
CLASSIFIER_INPUT = "occupancy"
CLASSIFIER_OUTPUT = "zone_probabilities"


class _WithSoftmax(nn.Module):
    def __init__(self, net):
        super().__init__()
        self.net = net

    def forward(self, x):
        return torch.softmax(self.net(x), dim=1)


def sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def check_onnx(path: Path) -> dict:
    model = onnx.load(str(path))
    onnx.checker.check_model(model)
    if model.ir_version > MAX_IR_VERSION:
        raise RuntimeError(f"{path}: ONNX IR version {model.ir_version} > {MAX_IR_VERSION}, which onnxruntime 1.22 "
                           "cannot load")
    opset = max(o.version for o in model.opset_import if o.domain in ("", "ai.onnx"))
    return {"ir_version": int(model.ir_version), "opset": int(opset)}


def export_classifier(model: nn.Module, image_px: int, path: Path) -> dict:
    """Exports with the softmax inside, so the runtime reads probabilities directly."""
    model = _WithSoftmax(model.cpu().eval())
    dummy = torch.zeros(1, 1, image_px, image_px)
    tmp = Path(str(path) + ".partial")
    torch.onnx.export(model, dummy, str(tmp), dynamo=False, opset_version=OPSET, input_names=[CLASSIFIER_INPUT],
                      output_names=[CLASSIFIER_OUTPUT],
                      dynamic_axes={CLASSIFIER_INPUT: {0: "batch"}, CLASSIFIER_OUTPUT: {0: "batch"}})
    info = check_onnx(tmp)
    tmp.replace(path)
    return info


def export_keypoints(weights: Path, image_px: int, path: Path, work_dir: Path) -> dict:
    offline.configure(Path(work_dir) / "ultralytics-config")
    from ultralytics import YOLO

    exported = YOLO(str(weights), task="pose").export(format="onnx", imgsz=image_px, opset=OPSET, simplify=True,
                                                      dynamic=False, device="cpu", verbose=False)
    info = check_onnx(Path(exported))
    shutil.copyfile(exported, str(path) + ".partial")
    Path(str(path) + ".partial").replace(path)
    return info
