"""Keeps ultralytics off the network and out of the user's home directory.

Must be imported before ultralytics: ultralytics reads these variables at import time.
Every setting here was needed on a machine without internet (see shared/notes/dependencies.md).
"""
import os
import shutil
from pathlib import Path

# A DejaVu font ships with matplotlib; ultralytics insists on finding "Arial.ttf" before plotting.
_FONT_NAME = "Arial.ttf"


def configure(config_dir: Path) -> None:
    """Points ultralytics at config_dir, disables its network probes, and provides its font."""
    config_dir = Path(config_dir).resolve()
    config_dir.mkdir(parents=True, exist_ok=True)
    os.environ["YOLO_CONFIG_DIR"] = str(config_dir)
    os.environ["YOLO_OFFLINE"] = "1"
    os.environ["YOLO_AUTOINSTALL"] = "0"
    os.environ.setdefault("YOLO_VERBOSE", "False")
    font_dir = config_dir / "Ultralytics"
    font_dir.mkdir(parents=True, exist_ok=True)
    font = font_dir / _FONT_NAME
    if not font.exists():
        import matplotlib

        dejavu = Path(matplotlib.get_data_path()) / "fonts" / "ttf" / "DejaVuSans.ttf"
        shutil.copyfile(dejavu, font)


def default_config_dir() -> Path:
    return Path(os.environ.get("KRP_YOLO_CONFIG_DIR", Path.cwd() / "out" / "ultralytics-config"))
