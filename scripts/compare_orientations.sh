#!/usr/bin/env bash
# Zone classifier accuracy on heading-up against wall-aligned submaps (same poses, seed and
# budget); writes reports/orientation/<world>/ORIENTATION.md and orientation_comparison.json.
#   scripts/compare_orientations.sh office_two_zone [extra options of krp_training.compare_orientations]
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORLD="${1:?usage: $0 WORLD [options]}"
shift
cd "$REPO_ROOT"
exec "$REPO_ROOT/.venv/bin/python" -m krp_training.compare_orientations --world "$WORLD" \
  --out "reports/orientation/$WORLD" "$@"
