"""The keypoint model trained with several OKS sigmas of its loss, side by side on one dataset.

Every run gets the same dataset (krp-dataset with krp-train-map's defaults), the same training
images, seed and epochs; only the sigma schedule differs: `KeypointParams.oks_sigma`, and a
sharper `fine_oks_sigma` for the last `fine_epochs` epochs when a run names one. Each exported
model is measured as krp-train-map measures it: ultralytics' validator (with ultralytics' own
sigma, whatever the training sigma) and the error of observed keypoints, per landmark. Writes
loss_sigma.json and LOSS_SIGMA.md into --out.
"""
import argparse
import sys
from pathlib import Path

from . import keypoint_error, keypoint_trials, train_keypoints
from .augment import max_rotation_deg
from .command_line import invocation
from .keypoint_trials import EVAL_SPLITS
from .train_map import KEYPOINT_TRAIN_IMAGES


def parse_schedule(text: str) -> dict:
    """'S' (sigma S throughout) or 'S:F:N' (S, then F for the last N epochs) -> the run's schedule."""
    parts = text.split(":")
    if len(parts) not in (1, 3):
        raise ValueError(f"'{text}' is neither SIGMA nor SIGMA:FINE_SIGMA:FINE_EPOCHS")
    schedule = {"oks_sigma": float(parts[0]), "fine_oks_sigma": 0.0, "fine_epochs": 0}
    if len(parts) == 3:
        schedule["fine_oks_sigma"] = float(parts[1])
        schedule["fine_epochs"] = int(parts[2])
        if schedule["fine_epochs"] < 1:
            raise ValueError(f"'{text}': the fine epochs must be at least 1")
    if not (schedule["oks_sigma"] >= 0 and schedule["fine_oks_sigma"] >= 0):
        raise ValueError(f"'{text}': sigmas must be >= 0")
    return schedule


def markdown(result: dict) -> str:
    header = f"| training sigma | split | {keypoint_trials.METRIC_HEADER} | train s |"
    lines = [f"# Keypoint loss sigma: {result['world']}", "", f"Command: `{result['command']}`", "",
             f"Dataset: `{result['dataset_command']}`; {result['train_images']} training images, "
             f"{result['epochs']} epochs, seed {result['seed']} for every run. pose mAP is ultralytics' "
             "(its own sigma for every run); errors are of keypoints labelled observed, on images whose top "
             f"detection names the right zone; a landmark is not learned when its median error is over "
             f"{keypoint_error.UNLEARNED_MEDIAN_M:g} m.", "",
             header, keypoint_trials.rule_under(header)]
    for r in result["runs"]:
        for s in EVAL_SPLITS:
            lines.append(f"| {train_keypoints.sigma_schedule_name(r)} | {s} | {keypoint_trials.metric_cells(r[s])} | "
                         f"{r['seconds']:.0f} |")
    return "\n".join(lines) + "\n"


def parse_args(argv):
    p = argparse.ArgumentParser(prog="compare_loss_sigma", description=__doc__.splitlines()[0])
    keypoint_trials.add_dataset_arguments(p)
    p.add_argument("--out", required=True, type=Path, help="folder for loss_sigma.json and LOSS_SIGMA.md")
    p.add_argument("--sigmas", default="0,0.25",
                   help="comma-separated runs, each an OKS sigma S (0 = ultralytics' 1/K) or S:F:N, sigma S "
                        "and then F for the last N epochs")
    p.add_argument("--keypoint-train-images", type=int, default=KEYPOINT_TRAIN_IMAGES)
    p.add_argument("--epochs", type=int, default=40)
    args = p.parse_args(argv)
    try:
        args.sigmas = [parse_schedule(s) for s in args.sigmas.split(",")]
    except ValueError as e:
        p.error(f"--sigmas: {e}")
    if any(s["fine_epochs"] > args.epochs for s in args.sigmas):
        p.error(f"--sigmas: a run's fine epochs exceed --epochs {args.epochs}")
    return args


def main(argv=None) -> int:
    args = parse_args(argv)
    result = {"world": args.world, "command": invocation("python -m krp_training.compare_loss_sigma", argv),
              "epochs": args.epochs, "seed": args.seed}

    def train_run(schedule, dataset, card, work):
        params = train_keypoints.KeypointParams(epochs=args.epochs, seed=args.seed,
                                                rotation_deg=max_rotation_deg(card), **schedule)
        run = {**schedule, **keypoint_trials.train_and_measure(dataset, card, work, args.keypoint_train_images, params)}
        result["train_images"] = run["train_images"]  # every run draws the same images
        return run

    keypoint_trials.run_comparison(args, result, args.sigmas, train_run, "loss_sigma.json", "LOSS_SIGMA.md", markdown)
    print(f"compare_loss_sigma: {args.out / 'LOSS_SIGMA.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
