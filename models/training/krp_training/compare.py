"""Table 4.2's analogue and the leave-one-zone-out check, written to <models>/comparison.json.

For each architecture, a classifier is trained on a dataset made with scenario generation and on
one made without (krp-dataset --strength 0), and evaluated on the same held-out splits of the
dataset with it (val, test, changed). Budgets are parameters because the thesis's large networks
cost minutes per epoch on a CPU; the JSON records the budget used next to every figure.
"""
import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import torch

from . import classifier_models, comparison_record, train_classifier
from .augment import AugmentParams, max_rotation_deg
from .command_line import invocation
from .image_folders import read_split
from .train_map import DEFAULT_BIN_DIR, REPO_ROOT


def make_dataset(bin_dir: Path, world: str, strength: float, per_zone: int, seed: int, out: Path,
                 orientation: str = "wall_axes", lidar: str = None) -> Path:
    """krp-dataset for `world`, with `lidar` (a built-in profile name or a profile file; None: the
    world's default)."""
    cmd = [str(bin_dir / "krp-dataset"), "--world", world, "--world-dir", str(REPO_ROOT / "sim_worlds"),
           "--out", str(out), "--samples-per-zone", str(per_zone), "--changed-per-zone",
           str(max(10, per_zone // 10)), "--strength", str(strength), "--seed", str(seed),
           "--orientation", orientation]
    if lidar:
        cmd += ["--lidar", str(lidar)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return out


def lidar_mismatch(models_dir: Path, card: dict):
    """Why the comparison's datasets do not suit the models in `models_dir` (their manifest names
    another lidar), or None: a table beside a model must be of the lidar it was trained for."""
    manifest_path = Path(models_dir) / "manifest.json"
    if not manifest_path.exists():
        return None
    wanted = json.loads(manifest_path.read_text()).get("lidar", {}).get("name")
    got = card.get("lidar", {}).get("name")
    if wanted and got != wanted:
        return (f"the models in {models_dir} were trained for lidar '{wanted}', the comparison's datasets were made "
                f"for '{got}': pass --lidar {wanted}")
    return None


def _limit(data, n: int, seed: int):
    if n <= 0 or len(data) <= n:
        return data
    keep = torch.zeros(len(data), dtype=torch.bool)
    keep[torch.randperm(len(data), generator=torch.Generator().manual_seed(seed))[:n]] = True
    return data.subset(keep)


def leave_one_zone_out(sets: dict, zones: list, params: train_classifier.ClassifierParams) -> dict:
    """Trains without zone B and shows what the classifier says on B's test images."""
    rows = []
    for b, zone_b in enumerate(zones):
        keep = [z for z in range(len(zones)) if z != b]
        remap = {z: i for i, z in enumerate(keep)}
        def only_kept(d):
            sub = d.subset(torch.tensor([int(l) != b for l in d.labels]))
            sub.labels = torch.tensor([remap[int(l)] for l in sub.labels], dtype=torch.int64)
            return sub
        res = train_classifier.train(only_kept(sets["train"]), only_kept(sets["val"]), len(keep), params,
                                     progress_label=f"without {zone_b}")
        unseen = sets["test"].subset(sets["test"].labels == b)
        probs = train_classifier.predict(res.model, unseen.images)
        top = probs.argmax(1)
        most = int(torch.bincount(top, minlength=len(keep)).argmax()) if len(top) else 0
        rows.append({"trained_on": ", ".join(zones[z] for z in keep), "evaluated_on": zone_b,
                     "mean_max_probability": float(probs.max(1).values.mean()) if len(top) else None,
                     "predicted_trained_zone": float((top == most).float().mean()) if len(top) else None,
                     "most_predicted": zones[keep[most]]})
    finding = ("A softmax classifier always names one of the zones it was trained on, and with a high "
               "probability (column 3): its confidence cannot tell an unseen place. The relocalizer must "
               "therefore verify every hypothesis against the map (issue 4) rather than trust the score.")
    if len(zones) == 2:
        finding = ("With two zones, the classifier trained without B has a single output, so column 3 is 1 by "
                   "construction: this shows only that nothing in a softmax classifier can say 'a zone I never "
                   "saw'. The check says more on worlds with three or more zones.")
    return {"what": "The classifier is trained without zone B, then shown B's test images. The thesis trained on "
                    "zone A and validated on zone B to show that a classifier cannot recognise a zone it never saw.",
            "rows": rows,
            "finding": finding}


def _parse_args(argv):
    p = argparse.ArgumentParser(prog="compare", description=__doc__.splitlines()[0])
    p.add_argument("--world", required=True)
    p.add_argument("--out", required=True, type=Path, help="model folder; comparison.json is written there")
    p.add_argument("--architectures", default=",".join(classifier_models.ARCHITECTURES),
                   help="comma-separated, of: " + ", ".join(classifier_models.ARCHITECTURES))
    p.add_argument("--samples-per-zone", type=int, default=300)
    p.add_argument("--train-limit", type=int, default=0, help="train on at most this many images (0 = all)")
    p.add_argument("--epochs", type=int, default=10)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--lidar", help="lidar profile for the datasets: a built-in name (lds01, omni_12m, safety_270) or "
                                   "a profile file (default: the world's); must be the one the models in --out "
                                   "were trained for")
    p.add_argument("--bin-dir", type=Path, default=DEFAULT_BIN_DIR)
    p.add_argument("--scenario-generation", choices=sorted(comparison_record.STRENGTH_CHOICES), default="both",
                   help="train each architecture with scenario generation, without, or both (default): a large "
                        "network's two runs can then be made in two invocations with --add")
    p.add_argument("--skip-loo", action="store_true", help="skip the leave-one-zone-out check")
    p.add_argument("--add", action="store_true",
                   help="add these architectures' runs to the existing comparison.json (same budget and datasets, "
                        "checked), each saved as it finishes; without it comparison.json is replaced at the end")
    args = p.parse_args(argv)
    try:
        args.architectures = classifier_models.parse_list(args.architectures)
    except ValueError as e:
        p.error(f"--architectures: {e}")
    return args


def main(argv=None) -> int:
    args = _parse_args(argv)
    command = invocation("python -m krp_training.compare", argv)
    budget = {"world": args.world, "epochs": args.epochs, "samples_per_zone": args.samples_per_zone,
              "train_limit": args.train_limit, "seed": args.seed}
    if args.lidar:  # only when given, so the records made before --lidar existed still take --add runs
        budget["lidar"] = args.lidar
    with tempfile.TemporaryDirectory() as tmp:
        try:
            dirs = {s: make_dataset(args.bin_dir, args.world, s, args.samples_per_zone, args.seed,
                                    Path(tmp) / f"strength{s}", lidar=args.lidar) for s in comparison_record.STRENGTHS}
        except (subprocess.CalledProcessError, FileNotFoundError) as e:
            print(f"compare: krp-dataset could not make the datasets ({e}); its message, if any, is above. Nothing "
                  "was written.", file=sys.stderr)
            return 2
        card = json.loads((dirs[1.0] / "dataset_card.json").read_text())
        mismatch = lidar_mismatch(args.out, card)
        if mismatch:
            print(f"compare: {mismatch}", file=sys.stderr)
            return 2
        digests = {_strength_key(s): comparison_record.dataset_digest(d) for s, d in dirs.items()}
        try:
            record = comparison_record.start(budget, digests, command,
                                             comparison_record.read(args.out) if args.add else None)
        except comparison_record.ComparisonMismatch as e:
            print(f"compare: {args.out / comparison_record.FILE_NAME}: {e}", file=sys.stderr)
            return 2
        zones = card["zones"]
        augment = AugmentParams(max_rotation_deg=max_rotation_deg(card))
        sets = {s: {split: read_split(d, split, zones) for split in ("train", "val", "test", "changed")}
                for s, d in dirs.items()}
        eval_sets = sets[1.0]  # both variants are judged on the realistic (scenario) splits
        # How many images each accuracy is over: at a few hundred, one image moves it by a point or more.
        record["split_images"] = {s: len(eval_sets[s]) for s in ("val", "test", "changed")}
        # Without --add the old comparison stays whole until this one is; its progress goes beside it.
        progress_name = comparison_record.FILE_NAME if args.add else "comparison.running.json"
        for arch in args.architectures:
            for strength in comparison_record.STRENGTH_CHOICES[args.scenario_generation]:
                train_set = _limit(sets[strength]["train"], args.train_limit, args.seed)
                params = train_classifier.ClassifierParams(architecture=arch, epochs=args.epochs, seed=args.seed,
                                                           augment=augment)
                res = train_classifier.train(train_set, sets[strength]["val"], len(zones), params,
                                             progress_label=f"{arch} strength {strength}")
                run = {"architecture": arch, "strength": strength, "epochs": args.epochs,
                       "train_images": len(train_set), "seconds": res.seconds,
                       **{s: train_classifier.accuracy(res.model, eval_sets[s]) for s in ("val", "test", "changed")}}
                comparison_record.add_run(record, run)
                comparison_record.write(args.out, record, progress_name)
                print(json.dumps(run), flush=True)
        if not args.skip_loo:
            record["leave_one_zone_out"] = leave_one_zone_out(
                eval_sets, zones, train_classifier.ClassifierParams(epochs=args.epochs, seed=args.seed, augment=augment))
    comparison_record.write(args.out, record)
    if not args.add:
        (args.out / progress_name).unlink(missing_ok=True)
    from . import report
    report.refresh(args.out)
    print(f"comparison: {args.out / comparison_record.FILE_NAME}")
    return 0


def _strength_key(strength: float) -> str:
    return "with_scenarios" if strength > 0 else "without_scenarios"


if __name__ == "__main__":
    sys.exit(main())
