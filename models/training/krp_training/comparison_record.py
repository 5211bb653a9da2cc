"""comparison.json: Table 4.2's runs, kept so that architectures can be added run by run.

The thesis's large networks cost an hour or more per run on a 2-core CPU, so the comparison is
built up over several invocations (`compare --add`). Runs made in different invocations are only
comparable when they trained and were judged on the same images with the same budget: the record
keeps the budget and a digest of each dataset's classifier images, and refuses to mix runs whose
budget or data differ.
"""
import hashlib
import json
from pathlib import Path

STRENGTHS = (1.0, 0.0)  # with and without scenario generation
# compare --scenario-generation: which of STRENGTHS an invocation trains (both datasets are made
# either way, since --add checks both digests).
STRENGTH_CHOICES = {"both": STRENGTHS, "with": (1.0,), "without": (0.0,)}
FILE_NAME = "comparison.json"


class ComparisonMismatch(ValueError):
    """An existing comparison.json cannot take runs made with another budget or other data."""


def dataset_digest(dataset_dir: Path) -> str:
    """sha256 over the classifier images' relative paths and bytes, in path order."""
    root = Path(dataset_dir) / "classifier"
    h = hashlib.sha256()
    for path in sorted(p for p in root.rglob("*") if p.is_file()):
        h.update(str(path.relative_to(root)).encode() + b"\0")
        h.update(path.read_bytes())
    return h.hexdigest()


def budget_note(budget: dict) -> str:
    images = (f"training on at most {budget['train_limit']} of the training split's images" if budget["train_limit"]
              else "training on the whole training split")
    return (f"Budget: {budget['epochs']} epochs, {budget['samples_per_zone']} poses per zone, {images}, seed "
            f"{budget['seed']}; every run is evaluated on the splits of the dataset made with scenario generation.")


def ratios(runs: list, split: str = "changed") -> dict:
    """`split`'s accuracy with / without scenario generation, per architecture that has both (the
    thesis's Table 4.2 gives the test split's; the changed split is where scenario generation should show)."""
    out = {}
    for arch in dict.fromkeys(r["architecture"] for r in runs):
        with_sg = [r for r in runs if r["architecture"] == arch and r["strength"] > 0]
        without = [r for r in runs if r["architecture"] == arch and r["strength"] == 0]
        if with_sg and without and with_sg[0][split] is not None and without[0][split]:
            out[arch] = with_sg[0][split] / without[0][split]
    return out


def start(budget: dict, digests: dict, command: str, existing: dict = None) -> dict:
    """A record for a new invocation: empty, or `existing` (when adding) checked to match."""
    if existing is None:
        return {"commands": [command], "budget": budget, "dataset_sha256": digests, "runs": [], "ratios": {},
                "leave_one_zone_out": None, "note": budget_note(budget)}
    if "budget" not in existing or "dataset_sha256" not in existing:
        raise ComparisonMismatch("the existing comparison.json does not record its budget and datasets (made before "
                                 "--add existed): its runs cannot be shown to share this run's data; run every "
                                 "architecture again without --add")
    if existing["budget"] != budget:
        raise ComparisonMismatch(f"the existing comparison.json was made with budget {existing['budget']}, this run "
                                 f"asks for {budget}: use the same options, or run every architecture again "
                                 "without --add")
    if existing["dataset_sha256"] != digests:
        raise ComparisonMismatch("the datasets made for this run differ from those of the existing comparison.json "
                                 "(krp-dataset or the world changed since): run every architecture again without "
                                 "--add")
    record = dict(existing)
    record["commands"] = list(existing["commands"]) + [command]
    return record


def add_run(record: dict, run: dict) -> None:
    """Adds `run`, replacing an earlier one of the same architecture and strength."""
    key = (run["architecture"], run["strength"])
    record["runs"] = [r for r in record["runs"] if (r["architecture"], r["strength"]) != key] + [run]
    record["ratios"] = ratios(record["runs"])


def read(folder: Path):
    path = Path(folder) / FILE_NAME
    return json.loads(path.read_text()) if path.exists() else None


def write(folder: Path, record: dict, name: str = FILE_NAME) -> Path:
    """Written whole to a side file first, so that an interrupted write leaves the last one intact."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    tmp = folder / (name + ".partial")
    tmp.write_text(json.dumps(record, indent=2) + "\n")
    return tmp.replace(folder / name)
