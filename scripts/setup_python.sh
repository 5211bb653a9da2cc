#!/usr/bin/env bash
# Creates the project's Python environment for training (models/training) in <repo>/.venv.
# Idempotent: when the pinned set is already installed it returns in a second.
# Uses Debian's python3-venv (installed by install_deps.sh); never installs system-wide.
#
# Environment:
#   KRP_VENV   where the environment lives (default: <repo>/.venv)
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="${KRP_VENV:-$REPO_ROOT/.venv}"
REQS="$REPO_ROOT/models/training/requirements.txt"
STAMP="$VENV/.krp-requirements.sha256"

# The system interpreter, not a pyenv shim: Debian's venv module is what install_deps.sh provides.
PYTHON=/usr/bin/python3
[ -x "$PYTHON" ] || PYTHON="$(command -v python3)"

want="$(sha256sum "$REQS" | cut -d' ' -f1)"
if [ -x "$VENV/bin/python" ] && [ "$(cat "$STAMP" 2>/dev/null)" = "$want" ]; then
  echo "[setup_python] $VENV: pinned training stack present"
  exit 0
fi

# torch's CUDA wheels install to ~6 GB; pip unpacks each wheel beside it, so ask for headroom.
REQUIRED_FREE_GB="${KRP_VENV_REQUIRED_FREE_GB:-8}"
venv_parent="$(dirname "$VENV")"
mkdir -p "$venv_parent"
free_gb=$(( $(df -Pk "$venv_parent" | awk 'NR==2 {print $4}') / 1024 / 1024 ))
if [ "$free_gb" -lt "$REQUIRED_FREE_GB" ]; then
  echo "[setup_python] error: $venv_parent has ${free_gb} GB free; the training stack needs about ${REQUIRED_FREE_GB} GB" >&2
  echo "[setup_python] free space there, or set KRP_VENV to a roomier place" >&2
  exit 1
fi

echo "[setup_python] creating $VENV (torch from PyPI is a ~3 GB download; a few minutes)"
"$PYTHON" -m venv "$VENV"
# --no-cache-dir: a cached copy of every wheel would cost another ~3 GB for a one-off install.
"$VENV/bin/python" -m pip install -q --no-cache-dir --upgrade pip
"$VENV/bin/python" -m pip install --no-cache-dir --progress-bar on -r "$REQS"
"$VENV/bin/python" -m pip install -q --no-cache-dir --no-deps -e "$REPO_ROOT/models/training"
echo "$want" > "$STAMP"
echo "[setup_python] done: $("$VENV/bin/python" -c 'import torch, ultralytics; print("torch", torch.__version__, "ultralytics", ultralytics.__version__)')"
