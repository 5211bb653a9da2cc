"""Table 4.2's analogue and the leave-one-zone-out check, written to <models>/comparison.json.

For each architecture, a classifier is trained on a dataset made with scenario generation and on
one made without (krp-dataset --strength 0), and evaluated on the same held-out splits of the
dataset with it (val, test, changed). Budgets are parameters because the thesis's large networks
cost minutes per epoch on a CPU; the JSON records the budget used next to every figure.
"""
import argparse
import json
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

import torch

from . import classifier_models, train_classifier
from .augment import AugmentParams, max_rotation_deg
from .image_folders import read_split
from .train_map import DEFAULT_BIN_DIR, REPO_ROOT


def make_dataset(bin_dir: Path, world: str, strength: float, per_zone: int, seed: int, out: Path,
             orientation: str = "wall_axes") -> Path:
    subprocess.run([str(bin_dir / "krp-dataset"), "--world", world, "--world-dir", str(REPO_ROOT / "sim_worlds"),
                    "--out", str(out), "--samples-per-zone", str(per_zone), "--changed-per-zone",
                    str(max(10, per_zone // 10)), "--strength", str(strength), "--seed", str(seed),
                    "--orientation", orientation], check=True, stdout=subprocess.DEVNULL)
    return out


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


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="compare", description=__doc__.splitlines()[0])
    p.add_argument("--world", required=True)
    p.add_argument("--out", required=True, type=Path, help="model folder; comparison.json is written there")
    p.add_argument("--architectures", default=",".join(classifier_models.ARCHITECTURES))
    p.add_argument("--samples-per-zone", type=int, default=300)
    p.add_argument("--train-limit", type=int, default=0, help="train on at most this many images (0 = all)")
    p.add_argument("--epochs", type=int, default=10)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--bin-dir", type=Path, default=DEFAULT_BIN_DIR)
    p.add_argument("--skip-loo", action="store_true", help="skip the leave-one-zone-out check")
    args = p.parse_args(argv)
    command = "python -m krp_training.compare " + " ".join(shlex.quote(a) for a in (argv or sys.argv[1:]))
    archs = [a for a in args.architectures.split(",") if a]
    runs, eval_sets, zones = [], None, None
    with tempfile.TemporaryDirectory() as tmp:
        for strength in (1.0, 0.0):
            d = make_dataset(args.bin_dir, args.world, strength, args.samples_per_zone, args.seed,
                         Path(tmp) / f"strength{strength}")
            card = json.loads((d / "dataset_card.json").read_text())
            zones = card["zones"]
            augment = AugmentParams(max_rotation_deg=max_rotation_deg(card))
            sets = {s: read_split(d, s, zones) for s in ("train", "val", "test", "changed")}
            if strength > 0:
                eval_sets = sets  # both variants are judged on the realistic (scenario) splits
            train_set = _limit(sets["train"], args.train_limit, args.seed)
            for arch in archs:
                params = train_classifier.ClassifierParams(architecture=arch, epochs=args.epochs, seed=args.seed,
                                                           augment=augment)
                res = train_classifier.train(train_set, sets["val"], len(zones), params,
                                             progress_label=f"{arch} strength {strength}")
                runs.append({"architecture": arch, "strength": strength, "epochs": args.epochs,
                             "train_images": len(train_set), "seconds": res.seconds,
                             **{s: train_classifier.accuracy(res.model, eval_sets[s]) for s in
                                ("val", "test", "changed")}})
                print(json.dumps(runs[-1]), flush=True)
        loo = None
        if not args.skip_loo:
            loo = leave_one_zone_out(eval_sets, zones, train_classifier.ClassifierParams(epochs=args.epochs,
                                                                                          seed=args.seed,
                                                                                          augment=augment))
    ratios = {}
    for arch in archs:
        w = next(r for r in runs if r["architecture"] == arch and r["strength"] > 0)
        wo = next(r for r in runs if r["architecture"] == arch and r["strength"] == 0)
        if w["changed"] is not None and wo["changed"]:
            ratios[arch] = w["changed"] / wo["changed"]
    result = {"command": command, "note": f"Budget: {args.epochs} epochs, {args.samples_per_zone} poses per zone, "
              f"training on at most {args.train_limit or 'all'} images; every run is evaluated on the splits of the "
              "dataset made with scenario generation.", "runs": runs, "ratios": ratios, "leave_one_zone_out": loo}
    args.out.mkdir(parents=True, exist_ok=True)
    tmp_json = args.out / "comparison.json.partial"
    tmp_json.write_text(json.dumps(result, indent=2) + "\n")
    tmp_json.replace(args.out / "comparison.json")
    if (args.out / "manifest.json").exists():
        from . import report
        report.write(args.out, json.loads((args.out / "manifest.json").read_text()), name=str(args.out))
    print(f"comparison: {args.out / 'comparison.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
