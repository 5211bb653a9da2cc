"""A tiny krp-train-map run: a few images, one epoch each; the pipeline must not rot."""
import json
import subprocess

import numpy as np
import onnxruntime as ort
import pytest

from krp_training import train_keypoints, train_map


def test_tiny_train_and_export(tmp_path, bin_dir):
    out = tmp_path / "office_two_zone"  # a --models-root layout, so krp-bench can use it below
    rc = train_map.main(["--world", "office_two_zone", "--out", str(out), "--work-dir", str(tmp_path / "work"),
                         "--samples-per-zone", "12", "--changed-per-zone", "3", "--classifier-epochs", "1",
                         "--keypoint-epochs", "2", "--keypoint-fine-sigma", "0.1", "--keypoint-fine-epochs", "1",
                         "--bin-dir", str(bin_dir), "--device", "cpu"])
    assert rc == 0
    assert not (tmp_path / "office_two_zone.partial").exists()
    m = json.loads((out / "manifest.json").read_text())
    assert m["zones"] == ["west_wing", "east_wing"]
    assert m["classifier"]["input"]["shape"] == [1, 1, 160, 160]
    assert m["submap"]["orientation"] == "wall_axes"  # krp-dataset's default, read by the C++ runtime
    assert m["keypoints"]["kpt_shape"] == [12, 3]
    assert m["classifier"]["ir_version"] <= 10 and m["keypoints"]["ir_version"] <= 10
    assert len(m["landmarks"]["zones"][0]["points"]) == 12
    # The zones the dataset was made with sit beside the models, for the runtime's zone search.
    assert m["zone_outlines"]["file"] == "zones.yaml"
    assert "west_wing" in (out / "zones.yaml").read_text()
    assert "krp-train-map --world office_two_zone" in m["training"]["command"]
    assert set(m["training"]["stage_seconds"]) >= {"dataset", "classifier", "keypoints", "export", "evaluate"}

    cls = ort.InferenceSession(str(out / "zone_classifier.onnx"))
    p = cls.run(None, {"occupancy": np.zeros((1, 1, 160, 160), np.float32)})[0]
    assert p.shape == (1, 2) and abs(float(p.sum()) - 1.0) < 1e-5
    kp = ort.InferenceSession(str(out / "keypoints.onnx"))
    y = kp.run(None, {"images": np.zeros((1, 3, 160, 160), np.float32)})[0]
    assert y.shape[:2] == (1, 4 + 2 + 3 * 12)

    for fig in ("classifier_curves.png", "confusion_test.png", "confusion_changed.png", "keypoint_curves.png",
                "keypoint_results.csv"):
        assert (out / "figures" / fig).stat().st_size > 0
    report = (out / "REPORT.md").read_text()
    assert "Zone classifier" in report and "Keypoint model" in report
    # Every training image is used at this size (the 600-image cap is above the split).
    n_train = m["classifier"]["metrics"]["images"]["train"]
    assert m["keypoints"]["metrics"]["train_images"] == n_train
    assert f"on {n_train} of {n_train} training images" in report
    # The keypoint loss's sigma is recorded, and every landmark's error is told apart.
    assert m["training"]["keypoint_params"]["oks_sigma"] == train_keypoints.KeypointParams.oks_sigma
    assert (m["training"]["keypoint_params"]["fine_oks_sigma"], m["training"]["keypoint_params"]["fine_epochs"]) == (0.1, 1)
    assert f"loss sigma {train_keypoints.KeypointParams.oks_sigma:g}, then 0.1 for the last 1 epochs" in report
    assert "per_landmark" in m["keypoints"]["metrics"]["test"]["keypoint_error"]
    assert "Landmarks not learned" in report
    # The classifier's test accuracy is told apart by distance to another zone; the bands count every image.
    bands = m["classifier"]["metrics"]["by_border_distance"]["test"]
    assert sum(b["images"] for b in bands) == m["classifier"]["metrics"]["images"]["test"]
    assert "distance to another zone" in report

    # The C++ runtime reads what Python wrote.
    res = subprocess.run([str(bin_dir / "krp-infer"), "--models", str(out), "--latency", "3"], capture_output=True,
                         text=True)
    assert res.returncode == 0, res.stderr
    assert json.loads(res.stdout)["models"][0]["sha256"] == m["classifier"]["sha256"]

    # The C++ relocalizer runs these (wall-aligned) models inside the seeded filter: four turns of
    # the submap through the classifier, the keypoint model on the top ones, verification.
    res = subprocess.run([str(bin_dir / "krp-bench"), "--worlds", "office_two_zone", "--world-dir",
                          str(train_map.REPO_ROOT / "sim_worlds"), "--methods", "seeded", "--models-root",
                          str(tmp_path), "--trials", "1", "--steps", "1", "--out", str(tmp_path / "bench")],
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    trials = (tmp_path / "bench" / "trials.csv").read_text().splitlines()
    assert len(trials) == 2 and ",seeded," in trials[1]


def test_existing_output_survives_a_failed_run(tmp_path, bin_dir):
    out = tmp_path / "models"
    out.mkdir()
    (out / "keep.txt").write_text("previous models")
    try:
        train_map.main(["--world", "no_such_world", "--out", str(out), "--work-dir", str(tmp_path / "work"),
                        "--bin-dir", str(bin_dir)])
    except subprocess.CalledProcessError:
        pass
    assert (out / "keep.txt").read_text() == "previous models"


def test_a_negative_keypoint_loss_sigma_is_refused_before_any_work(tmp_path, bin_dir, capsys):
    with pytest.raises(SystemExit):
        train_map.main(["--world", "office_two_zone", "--out", str(tmp_path / "m"), "--work-dir",
                        str(tmp_path / "work"), "--keypoint-loss-sigma", "-1", "--bin-dir", str(bin_dir)])
    assert "--keypoint-loss-sigma must be >= 0" in capsys.readouterr().err
    assert not (tmp_path / "work").exists() and not (tmp_path / "m.partial").exists()


@pytest.mark.parametrize("flags, says", [
    (["--keypoint-fine-sigma", "-0.1"], "--keypoint-fine-sigma must be >= 0"),
    (["--keypoint-epochs", "10", "--keypoint-fine-epochs", "11"], "--keypoint-fine-epochs must be in [0, --keypoint-epochs = 10], not 11"),
])
def test_a_sigma_schedule_that_cannot_run_is_refused_before_any_work(tmp_path, bin_dir, capsys, flags, says):
    with pytest.raises(SystemExit):
        train_map.main(["--world", "office_two_zone", "--out", str(tmp_path / "m"), "--work-dir",
                        str(tmp_path / "work"), "--bin-dir", str(bin_dir)] + flags)
    assert says in capsys.readouterr().err
    assert not (tmp_path / "work").exists() and not (tmp_path / "m.partial").exists()


@pytest.mark.parametrize("flag, value, says", [
    ("--classifier-epochs", "0", "--classifier-epochs must be 1 or more, not 0"),
    ("--samples-per-zone", "-5", "--samples-per-zone must be 1 or more, not -5"),
    ("--keypoint-train-images", "-1", "--keypoint-train-images must be 0 or more, not -1"),
    ("--seed", "-2", "--seed must be 0 or more, not -2"),
    ("--strength", "-0.5", "--strength must be >= 0 (0 = off), not -0.5"),
])
def test_a_bad_count_is_refused_before_any_work(tmp_path, bin_dir, capsys, flag, value, says):
    with pytest.raises(SystemExit):
        train_map.main(["--world", "office_two_zone", "--out", str(tmp_path / "m"), "--work-dir",
                        str(tmp_path / "work"), flag, value, "--bin-dir", str(bin_dir)])
    assert says in capsys.readouterr().err
    assert not (tmp_path / "work").exists() and not (tmp_path / "m.partial").exists()


def test_the_help_shows_no_empty_defaults(capsys):
    with pytest.raises(SystemExit):
        train_map.parse_args(["--help"])
    text = capsys.readouterr().out
    assert "(default: None)" not in text
    assert "(default: 4000)" in text


def test_a_map_file_without_zones_is_zoned_and_trained(tmp_path, bin_dir):
    """A new user's path: a map file only (no world, no zones), so the zones are made automatically."""
    map_file = train_map.REPO_ROOT / "sim_worlds" / "office_two_zone" / "office_two_zone.yaml"
    out = tmp_path / "my_floor"
    rc = train_map.main(["--map", str(map_file), "--out", str(out), "--work-dir", str(tmp_path / "work"),
                         "--samples-per-zone", "6", "--changed-per-zone", "2", "--classifier-epochs", "1",
                         "--keypoint-epochs", "1", "--bin-dir", str(bin_dir), "--device", "cpu"])
    assert rc == 0
    m = json.loads((out / "manifest.json").read_text())
    assert m["map"]["file"] == "office_two_zone.yaml"
    assert m["lidar"]["name"] == "omni_12m"  # the default for --map
    assert len(m["zones"]) >= 2 and all(z.startswith("zone_") for z in m["zones"]), m["zones"]
    assert len(m["landmarks"]["zones"]) == len(m["zones"])
    zones_yaml = (out / "zones.yaml").read_text()
    assert all(z in zones_yaml for z in m["zones"])
    assert "krp-train-map --map" in m["training"]["command"]
    cls = ort.InferenceSession(str(out / "zone_classifier.onnx"))
    p = cls.run(None, {"occupancy": np.zeros((1, 1, 160, 160), np.float32)})[0]
    assert p.shape == (1, len(m["zones"]))
    res = subprocess.run([str(bin_dir / "krp-infer"), "--models", str(out), "--latency", "1"], capture_output=True,
                         text=True)
    assert res.returncode == 0, res.stderr


def test_a_users_own_lidar_profile_goes_with_the_models(tmp_path, bin_dir):
    """A scanner no built-in profile matches (180 deg, as a SICK LMS): its profile file trains the
    models, is kept beside them, and renders fresh submaps for them (what krp-recheck-models runs)."""
    from krp_training import manifest as manifest_io
    profile = tmp_path / "front_sick.yaml"
    profile.write_text("fov_deg: 180\nbeams: 361\nmax_range_m: 12\nrange_noise_std_m: 0.02\nmount_x_m: 0.2\n")
    map_file = train_map.REPO_ROOT / "sim_worlds" / "office_two_zone" / "office_two_zone.yaml"
    out = tmp_path / "sick_floor"
    rc = train_map.main(["--map", str(map_file), "--lidar", str(profile), "--out", str(out), "--work-dir",
                         str(tmp_path / "work"), "--samples-per-zone", "6", "--changed-per-zone", "2",
                         "--classifier-epochs", "1", "--keypoint-epochs", "1", "--bin-dir", str(bin_dir),
                         "--device", "cpu"])
    assert rc == 0
    m = json.loads((out / "manifest.json").read_text())
    lidar = m["lidar"]
    assert lidar["name"] == "front_sick" and lidar["from_file"] is True
    assert lidar["fov_deg"] == pytest.approx(180.0) and lidar["beams"] == 361 and lidar["mount_x_m"] == 0.2
    assert lidar["profile_file"] == "lidar.yaml" and "fov_deg: 180" in (out / "lidar.yaml").read_text()
    args = manifest_io.rendering_args(m, out)
    assert args[:2] == ["--lidar", str(out / "lidar.yaml")]
    with pytest.raises(ValueError, match="profile file"):
        manifest_io.rendering_args(m)
    fresh = subprocess.run([str(bin_dir / "krp-dataset"), "--map", str(map_file), "--zones", str(out / "zones.yaml"),
                            *args, "--out", str(tmp_path / "fresh"), "--samples-per-zone", "1",
                            "--changed-per-zone", "1"], capture_output=True, text=True)
    assert fresh.returncode == 0, fresh.stderr
    card = json.loads((tmp_path / "fresh" / "dataset_card.json").read_text())
    assert card["lidar"]["name"] == "front_sick" and card["lidar"]["beams"] == 361


def test_the_estimate_scales_with_images_and_epochs():
    one = train_map.estimate_rest_s(1000, 10, 600, 40)
    assert one["classifier"] == 1000 * 10 * train_map.SECONDS_PER_IMAGE_EPOCH["compact"]
    assert one["keypoints"] == 600 * 40 * train_map.SECONDS_PER_IMAGE_EPOCH["yolo"]
    double = train_map.estimate_rest_s(2000, 10, 600, 80)
    assert double["classifier"] == 2 * one["classifier"] and double["keypoints"] == 2 * one["keypoints"]


def test_the_estimate_scales_with_the_machines_measured_slowdown():
    one = train_map.estimate_rest_s(1000, 10, 600, 40)
    slower = train_map.estimate_rest_s(1000, 10, 600, 40, slowdown=3.0)
    assert slower["classifier"] == pytest.approx(3 * one["classifier"])
    assert slower["keypoints"] == pytest.approx(3 * one["keypoints"])
    for bad in (0.0, -1.0, float("nan")):
        with pytest.raises(ValueError, match="slowdown"):
            train_map.estimate_rest_s(1000, 10, 600, 40, slowdown=bad)


def test_the_speed_probe_times_a_real_training_step():
    from krp_training import machine_speed
    small = machine_speed.probe_step_seconds(input_px=32, steps=2)
    assert 0 < small < 10
    # Twenty-five times the pixels cannot train faster: the probe measures work, not a constant.
    large = machine_speed.probe_step_seconds(input_px=160, steps=2)
    assert large > small
    with pytest.raises(ValueError, match="steps"):
        machine_speed.probe_step_seconds(steps=0)
    # A submap side the compact classifier cannot take is probed at the nearest one it can.
    assert machine_speed.probe_step_seconds(input_px=150, steps=1) > 0


def test_short_estimates_read_in_seconds_and_long_ones_in_minutes():
    from krp_training.stage_timer import duration
    assert duration(14.4) == "14 s"
    assert duration(89) == "89 s"
    assert duration(90) == "1.5 min"
    assert duration(1824) == "30.4 min"
