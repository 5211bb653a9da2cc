import os
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def bin_dir() -> Path:
    """The built C++ apps (CTest passes KRP_BIN_DIR; by hand, the default build folder)."""
    d = Path(os.environ.get("KRP_BIN_DIR", REPO_ROOT / "build" / "mrpt_krp_plugin" / "apps"))
    if not (d / "krp-dataset").exists():
        pytest.fail(f"{d}/krp-dataset not built: run scripts/build.sh or set KRP_BIN_DIR")
    return d
