"""REPORT.md of a model folder, assembled from manifest.json and the optional side results.

Side results are written by their own committed commands and carry that command:
  comparison.json  architectures with/without scenario generation, leave-one-zone-out (krp_training.compare)
  latency.json     C++ onnxruntime latency of the exported files (krp-model-latency)
A side result that measured other model files than the ones in the folder is not shown as theirs.
"""
import json
import shutil
from pathlib import Path

from . import classifier_models, comparison_record, train_keypoints

SIDE_RESULTS = ("comparison.json", "latency.json")


def _pct(x):
    return "n/a" if x is None or x != x else f"{100 * x:.1f} %"


def _f(x, digits=3):
    return "n/a" if x is None or x != x else f"{x:.{digits}f}"


def _classifier_section(m):
    c = m["classifier"]["metrics"]
    zones = m["zones"]
    lines = ["## Zone classifier (shipped: `zone_classifier.onnx`, " + c["architecture"] + ")", "",
             "| split | images | accuracy |", "|---|---|---|"]
    for s in ("val", "test", "changed"):
        lines.append(f"| {s} | {c['images'][s]} | {_pct(c['accuracy'][s])} |")
    lines += _border_bands(c.get("by_border_distance"))
    lines += ["", f"Best validation epoch {c['best_epoch']}; training took {c['train_seconds']:.0f} s.", "",
              "Confusion matrix, test split (rows: true zone, columns: predicted):", "",
              "| | " + " | ".join(zones) + " |", "|---" * (len(zones) + 1) + "|"]
    for name, row in zip(zones, c["confusion"]["test"]):
        lines.append(f"| **{name}** | " + " | ".join(str(v) for v in row) + " |")
    lines += ["", "![classifier curves](figures/classifier_curves.png) ![confusion, test](figures/confusion_test.png)"
              " ![confusion, changed](figures/confusion_changed.png)", ""]
    return lines


def border_band_table(by_split: dict) -> list:
    """Accuracy per distance band to another zone, one column pair per split (zone_border.py)."""
    splits = [s for s in ("test", "changed") if by_split.get(s)]
    if not splits:
        return []
    lines = ["| distance to another zone | " + " | ".join(f"{s} images | {s} accuracy" for s in splits) + " |",
             "|---" * (1 + 2 * len(splits)) + "|"]
    for i, row in enumerate(by_split[splits[0]]):
        cells = []
        for s in splits:
            r = by_split[s][i]
            cells += [str(r["images"]), _pct(r["accuracy"])]
        lines.append(f"| {row['band']} | " + " | ".join(cells) + " |")
    return lines


def _border_bands(by_split) -> list:
    if not by_split:
        return []
    return ["", "Accuracy by how far the pose lies from another zone (`krp_training/zone_border.py`): a border across "
            "open floor, such as a corridor split in the middle, has nothing on the floor to mark it, so mistakes "
            "within a metre of it say little about the classifier; the relocalizer runs the keypoint model on its "
            "top zones for them.", "", *border_band_table(by_split)]


def _identity_mistakes(k) -> list:
    """Models trained before the swap count was measured have none: nothing to say then."""
    e = {s: k[s]["keypoint_error"] for s in ("test", "changed")}
    if any("on_another_landmark" not in v for v in e.values()):
        return []
    parts = [f"{s} {v['on_another_landmark']} of {v['observed_keypoints']}, the rest "
             f"{_f(v['mean_error_not_swapped_m'])} m mean / {_f(v['median_error_not_swapped_m'])} m median"
             for s, v in e.items() if v["mean_error_not_swapped_m"] is not None]
    if not parts:
        return []
    return [f"Identity mistakes (an observed keypoint more than {e['test']['swap_radius_m']} m from its own landmark "
            "and within it of another landmark in the image): " + "; ".join(parts) + ".", ""]


def _unlearned_landmarks(k) -> list:
    """Models evaluated before the per-landmark breakdown have none: nothing to say then."""
    e = {s: k[s]["keypoint_error"] for s in ("test", "changed")}
    if any("per_landmark" not in v for v in e.values()):
        return []
    parts = []
    for s, v in e.items():
        bad = [r for r in v["per_landmark"] if r["unlearned"]]
        names = ", ".join(f"{r['zone']} #{r['keypoint']} ({r['observed']} observed, median {_f(r['median_m'], 1)} m)"
                          for r in bad) or "none"
        parts.append(f"{s}: {names}; the other landmarks' keypoints {_f(v['mean_error_learned_landmarks_m'])} m mean / "
                     f"{_f(v['median_error_learned_landmarks_m'])} m median")
    return [f"Landmarks not learned (the median error of their observed keypoints is over "
            f"{e['test']['unlearned_median_m']} m: the model puts them elsewhere on nearly every image): "
            + "; ".join(parts) + ".", ""]


def _keypoint_section(m):
    k = m["keypoints"]["metrics"]
    lines = ["## Keypoint model (shipped: `keypoints.onnx`, YOLOv8n-pose; Table 4.3's analogue)", "",
             "Measured on the exported ONNX file with ultralytics' validator; the weights are the last epoch's "
             "(no model selection on the validation split).", "",
             "| split | box P | box R | box mAP50 | box mAP50-95 | pose P | pose R | pose mAP50 | pose mAP50-95 |"
             " mean kpt error | median | observed kpts |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for s in ("test", "changed"):
        b, p, e = k[s]["box"], k[s]["pose"], k[s]["keypoint_error"]
        lines.append(f"| {s} | {_f(b['precision'])} | {_f(b['recall'])} | {_f(b['map50'])} | {_f(b['map50_95'])} | "
                     f"{_f(p['precision'])} | {_f(p['recall'])} | {_f(p['map50'])} | {_f(p['map50_95'])} | "
                     f"{_f(e['mean_error_m'])} m | {_f(e['median_error_m'])} m | {e['observed_keypoints']} |")
    lines += ["", "Keypoint error: distance between predicted and true image position of every keypoint labelled "
              "observed (visibility 2), in metres, on images whose top detection names the right zone "
              f"(test: {k['test']['keypoint_error']['right_zone']} of {k['test']['keypoint_error']['images']}; "
              f"changed: {k['changed']['keypoint_error']['right_zone']} of "
              f"{k['changed']['keypoint_error']['images']}).", "",
              *_identity_mistakes(k),
              *_unlearned_landmarks(k),
              _keypoint_training_line(m), "",
              "![keypoint curves](figures/keypoint_curves.png)", ""]
    return lines


def _keypoint_training_line(m):
    # Older manifests do not record how many images the keypoint model saw; their command line does.
    k = m["keypoints"]["metrics"]
    seen = ""
    if "train_images" in k:
        seen = f" on {k['train_images']} of {m['classifier']['metrics']['images']['train']} training images"
    params = m.get("training", {}).get("keypoint_params")
    sigma = f", loss sigma {train_keypoints.sigma_schedule_name(params)}" if params else ""
    return f"Training: {k['epochs']} epochs{seen}{sigma}, {k['train_seconds']:.0f} s."


def _latency_section(folder: Path, m, name: str):
    path = folder / "latency.json"
    if not path.exists():
        return ["## Inference latency", "", "Not measured yet: run `scripts/measure_model_latency.sh "
                f"{name}`.", ""]
    lat = json.loads(path.read_text())
    current = {m["classifier"]["file"]: m["classifier"]["sha256"], m["keypoints"]["file"]: m["keypoints"]["sha256"]}
    lines = ["## Inference latency (C++ onnxruntime, one thread)", "", f"Command: `{lat['command']}` (run by `scripts/measure_model_latency.sh` on a submap it renders)", "",
             "| model | runs | median | p90 |", "|---|---|---|---|"]
    for r in lat["models"]:
        if current.get(r["file"]) != r["sha256"]:
            lines.append(f"| {r['file']} | stale: measured another file; re-run the command | | |")
        else:
            lines.append(f"| {r['file']} | {r['runs']} | {r['median_ms']:.2f} ms | {r['p90_ms']:.2f} ms |")
    return lines + [""]


def _comparison_section(folder: Path):
    path = folder / "comparison.json"
    if not path.exists():
        return ["## Architecture comparison (Table 4.2's analogue)", "",
                "Not run yet: `scripts/compare_classifiers.sh <world>`.", ""]
    c = json.loads(path.read_text())
    return ["## Architecture comparison (Table 4.2's analogue)", ""] + comparison_lines(c) + [""]


def _thesis_rank(architecture: str) -> int:
    """Where an architecture stands in the thesis's order (classifier_models.ARCHITECTURES); unknown ones last."""
    known = classifier_models.ARCHITECTURES
    return known.index(architecture) if architecture in known else len(known)


def _points(images: int) -> str:
    return f"{100.0 / images:.1f}" if images else "-"


def comparison_lines(c: dict) -> list:
    """comparison.json (krp_training.compare) as Markdown: commands, budget, runs, ratios, leave-one-zone-out."""
    commands = c.get("commands") or [c["command"]]
    if len(commands) == 1:
        lines = [f"Command: `{commands[0]}`", ""]
    else:
        lines = ["Commands, one after another, each adding its architectures' runs to the same budget and "
                 "datasets (checked by `--add`):", ""] + [f"- `{command}`" for command in commands] + [""]
    lines += [comparison_record.budget_note(c["budget"]) if c.get("budget") else c.get("note", ""), ""]
    if c.get("dataset_sha256"):
        d = c["dataset_sha256"]
        lines += [f"Datasets (sha256 of the classifier images): with scenario generation "
                  f"`{d['with_scenarios'][:16]}…`, without `{d['without_scenarios'][:16]}…`.", ""]
    if c.get("split_images"):
        n = c["split_images"]
        lines += [f"Each accuracy is over the scenario dataset's val / test / changed splits: {n['val']} / "
                  f"{n['test']} / {n['changed']} images, so one image moves it by "
                  f"{_points(n['val'])} / {_points(n['test'])} / {_points(n['changed'])} points.", ""]
    lines += ["| architecture | scenario generation | val acc | test acc | changed acc | epochs | train s |",
              "|---|---|---|---|---|---|---|"]
    for r in sorted(c["runs"], key=lambda r: (_thesis_rank(r["architecture"]), -r["strength"])):
        lines.append(f"| {r['architecture']} | {'with' if r['strength'] > 0 else 'without'} | {_pct(r['val'])} | "
                     f"{_pct(r['test'])} | {_pct(r['changed'])} | {r['epochs']} | {r['seconds']:.0f} |")
    changed = comparison_record.ratios(c["runs"])
    if changed:
        test = comparison_record.ratios(c["runs"], "test")
        lines += ["", "Ratio of accuracies with / without scenario generation (the thesis's Table 4.2 gives the "
                      "test split's):", "",
                  "| architecture | test | changed |", "|---|---|---|"]
        for arch in sorted(changed, key=_thesis_rank):
            lines.append(f"| {arch} | {_f(test.get(arch), 2)} | {_f(changed[arch], 2)} |")
    if c.get("latency_ms"):
        lines += ["", f"Inference latency of each architecture's exported classifier, one thread, "
                      f"{c.get('latency_runtime', 'onnxruntime')}; an untrained network of the same graph, since "
                      f"latency does not depend on the weights (`{c.get('latency_command', '')}`):", "",
                  "| architecture | ONNX size | median | p90 | runs |", "|---|---|---|---|---|"]
        for arch in sorted(c["latency_ms"], key=_thesis_rank):
            t = c["latency_ms"][arch]
            lines.append(f"| {arch} | {t['onnx_bytes'] / 1e6:.1f} MB | {t['median']:.2f} ms | {t['p90']:.2f} ms | "
                         f"{t['runs']} |")
    if c.get("leave_one_zone_out"):
        lz = c["leave_one_zone_out"]
        lines += ["", "### Leave-one-zone-out check", "", lz["what"], "",
                  "| trained on | evaluated on | mean max probability | predicted the trained zone |",
                  "|---|---|---|---|"]
        for r in lz["rows"]:
            lines.append(f"| {r['trained_on']} | {r['evaluated_on']} | {_f(r['mean_max_probability'])} | "
                         f"{_pct(r['predicted_trained_zone'])} |")
        lines += ["", lz["finding"]]
    return lines


def zone_outlines_lines(m: dict) -> list:
    """Where the relocalizer's zone search finds the zones the models were trained on."""
    outlines = m.get("zone_outlines")
    if not outlines:
        return ["Zone outlines: none beside the models (trained before krp-train-map kept them); give the "
                "relocalizer the zones they were trained on (`krp-localize --zones`, the ROS node's `zones_file`), "
                "or its zone search is off.", ""]
    line = (f"Zone outlines: `{outlines['file']}` beside the models (sha256 `{outlines['sha256'][:16]}…`), "
            "the zones the dataset was made with; the relocalizer's zone search reads them.")
    if outlines.get("added_after_training"):
        line += " " + outlines["added_after_training"]
    return [line, ""]


def write(folder: Path, m: dict, previous: Path = None, name: str = None) -> None:
    folder = Path(folder)
    if previous is not None and Path(previous).is_dir():
        for name in SIDE_RESULTS:  # kept; stale ones are marked by the hash check above
            if (Path(previous) / name).exists() and not (folder / name).exists():
                shutil.copyfile(Path(previous) / name, folder / name)
    t = m["training"]
    stages = ", ".join(f"{k} {v:.0f} s" for k, v in t.get("stage_seconds", {}).items())
    lines = [f"# Models for `{m['world']}`", "",
             f"Made by: `{t['command']}` on {t['device']} (torch {t['torch']}); stages: {stages}.", "",
             f"Lidar `{m['lidar']['name']}` ({m['lidar']['fov_deg']:.0f} deg, {m['lidar']['max_range_m']} m); "
             f"submap {m['submap']['size_m']} m / {m['submap']['size_px']} px ({m['submap']['resolution_m']} m/px); "
             f"{len(m['zones'])} zones; {m['landmarks']['keypoints_per_zone']} landmarks per zone "
             f"({m['landmarks']['method']}).", "",
             f"Dataset: seed {m['dataset']['seed']}, card sha256 `{m['dataset']['card_sha256'][:16]}…` "
             "(see DATASET_CARD.md); splits by 2 m floor block, so no location is in two splits. "
             "`changed` is a separate split with three times the clutter and occlusion and a third of the "
             "furniture moved.", ""] + zone_outlines_lines(m) + [
             "`keypoints.onnx` is exported by ultralytics and carries its AGPL-3.0 licence in its metadata "
             "(see models/training/LICENSE).", ""]
    lines += _classifier_section(m) + _keypoint_section(m) + _latency_section(folder, m, name or folder.name) + _comparison_section(folder)
    tmp = folder / "REPORT.md.partial"
    tmp.write_text("\n".join(lines) + "\n")
    tmp.replace(folder / "REPORT.md")


def refresh(folder: Path) -> bool:
    """Rewrites <folder>/REPORT.md from its manifest.json and side results; False (nothing written) without a manifest."""
    folder = Path(folder)
    if not (folder / "manifest.json").exists():
        return False
    write(folder, json.loads((folder / "manifest.json").read_text()), name=str(folder))
    return True


def main(argv=None) -> int:
    """Rewrites <folder>/REPORT.md from its manifest.json and side results."""
    import argparse

    p = argparse.ArgumentParser(prog="report", description=main.__doc__)
    p.add_argument("folder", type=Path)
    args = p.parse_args(argv)
    if not refresh(args.folder):
        p.error(f"{args.folder / 'manifest.json'}: not found")
    print(f"report: {args.folder / 'REPORT.md'}")
    return 0


if __name__ == "__main__":
    import sys

    sys.exit(main())
