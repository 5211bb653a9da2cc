"""The keypoint model trained on more images for fewer epochs, or fewer for more, side by side.

On a CPU the keypoint stage's cost is about training images x epochs (train_map's
SECONDS_PER_IMAGE_EPOCH), so krp-train-map's budget can buy either. Every run here gets the same
dataset (krp-dataset with krp-train-map's defaults), seed and loss schedule (krp-train-map's: the
last quarter of the epochs with the fine sigma); only the number of training images (drawn from
the same training split) and of epochs differ. Each exported model is measured as krp-train-map
measures it. Writes keypoint_budget.json and KEYPOINT_BUDGET.md into --out.
"""
import argparse
import sys
from pathlib import Path

from . import keypoint_error, keypoint_trials, train_keypoints
from .augment import max_rotation_deg
from .command_line import invocation
from .keypoint_trials import EVAL_SPLITS


def parse_budget(text: str) -> dict:
    """'IMAGESxEPOCHS' (600x40) -> {train_images, epochs}."""
    parts = text.lower().split("x")
    try:
        images, epochs = (int(p) for p in parts)
    except ValueError:
        raise ValueError(f"'{text}' is not IMAGESxEPOCHS (for example 600x40)") from None
    if images < 1 or epochs < 1:
        raise ValueError(f"'{text}': images and epochs must be at least 1")
    return {"train_images": images, "epochs": epochs}


def markdown(result: dict) -> str:
    header = f"| training images | epochs | image passes | split | {keypoint_trials.METRIC_HEADER} | train s |"
    lines = [f"# Keypoint training budget: {result['world']}", "", f"Command: `{result['command']}`", "",
             f"Dataset: `{result['dataset_command']}`; seed {result['seed']} for every run, each run's training "
             "images drawn from the same training split with that seed. Every run trains with krp-train-map's loss "
             "schedule (the last quarter of its epochs with the fine sigma). pose mAP is ultralytics'; errors are of "
             "keypoints labelled observed, on images whose top detection names the right zone; a landmark is not "
             f"learned when its median error is over {keypoint_error.UNLEARNED_MEDIAN_M:g} m. Image passes = "
             "training images x epochs, what the CPU pays for.", "",
             header, keypoint_trials.rule_under(header)]
    for r in result["runs"]:
        for s in EVAL_SPLITS:
            lines.append(f"| {r['train_images']} | {r['epochs']} | {r['train_images'] * r['epochs']:,} | {s} | "
                         f"{keypoint_trials.metric_cells(r[s])} | {r['seconds']:.0f} |")
    lines += ["", *_landmark_comparison(result["runs"])]
    return "\n".join(lines) + "\n"


def _landmark_medians(run: dict, split: str) -> dict:
    return {(r["zone"], r["keypoint"]): r["median_m"] for r in run[split]["keypoint_error"]["per_landmark"]}


def _landmark_comparison(runs: list) -> list:
    """Each run's landmarks against the first run's, landmark by landmark. A run that names the zone
    right on more images is measured on harder ones too, so its mean error may rise without any
    landmark being placed worse; a landmark's median over its own observations says whether it is."""
    if len(runs) < 2:
        return []
    lines = [f"Landmark by landmark against the first run ({runs[0]['train_images']} x {runs[0]['epochs']}): how many "
             "landmarks' median error of observed keypoints is higher, of those both runs measured."]
    for split in EVAL_SPLITS:
        first = _landmark_medians(runs[0], split)
        for r in runs[1:]:
            other = _landmark_medians(r, split)
            both = [k for k in first if k in other]
            higher = sum(other[k] > first[k] for k in both)
            lines.append(f"- {split}, {r['train_images']} x {r['epochs']}: {higher} of {len(both)} higher")
    return lines


def parse_args(argv):
    p = argparse.ArgumentParser(prog="compare_keypoint_budget", description=__doc__.splitlines()[0])
    keypoint_trials.add_dataset_arguments(p)
    p.add_argument("--out", required=True, type=Path, help="folder for keypoint_budget.json and KEYPOINT_BUDGET.md")
    p.add_argument("--budgets", default="600x40,1200x20,2400x10",
                   help="comma-separated runs, each IMAGESxEPOCHS: that many training images for that many epochs")
    args = p.parse_args(argv)
    try:
        args.budgets = [parse_budget(b) for b in args.budgets.split(",")]
    except ValueError as e:
        p.error(f"--budgets: {e}")
    return args


def _train_run(seed: int):
    def train_run(budget, dataset, card, work):
        params = train_keypoints.KeypointParams(epochs=budget["epochs"], seed=seed, rotation_deg=max_rotation_deg(card))
        run = keypoint_trials.train_and_measure(dataset, card, work, budget["train_images"], params)
        if run["train_images"] < budget["train_images"]:
            print(f"compare_keypoint_budget: the training split holds {run['train_images']} images, fewer than "
                  f"the {budget['train_images']} asked for; that run trained on all of them", file=sys.stderr)
        return {**run, "epochs": budget["epochs"], "asked_train_images": budget["train_images"]}

    return train_run


def main(argv=None) -> int:
    args = parse_args(argv)
    result = {"world": args.world, "command": invocation("python -m krp_training.compare_keypoint_budget", argv),
              "seed": args.seed}
    keypoint_trials.run_comparison(args, result, args.budgets, _train_run(args.seed), "keypoint_budget.json",
                                   "KEYPOINT_BUDGET.md", markdown)
    print(f"compare_keypoint_budget: {args.out / 'KEYPOINT_BUDGET.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
