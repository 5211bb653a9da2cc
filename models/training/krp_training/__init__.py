"""mrpt_krp_plugin training package (AGPL-3.0: it imports ultralytics)."""
