"""compare_keypoint_budget: runs named as images x epochs, and its table."""
import pytest


def _split(mean, landmark_medians=(0.2, 0.3)):
    return {"box": {"map50": 0.9}, "pose": {"map50": 0.8, "map50_95": 0.6},
            "keypoint_error": {"mean_error_m": mean, "median_error_m": 0.3, "right_zone": 90, "images": 100,
                               "unlearned_landmarks": [],
                               "per_landmark": [{"zone": "a", "keypoint": k, "median_m": m}
                                                for k, m in enumerate(landmark_medians)]}}


@pytest.mark.parametrize("text, budget", [("600x40", (600, 40)), ("2400X10", (2400, 10))])
def test_a_run_is_images_by_epochs(text, budget):
    from krp_training.compare_keypoint_budget import parse_budget

    b = parse_budget(text)
    assert (b["train_images"], b["epochs"]) == budget


@pytest.mark.parametrize("budgets", ["600", "600x40x2", "0x40", "600x0", "ax40", "600x40,"])
def test_the_comparison_refuses_a_run_it_cannot_train(budgets, capsys):
    from krp_training.compare_keypoint_budget import parse_args

    with pytest.raises(SystemExit):
        parse_args(["--world", "w", "--out", "o", "--budgets", budgets])
    assert "--budgets" in capsys.readouterr().err


def test_the_table_gives_each_runs_image_passes_and_metrics():
    from krp_training.compare_keypoint_budget import markdown

    runs = [{"train_images": 600, "epochs": 40, "seconds": 372.4, "test": _split(0.61), "changed": _split(1.1)},
            {"train_images": 1200, "epochs": 20, "seconds": 380.0, "test": _split(0.5), "changed": _split(0.9)}]
    text = markdown({"world": "w", "command": "python -m krp_training.compare_keypoint_budget --world w",
                     "dataset_command": "krp-dataset --world w", "seed": 1, "runs": runs})
    assert "| 600 | 40 | 24,000 | test | 0.900 | 0.800 | 0.600 | 0.610 m | 0.300 m | 90 of 100 | 0: none | 372 |" in text
    assert "| 1200 | 20 | 24,000 | changed | 0.900 | 0.800 | 0.600 | 0.900 m |" in text
    header, rule = [line for line in text.splitlines() if line.startswith("| training images") or line.startswith("|---")]
    assert header.count("|") == rule.count("|")


def test_each_run_is_compared_landmark_by_landmark_with_the_first():
    from krp_training.compare_keypoint_budget import markdown

    runs = [{"train_images": 600, "epochs": 40, "seconds": 1.0, "test": _split(0.6, (0.2, 0.3, 0.4)),
             "changed": _split(1.0, (0.5, 0.5))},
            {"train_images": 2400, "epochs": 10, "seconds": 1.0, "test": _split(0.7, (0.25, 0.3, 0.5)),
             "changed": _split(0.9, (0.4,))}]
    text = markdown({"world": "w", "command": "c", "dataset_command": "d", "seed": 1, "runs": runs})
    assert "- test, 2400 x 10: 2 of 3 higher" in text  # equal is not higher
    assert "- changed, 2400 x 10: 0 of 1 higher" in text  # only landmarks both runs measured


def test_a_run_that_fails_keeps_the_runs_before_it(tmp_path, monkeypatch):
    """Hours of training are not lost to a failure in a later run."""
    import json

    from krp_training import compare_keypoint_budget, keypoint_trials

    monkeypatch.setattr(keypoint_trials, "make_dataset",
                        lambda *a, **k: ({"submap": {"rotation": "wall_axes"}}, ["krp-dataset", "--world", "w"]))
    monkeypatch.setattr(compare_keypoint_budget, "max_rotation_deg", lambda card: 3.0)
    calls = []

    def train_and_measure(dataset, card, work, train_images, params):
        calls.append((train_images, params.epochs))
        if len(calls) == 2:
            raise RuntimeError("out of memory")
        return {"train_images": train_images, "seconds": 1.0, "params": {}, "test": _split(0.6),
                "changed": _split(1.0)}

    monkeypatch.setattr(keypoint_trials, "train_and_measure", train_and_measure)
    out = tmp_path / "out"
    with pytest.raises(RuntimeError, match="out of memory"):
        compare_keypoint_budget.main(["--world", "w", "--out", str(out), "--budgets", "600x40,1200x20"])
    kept = json.loads((out / "keypoint_budget.json").read_text())
    assert [(r["train_images"], r["epochs"]) for r in kept["runs"]] == [(600, 40)]
    assert "| 600 | 40 | 24,000 | test |" in (out / "KEYPOINT_BUDGET.md").read_text()
