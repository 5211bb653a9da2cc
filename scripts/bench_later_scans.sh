#!/usr/bin/env bash
# A seeded filter that relocalizes later scans while unsure of its pose (`seeded-later-scans`,
# MclParams::later_scans) against one seeded from its first scan alone (`seeded`), side by side
# in one krp-bench run per world: same trials and seeds as scripts/bench_relocalization.sh, 360
# deg 12 m lidar, 10 updates, 100 trials, with the path check (what the scans allow).
#   office_two_zone -> reports/later_scans/office_two_zone (~3 min on 2 idle cores)
#   warehouse       -> reports/later_scans/warehouse (~12 min)
#   lds01: office_two_zone with the thesis robot's 360 deg 3.5 m lidar and its models
#          (models/office_two_zone_lds01), the trials of scripts/bench_other_lidars.sh lds01
#                   -> reports/later_scans/office_two_zone_lds01 (~4 min)
# Usage: scripts/bench_later_scans.sh [office|warehouse|lds01|all] [extra krp-bench flags]
# (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
which="${1:-all}"
[[ $# -gt 0 ]] && shift
case "$which" in office|warehouse|lds01|all) ;; *) echo "usage: $0 [office|warehouse|lds01|all] [krp-bench flags]" >&2; exit 2;; esac
bench=./build/mrpt_krp_plugin/apps/krp-bench
common=(--models-root models --steps 10 --seed 1 --trials 100 --path-ambiguity --methods seeded,seeded-later-scans)
if [[ "$which" == all || "$which" == office ]]; then
  "$bench" --worlds office_two_zone --lidars omni_12m "${common[@]}" --out reports/later_scans/office_two_zone "$@"
fi
if [[ "$which" == all || "$which" == warehouse ]]; then
  "$bench" --worlds warehouse --lidars omni_12m "${common[@]}" --out reports/later_scans/warehouse "$@"
fi
if [[ "$which" == all || "$which" == lds01 ]]; then
  "$bench" --worlds office_two_zone --lidars lds01 "${common[@]}" --out reports/later_scans/office_two_zone_lds01 "$@"
fi
