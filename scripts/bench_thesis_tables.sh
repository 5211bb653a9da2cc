#!/usr/bin/env bash
# Regenerates the thesis's comparisons with classical methods (issue 4: its Tables 4.4 and 4.5) for
# the shipped models: SIFT and ORB zoning against the CNN, ICP from the zone's centre against the
# keypoint alignment. 30 reference and 100 held-out submaps per zone, seed 1, scenes with the
# world's unmapped clutter.   -> reports/thesis_tables/<world>/REPORT.md, samples.csv
# Usage: scripts/bench_thesis_tables.sh [office|warehouse|all] [extra krp-thesis-tables flags]
# (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
which="${1:-all}"
[[ $# -gt 0 ]] && shift
case "$which" in office|warehouse|all) ;; *) echo "usage: $0 [office|warehouse|all] [krp-thesis-tables flags]" >&2; exit 2;; esac
tables=./build/mrpt_krp_plugin/apps/krp-thesis-tables
common=(--references 30 --tests 100 --seed 1)
if [[ "$which" == all || "$which" == office ]]; then
  "$tables" --world office_two_zone --models models/office_two_zone "${common[@]}" \
    --out reports/thesis_tables/office_two_zone "$@"
fi
if [[ "$which" == all || "$which" == warehouse ]]; then
  "$tables" --world warehouse --models models/warehouse "${common[@]}" --out reports/thesis_tables/warehouse "$@"
fi
