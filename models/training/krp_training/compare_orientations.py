"""Zone classifier accuracy on heading-up against wall-aligned submaps, same world, seed and budget.

Both datasets come from krp-dataset with the same seed, so they hold the same poses and scans;
only the turn of the submap differs (and with it the training rotation, augment.max_rotation_deg).
Writes orientation_comparison.json and ORIENTATION.md into --out.
"""
import argparse
import json
import sys
import tempfile
from pathlib import Path

from . import train_classifier
from .augment import AugmentParams, max_rotation_deg
from .command_line import invocation
from .compare import make_dataset
from .image_folders import read_split
from .train_map import DEFAULT_BIN_DIR

ORIENTATIONS = ("heading_up", "wall_axes")
EVAL_SPLITS = ("val", "test", "changed")


def _percent(x):
    return "n/a" if x is None else f"{100 * x:.1f} %"


def markdown(result: dict) -> str:
    lines = [f"# Submap orientation: {result['world']}", "", f"Command: `{result['command']}`", "",
             result["note"], "", "| orientation | training rotation | val | test | changed | best epoch | train s |",
             "|---|---|---|---|---|---|---|"]
    for r in result["runs"]:
        lines.append(f"| {r['orientation']} | +-{r['max_rotation_deg']:g} deg | " +
                     " | ".join(_percent(r[s]) for s in EVAL_SPLITS) + f" | {r['best_epoch']} | {r['seconds']:.0f} |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="compare_orientations", description=__doc__.splitlines()[0])
    p.add_argument("--world", required=True)
    p.add_argument("--out", required=True, type=Path, help="folder for orientation_comparison.json and ORIENTATION.md")
    p.add_argument("--architecture", default="compact")
    p.add_argument("--samples-per-zone", type=int, default=600)
    p.add_argument("--epochs", type=int, default=20)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--bin-dir", type=Path, default=DEFAULT_BIN_DIR)
    args = p.parse_args(argv)
    command = invocation("python -m krp_training.compare_orientations", argv)
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        for orientation in ORIENTATIONS:
            d = make_dataset(args.bin_dir, args.world, 1.0, args.samples_per_zone, args.seed, Path(tmp) / orientation,
                         orientation)
            card = json.loads((d / "dataset_card.json").read_text())
            sets = {s: read_split(d, s, card["zones"]) for s in ("train",) + EVAL_SPLITS}
            rotation = max_rotation_deg(card)
            params = train_classifier.ClassifierParams(architecture=args.architecture, epochs=args.epochs,
                                                       seed=args.seed, augment=AugmentParams(max_rotation_deg=rotation))
            res = train_classifier.train(sets["train"], sets["val"], len(card["zones"]), params,
                                         progress_label=orientation)
            runs.append({"orientation": orientation, "max_rotation_deg": rotation, "best_epoch": res.best_epoch,
                         "seconds": res.seconds, "train_images": len(sets["train"]),
                         **{s: train_classifier.accuracy(res.model, sets[s]) for s in EVAL_SPLITS}})
            print(json.dumps(runs[-1]), flush=True)
    result = {"world": args.world, "command": command, "runs": runs,
              "note": f"{args.architecture} classifier, {args.epochs} epochs, {args.samples_per_zone} poses per zone, "
                      f"seed {args.seed}; accuracy of the best-validation epoch's weights on each split."}
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "orientation_comparison.json").write_text(json.dumps(result, indent=2) + "\n")
    (args.out / "ORIENTATION.md").write_text(markdown(result))
    print(markdown(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
