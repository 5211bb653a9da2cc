#!/usr/bin/env bash
# Table 4.2's analogue (architectures with and without scenario generation) and the
# leave-one-zone-out check for a world; writes <models>/comparison.json and refreshes REPORT.md.
#   scripts/compare_classifiers.sh office_two_zone [extra options of krp_training.compare]
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORLD="${1:?usage: $0 WORLD [options]}"
shift
cd "$REPO_ROOT"
exec "$REPO_ROOT/.venv/bin/python" -m krp_training.compare --world "$WORLD" --out "models/$WORLD" "$@"
