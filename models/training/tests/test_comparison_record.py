"""Table 4.2's record (comparison_record.py): runs added across invocations only on the same budget and data."""
import json

import pytest

from krp_training import comparison_record, report
from krp_training.compare import main as compare_main

BUDGET = {"world": "w", "epochs": 8, "samples_per_zone": 300, "train_limit": 0, "seed": 1}
DIGESTS = {"with_scenarios": "a" * 64, "without_scenarios": "b" * 64}


def run(arch, strength, changed, val=0.5):
    return {"architecture": arch, "strength": strength, "epochs": 8, "train_images": 10, "seconds": 1.0,
            "val": val, "test": 0.5, "changed": changed}


def test_a_run_replaces_the_same_architecture_and_strength_and_the_ratio_follows():
    record = comparison_record.start(BUDGET, DIGESTS, "first")
    comparison_record.add_run(record, run("compact", 1.0, 0.8))
    assert record["ratios"] == {}  # no run without scenario generation yet
    comparison_record.add_run(record, run("compact", 0.0, 0.4))
    assert record["ratios"] == {"compact": pytest.approx(2.0)}
    comparison_record.add_run(record, run("compact", 0.0, 0.5))
    assert len(record["runs"]) == 2
    assert record["ratios"] == {"compact": pytest.approx(1.6)}
    record["runs"][0]["test"] = 0.9
    assert comparison_record.ratios(record["runs"], "test") == {"compact": pytest.approx(1.8)}


def test_adding_keeps_the_earlier_runs_and_commands():
    earlier = comparison_record.start(BUDGET, DIGESTS, "first")
    comparison_record.add_run(earlier, run("compact", 1.0, 0.8))
    record = comparison_record.start(BUDGET, DIGESTS, "second", existing=json.loads(json.dumps(earlier)))
    comparison_record.add_run(record, run("vgg16", 1.0, 0.9))
    assert record["commands"] == ["first", "second"]
    assert [r["architecture"] for r in record["runs"]] == ["compact", "vgg16"]
    assert earlier["commands"] == ["first"]  # the existing record is not changed in place


@pytest.mark.parametrize("existing, says", [
    ({"commands": ["old"], "runs": []}, "does not record its budget"),
    ({"commands": ["old"], "runs": [], "budget": {**BUDGET, "epochs": 20}, "dataset_sha256": DIGESTS}, "budget"),
    ({"commands": ["old"], "runs": [], "budget": BUDGET, "dataset_sha256": {**DIGESTS, "without_scenarios": "c"}},
     "datasets made for this run differ"),
])
def test_runs_on_another_budget_or_other_data_are_refused(existing, says):
    with pytest.raises(comparison_record.ComparisonMismatch, match=says):
        comparison_record.start(BUDGET, DIGESTS, "new", existing=existing)


def test_the_dataset_digest_sees_a_changed_image_and_a_moved_one(tmp_path):
    images = tmp_path / "classifier" / "train" / "zone_a"
    images.mkdir(parents=True)
    (images / "0.png").write_bytes(b"\x00\x01")
    (tmp_path / "dataset_card.json").write_text("{}")
    first = comparison_record.dataset_digest(tmp_path)
    (tmp_path / "dataset_card.json").write_text('{"other": 1}')  # not an image: not part of the digest
    assert comparison_record.dataset_digest(tmp_path) == first
    (images / "0.png").write_bytes(b"\x00\x02")
    changed = comparison_record.dataset_digest(tmp_path)
    assert changed != first
    (images / "0.png").rename(images / "1.png")
    assert comparison_record.dataset_digest(tmp_path) not in (first, changed)


def test_a_write_leaves_only_the_finished_file(tmp_path):
    record = comparison_record.start(BUDGET, DIGESTS, "first")
    comparison_record.write(tmp_path, record)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["comparison.json"]
    assert comparison_record.read(tmp_path) == record


def test_the_report_lists_every_command_and_the_runs_in_the_thesis_order():
    record = comparison_record.start(BUDGET, DIGESTS, "python -m krp_training.compare --architectures vgg16")
    record["commands"].append("python -m krp_training.compare --add --architectures compact")
    for r in (run("vgg16", 0.0, 0.4), run("vgg16", 1.0, 0.8), run("compact", 1.0, 0.7)):
        comparison_record.add_run(record, r)
    text = "\n".join(report.comparison_lines(record))
    assert "- `python -m krp_training.compare --architectures vgg16`" in text
    assert "- `python -m krp_training.compare --add --architectures compact`" in text
    rows = [line for line in text.splitlines() if line.startswith("| compact |") or line.startswith("| vgg16 |")]
    assert [row.split("|")[1:3] for row in rows[:3]] == [[" compact ", " with "], [" vgg16 ", " with "],
                                                          [" vgg16 ", " without "]]
    assert "`aaaaaaaaaaaaaaaa…`" in text and "| vgg16 | 1.00 | 2.00 |" in text


def test_an_unknown_architecture_is_refused_before_any_work(tmp_path, capsys):
    with pytest.raises(SystemExit) as e:
        compare_main(["--world", "w", "--out", str(tmp_path), "--architectures", "compact,resnet50"])
    assert e.value.code == 2
    assert "unknown ['resnet50']" in capsys.readouterr().err
    assert not any(tmp_path.iterdir())


def test_each_architecture_latency_is_measured_on_its_exported_graph(tmp_path):
    from krp_training import architecture_latency
    t = architecture_latency.measure("compact", 64, runs=5, warmup=1, work_dir=tmp_path)
    assert t["runs"] == 5 and 0 < t["median"] <= t["p90"] and t["onnx_bytes"] > 0
    assert (tmp_path / "compact.onnx").exists()


def test_the_report_shows_the_latency_in_the_thesis_order():
    record = comparison_record.start(BUDGET, DIGESTS, "first")
    record["latency_ms"] = {"vgg16": {"runs": 200, "median": 90.0, "p90": 95.0, "onnx_bytes": 58_800_000},
                            "compact": {"runs": 200, "median": 0.5, "p90": 0.6, "onnx_bytes": 400_000}}
    record["latency_command"] = "python -m krp_training.architecture_latency --out m"
    lines = report.comparison_lines(record)
    rows = [line for line in lines if line.startswith("| compact | 0.4 MB") or line.startswith("| vgg16 | 58.8 MB")]
    assert rows == ["| compact | 0.4 MB | 0.50 ms | 0.60 ms | 200 |", "| vgg16 | 58.8 MB | 90.00 ms | 95.00 ms | 200 |"]


def test_latency_needs_a_comparison_to_add_to(tmp_path, capsys):
    from krp_training import architecture_latency
    with pytest.raises(SystemExit) as e:
        architecture_latency.main(["--out", str(tmp_path), "--architectures", "compact"])
    assert e.value.code == 2 and "run krp_training.compare first" in capsys.readouterr().err


def test_the_report_says_how_much_one_image_moves_each_accuracy():
    record = comparison_record.start(BUDGET, DIGESTS, "first")
    record["split_images"] = {"val": 120, "test": 104, "changed": 60}
    text = "\n".join(report.comparison_lines(record))
    assert "120 / 104 / 60 images, so one image moves it by 0.8 / 1.0 / 1.7 points." in text


def test_the_budget_note_says_how_many_images_trained():
    assert "training on the whole training split, seed 1;" in comparison_record.budget_note(BUDGET)
    assert "at most 500 of the training split's images" in comparison_record.budget_note({**BUDGET, "train_limit": 500})
