"""Inference latency of each Table 4.2 architecture: onnxruntime, one thread, on the exported graph.

Latency depends on the graph, not on the weights, so each architecture is built untrained
(weights=None, as it is trained), exported exactly as the shipped classifier is
(export.export_classifier) and run by onnxruntime in Python with one intra-op thread on one
submap-sized input: median and 90th percentile over `runs` runs after `warmup` unmeasured ones.
The figures go into comparison.json (`latency_ms`) beside the accuracies, so that the table says
what each architecture costs on the robot as well as how accurate it is.

    python -m krp_training.architecture_latency --out models/office_two_zone
"""
import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import torch

from . import classifier_models, comparison_record, export
from .command_line import invocation

DEFAULT_RUNS = 200
DEFAULT_WARMUP = 10
DEFAULT_INPUT_PX = 160  # the shipped submap images' side
NUM_CLASSES = 2  # the output layer's size barely moves the latency of any architecture here


def measure(architecture: str, input_px: int, runs: int, warmup: int, work_dir: Path) -> dict:
    import onnxruntime as ort

    torch.manual_seed(0)
    path = Path(work_dir) / f"{architecture}.onnx"
    export.export_classifier(classifier_models.build(architecture, NUM_CLASSES, input_px=input_px), input_px, path)
    opts = ort.SessionOptions()
    opts.intra_op_num_threads = 1
    opts.inter_op_num_threads = 1
    session = ort.InferenceSession(str(path), opts, providers=["CPUExecutionProvider"])
    feed = {export.CLASSIFIER_INPUT: np.random.default_rng(0).uniform(-1, 1, (1, 1, input_px, input_px))
            .astype(np.float32)}
    for _ in range(warmup):
        session.run(None, feed)
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        session.run(None, feed)
        times.append((time.perf_counter() - start) * 1000.0)
    return {"runs": runs, "median": float(np.median(times)), "p90": float(np.percentile(times, 90)),
            "onnx_bytes": path.stat().st_size}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="architecture_latency", description=__doc__.splitlines()[0])
    p.add_argument("--out", required=True, type=Path, help="model folder holding comparison.json")
    p.add_argument("--architectures", default="",
                   help="comma-separated (default: every architecture comparison.json has runs of)")
    p.add_argument("--runs", type=int, default=DEFAULT_RUNS)
    p.add_argument("--warmup", type=int, default=DEFAULT_WARMUP)
    p.add_argument("--input-px", type=int, default=DEFAULT_INPUT_PX)
    args = p.parse_args(argv)
    if args.runs < 1 or args.warmup < 0 or args.input_px < 32:
        p.error("--runs must be at least 1, --warmup at least 0 and --input-px at least 32")
    record = comparison_record.read(args.out)
    if record is None:
        p.error(f"{args.out / comparison_record.FILE_NAME}: not found; run krp_training.compare first")
    compared = ",".join(dict.fromkeys(r["architecture"] for r in record["runs"]))
    try:
        archs = classifier_models.parse_list(args.architectures or compared)
    except ValueError as e:
        p.error(f"--architectures: {e}")
    import onnxruntime as ort

    latency = dict(record.get("latency_ms") or {})
    with tempfile.TemporaryDirectory() as tmp:
        for arch in archs:
            latency[arch] = measure(arch, args.input_px, args.runs, args.warmup, Path(tmp))
            print(json.dumps({arch: latency[arch]}), flush=True)
    record["latency_ms"] = latency
    record["latency_command"] = invocation("python -m krp_training.architecture_latency", argv)
    record["latency_runtime"] = f"onnxruntime {ort.__version__} (Python), {args.input_px} px input"
    comparison_record.write(args.out, record)
    from . import report
    report.refresh(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
