"""Parity between the C++ runtime (krp-infer) and Python on the same submap images.

  outputs: onnxruntime in Python and in C++ give the same classifier probabilities and the same
           raw keypoint-model output (tolerances below).
  decode:  the C++ YOLOv8-pose decode keeps the same detections as ultralytics, both on the same
           raw tensor (ultralytics' own non_max_suppression) and end to end from the PNG
           (YOLO(...).predict on the exported model).
Images are rendered by krp-dataset (the C++ code the robot runs) into a temporary folder.
Exit status 0 when every check passes; the numbers are printed either way.
"""
import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

from . import offline
from .manifest import classifier_input, rendering_args

# Both sides run the same onnxruntime version with one thread; what remains is float summation order.
PROBABILITY_TOLERANCE = 1e-5
RAW_TOLERANCE_PX = 1e-3  # raw output values are pixel coordinates up to the image size, or probabilities
DECODE_TOLERANCE_PX = 1e-3
SCORE_TOLERANCE = 1e-5
# A low threshold keeps many overlapping candidates, so NMS itself is exercised, not just the top box.
PARITY_CONF = 0.05
PARITY_IOU = 0.7


def render_images(dataset_app: Path, world_dir: Path, manifest: dict, models: Path, out: Path,
                  per_zone: int) -> tuple:
    subprocess.run([str(dataset_app), "--world", manifest["world"], "--world-dir", str(world_dir),
                    *rendering_args(manifest, models), "--out", str(out), "--samples-per-zone", str(per_zone),
                    "--changed-per-zone", "1", "--seed", "7"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    occ = sorted((out / "classifier").glob("*/*/*.png"))
    sdt = sorted((out / "keypoints" / "images").glob("*/*.png"))
    return occ, sdt


def run_cpp(krp_infer: Path, models: Path, occ: list, sdt: list, raw_dir: Path) -> dict:
    out = subprocess.run([str(krp_infer), "--models", str(models), "--occupancy", ",".join(map(str, occ)),
                          "--sdt", ",".join(map(str, sdt)), "--conf", str(PARITY_CONF), "--iou", str(PARITY_IOU),
                          "--raw-dir", str(raw_dir), "--threads", "1"], capture_output=True, text=True)
    if out.returncode != 0:
        raise SystemExit(f"parity: krp-infer failed (exit {out.returncode}): {out.stderr.strip()}")
    return json.loads(out.stdout)


def check_outputs(models: Path, manifest: dict, cpp: dict, raw_dir: Path) -> list:
    import onnxruntime as ort
    from PIL import Image

    opts = ort.SessionOptions()
    opts.intra_op_num_threads = 1
    failures = []
    cls = ort.InferenceSession(str(models / manifest["classifier"]["file"]), opts)
    worst = 0.0
    for r in cpp["occupancy"]:
        x = classifier_input(manifest, Image.open(r["image"]).convert("L"))
        py = cls.run(None, {manifest["classifier"]["input"]["name"]: x})[0][0]
        worst = max(worst, float(np.abs(py - np.asarray(r["probabilities"])).max()))
    print(f"classifier: {len(cpp['occupancy'])} images, max |p_python - p_cpp| = {worst:.2e} "
          f"(tolerance {PROBABILITY_TOLERANCE:.0e})")
    if worst > PROBABILITY_TOLERANCE or not cpp["occupancy"]:
        failures.append("classifier probabilities differ")
    kp = ort.InferenceSession(str(models / manifest["keypoints"]["file"]), opts)
    worst = 0.0
    for r in cpp["sdt"]:
        rgb = np.asarray(Image.open(r["image"]).convert("RGB"), dtype=np.float32) / 255.0
        py = kp.run(None, {manifest["keypoints"]["input"]["name"]: rgb.transpose(2, 0, 1)[None]})[0]
        cpp_raw = np.fromfile(raw_dir / (Path(r["image"]).stem + ".f32"), dtype=np.float32).reshape(py.shape)
        worst = max(worst, float(np.abs(py - cpp_raw).max()))
    print(f"keypoint model: {len(cpp['sdt'])} images, max |raw_python - raw_cpp| = {worst:.2e} "
          f"(tolerance {RAW_TOLERANCE_PX:.0e})")
    if worst > RAW_TOLERANCE_PX or not cpp["sdt"]:
        failures.append("keypoint model raw outputs differ")
    return failures


def _compare_detections(label: str, py_dets: list, cpp_dets: list) -> tuple:
    """(worst coordinate difference, worst score difference, problem or None)."""
    if len(py_dets) != len(cpp_dets):
        return 0.0, 0.0, f"{label}: ultralytics keeps {len(py_dets)} detections, C++ {len(cpp_dets)}"
    worst_xy, worst_score = 0.0, 0.0
    for p, c in zip(py_dets, cpp_dets):
        if p["class"] != c["class"]:
            return 0.0, 0.0, f"{label}: class {p['class']} vs {c['class']}"
        worst_xy = max(worst_xy, float(np.abs(np.asarray(p["box"]) - np.asarray(c["box"])).max()),
                       float(np.abs(np.asarray(p["keypoints"])[:, :2] - np.asarray(c["keypoints"])[:, :2]).max()))
        worst_score = max(worst_score, abs(p["score"] - c["score"]),
                          float(np.abs(np.asarray(p["keypoints"])[:, 2] - np.asarray(c["keypoints"])[:, 2]).max()))
    return worst_xy, worst_score, None


def check_decode(models: Path, manifest: dict, cpp: dict, raw_dir: Path, work: Path) -> list:
    offline.configure(work / "ultralytics-config")
    import torch
    from ultralytics import YOLO
    from ultralytics.utils.nms import non_max_suppression

    nc = len(manifest["zones"])
    k = manifest["keypoints"]["kpt_shape"][0]
    size = manifest["submap"]["size_px"]
    failures, total, worst_xy, worst_score = [], 0, 0.0, 0.0
    model = YOLO(str(models / manifest["keypoints"]["file"]), task="pose")
    for r in cpp["sdt"]:
        stem = Path(r["image"]).stem
        raw = np.fromfile(raw_dir / (stem + ".f32"), dtype=np.float32).reshape(1, 4 + nc + 3 * k, -1)
        kept = non_max_suppression(torch.from_numpy(raw), PARITY_CONF, PARITY_IOU, nc=nc, max_det=300)[0]
        same_raw = []
        for row in kept.numpy():
            box = np.clip(row[:4], 0, size)
            kpts = row[6:].reshape(k, 3).copy()
            kpts[:, :2] = np.clip(kpts[:, :2], 0, size)
            same_raw.append({"box": box.tolist(), "score": float(row[4]), "class": int(row[5]), "keypoints": kpts.tolist()})
        res = model.predict(r["image"], imgsz=size, conf=PARITY_CONF, iou=PARITY_IOU, device="cpu", verbose=False)[0]
        end_to_end = [{"box": b.tolist(), "score": float(s), "class": int(c), "keypoints": np.concatenate(
            [xy, conf[:, None]], 1).tolist()} for b, s, c, xy, conf in zip(
            res.boxes.xyxy.numpy(), res.boxes.conf.numpy(), res.boxes.cls.numpy(), res.keypoints.xy.numpy(),
            res.keypoints.conf.numpy())] if len(res.boxes) else []
        for label, py in (("same raw tensor", same_raw), ("end to end", end_to_end)):
            xy, sc, problem = _compare_detections(f"{stem} ({label})", py, r["detections"])
            if problem:
                failures.append(problem)
            worst_xy, worst_score = max(worst_xy, xy), max(worst_score, sc)
        total += len(r["detections"])
    print(f"decode: {len(cpp['sdt'])} images, {total} detections kept by C++ at conf {PARITY_CONF}; "
          f"max coordinate difference {worst_xy:.2e} px (tolerance {DECODE_TOLERANCE_PX:.0e}), "
          f"max score difference {worst_score:.2e} (tolerance {SCORE_TOLERANCE:.0e})")
    if total == 0:
        failures.append("no detections at all: the decode comparison would show nothing")
    if worst_xy > DECODE_TOLERANCE_PX or worst_score > SCORE_TOLERANCE:
        failures.append("decoded detections differ beyond tolerance")
    return failures


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--models", required=True, type=Path)
    p.add_argument("--krp-infer", required=True, type=Path)
    p.add_argument("--krp-dataset", required=True, type=Path)
    p.add_argument("--world-dir", required=True, type=Path)
    p.add_argument("--check", choices=("outputs", "decode"), required=True)
    p.add_argument("--per-zone", type=int, default=6, help="images rendered per zone")
    args = p.parse_args(argv)
    manifest = json.loads((args.models / "manifest.json").read_text())
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        occ, sdt = render_images(args.krp_dataset, args.world_dir, manifest, args.models, work / "images",
                                 args.per_zone)
        cpp = run_cpp(args.krp_infer, args.models, occ, sdt, work / "raw")
        failures = (check_outputs(args.models, manifest, cpp, work / "raw") if args.check == "outputs"
                    else check_decode(args.models, manifest, cpp, work / "raw", work))
    for f in failures:
        print("FAIL: " + f)
    print("parity " + args.check + (": FAILED" if failures else ": passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
