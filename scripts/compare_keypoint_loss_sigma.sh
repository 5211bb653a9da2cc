#!/usr/bin/env bash
# The keypoint model trained with ultralytics' default OKS sigma and with wider ones, side by side
# (same dataset, images, seed and epochs); writes reports/keypoint_loss_sigma/<world>/LOSS_SIGMA.md
# and loss_sigma.json. About 8 min per sigma on 2 CPU cores with the defaults (600 images, 40 epochs).
#   scripts/compare_keypoint_loss_sigma.sh office_two_zone [extra options of krp_training.compare_loss_sigma]
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORLD="${1:?usage: $0 WORLD [options]}"
shift
cd "$REPO_ROOT"
exec "$REPO_ROOT/.venv/bin/python" -m krp_training.compare_loss_sigma --world "$WORLD" \
  --out "reports/keypoint_loss_sigma/$WORLD" "$@"
