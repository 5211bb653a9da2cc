"""The model report's line on the zone outlines beside the models (report.py)."""
from krp_training import report


def test_the_report_names_the_zone_outlines_beside_the_models():
    m = {"zone_outlines": {"file": "zones.yaml", "sha256": "ab" * 32}}
    line = report.zone_outlines_lines(m)[0]
    assert line.startswith("Zone outlines: `zones.yaml` beside the models (sha256 `abababababababab…`)")
    assert "added" not in line


def test_outlines_added_after_training_say_so():
    m = {"zone_outlines": {"file": "zones.yaml", "sha256": "cd" * 32, "added_after_training": "Copied later."}}
    assert report.zone_outlines_lines(m)[0].endswith("the relocalizer's zone search reads them. Copied later.")


def test_models_without_outlines_say_the_zone_search_needs_them():
    for m in ({}, {"zone_outlines": None}):
        line = report.zone_outlines_lines(m)[0]
        assert "none beside the models" in line and "--zones" in line and "zones_file" in line
