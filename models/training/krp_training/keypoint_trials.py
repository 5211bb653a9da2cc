"""One dataset, several keypoint-model trainings on it, each measured as krp-train-map measures it.

The shared loop of the keypoint comparisons (compare_loss_sigma: the loss's sigma schedule;
compare_keypoint_budget: training images against epochs): every run sees the same krp-dataset
output and seed, and is scored by ultralytics' validator and by the error of observed keypoints.
"""
import json
import subprocess
import tempfile
from pathlib import Path

from . import export, keypoint_error, train_keypoints
from .command_line import quoted
from .train_map import DEFAULT_BIN_DIR, REPO_ROOT

EVAL_SPLITS = ("test", "changed")


def add_dataset_arguments(p) -> None:
    """The arguments every keypoint comparison takes: the world, its one dataset, the seed and where
    the C++ apps are."""
    p.add_argument("--world", required=True)
    p.add_argument("--samples-per-zone", type=int, default=4000)
    p.add_argument("--changed-per-zone", type=int, default=150)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--bin-dir", type=Path, default=DEFAULT_BIN_DIR)


def run_comparison(args, result: dict, plans: list, train_run, json_name: str, markdown_name: str, markdown) -> None:
    """Makes the comparison's one dataset (add_dataset_arguments' args), then each plan's run:
    `train_run(plan, dataset, card, work)` returns the run's dict, appended to result["runs"] and
    written out (write_results) before the next run starts."""
    with tempfile.TemporaryDirectory() as tmp:
        dataset = Path(tmp) / "dataset"
        card, command = make_dataset(args.bin_dir, args.world, REPO_ROOT / "sim_worlds", dataset,
                                     args.samples_per_zone, args.changed_per_zone, args.seed)
        result["dataset_command"] = quoted(["krp-dataset"] + command[1:])
        result["runs"] = []
        for number, plan in enumerate(plans):
            result["runs"].append(train_run(plan, dataset, card, Path(tmp) / f"run_{number}"))
            write_results(args.out, json_name, markdown_name, result, markdown)


def make_dataset(bin_dir: Path, world: str, world_dir: Path, out: Path, samples_per_zone: int,
                 changed_per_zone: int, seed: int) -> tuple:
    """(dataset card, the krp-dataset command as a list) after writing the dataset into `out`."""
    command = [str(Path(bin_dir) / "krp-dataset"), "--world", world, "--world-dir", str(world_dir), "--out", str(out),
               "--samples-per-zone", str(samples_per_zone), "--changed-per-zone", str(changed_per_zone),
               "--seed", str(seed)]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return json.loads((Path(out) / "dataset_card.json").read_text()), command


def train_and_measure(dataset: Path, card: dict, work: Path, train_images: int,
                      params: train_keypoints.KeypointParams) -> dict:
    """Trains on at most `train_images` of the dataset's training images (drawn with params.seed),
    exports to ONNX and measures the exported model on EVAL_SPLITS: {train_images, seconds, params,
    and per split box/pose metrics with its keypoint_error}."""
    img_px, res_m = int(card["submap"]["size_px"]), float(card["submap"]["resolution_m"])
    k = int(card["landmarks"]["keypoints_per_zone"])
    work.mkdir(parents=True, exist_ok=True)
    data_yaml, n_train = train_keypoints.limit_training_images(Path(dataset) / "keypoints" / "data.yaml", work,
                                                               train_images, params.seed)
    trained = train_keypoints.train(data_yaml, work, params, img_px)
    onnx = work / "keypoints.onnx"
    export.export_keypoints(trained.weights, img_px, onnx, work)
    run = {"train_images": n_train, "seconds": trained.seconds, "params": trained.params}
    for split in EVAL_SPLITS:
        run[split] = train_keypoints.evaluate(onnx, Path(dataset) / "keypoints", split, img_px, work)
        run[split]["keypoint_error"] = keypoint_error.mean_keypoint_error(onnx, dataset, split, img_px, res_m, k, work,
                                                                          zone_names=card["zones"])
    return run


def write_results(out: Path, json_name: str, markdown_name: str, result: dict, markdown) -> None:
    """Writes the result so far: called after every run, so that hours of training are not lost to
    a failure or an interrupt in a later run (a partial file lists the runs that finished)."""
    out.mkdir(parents=True, exist_ok=True)
    (out / json_name).write_text(json.dumps(result, indent=1))
    (out / markdown_name).write_text(markdown(result))


def fmt(x, digits=3) -> str:
    return "n/a" if x is None else f"{x:.{digits}f}"


def metric_cells(split_result: dict) -> str:
    """The table cells every comparison prints for one run on one split."""
    m, e = split_result, split_result["keypoint_error"]
    names = ", ".join(e["unlearned_landmarks"]) or "none"
    return (f"{fmt(m['box']['map50'])} | {fmt(m['pose']['map50'])} | {fmt(m['pose']['map50_95'])} | "
            f"{fmt(e['mean_error_m'])} m | {fmt(e['median_error_m'])} m | {e['right_zone']} of {e['images']} | "
            f"{len(e['unlearned_landmarks'])}: {names}")


METRIC_HEADER = ("box mAP50 | pose mAP50 | pose mAP50-95 | mean kpt error | median | right-zone images | "
                 "landmarks not learned")


def rule_under(header: str) -> str:
    """The Markdown rule line for a table header: one cell per column the header has."""
    return "|" + "---|" * (header.count("|") - 1)
