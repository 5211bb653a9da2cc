#!/usr/bin/env bash
# The seeded prior's particle count, fixed per hypothesis (`seeded`, the default: 250 per
# hypothesis, 500 to 5000 in all) against chosen from the hypotheses' spread by KLD sampling of
# the prior (`seeded-spread-count`, SeededInitParams::count_from_spread), side by side in one
# krp-bench run: same trials, same seeds, 360 deg 12 m lidar, 10 updates.
#   office_two_zone: 100 trials, into reports/spread_count/office_two_zone (~4 min on 2 idle cores)
#   warehouse:        30 trials, into reports/spread_count/warehouse (~8 min)
# Usage: scripts/bench_spread_count.sh [office|warehouse|all] [extra krp-bench flags]
# (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
which="${1:-all}"
[[ $# -gt 0 ]] && shift
case "$which" in office|warehouse|all) ;; *) echo "usage: $0 [office|warehouse|all] [krp-bench flags]" >&2; exit 2;; esac
bench=./build/mrpt_krp_plugin/apps/krp-bench
common=(--lidars omni_12m --models-root models --steps 10 --seed 1 --methods seeded,seeded-spread-count)
if [[ "$which" == all || "$which" == office ]]; then
  "$bench" --worlds office_two_zone "${common[@]}" --trials 100 --out reports/spread_count/office_two_zone "$@"
fi
if [[ "$which" == all || "$which" == warehouse ]]; then
  "$bench" --worlds warehouse "${common[@]}" --trials 30 --out reports/spread_count/warehouse "$@"
fi
