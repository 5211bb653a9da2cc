#!/usr/bin/env bash
# Regenerates the committed calibration check (issue 4): does the relocalizer's confidence mean
# what it says? The global-matcher relocalizer answers 100 first scans per world (no motion:
# --steps 0, 360 deg 12 m lidar):
#   1. raw confidences on seed 7, the three worlds together  -> reports/calibration/REPORT.md
#   2. per world, a Platt calibration fitted on seed 11      -> reports/calibration/<world>.calibration.yaml
#   3. per world, that calibration on seed 7 (held out)      -> reports/calibration/calibrated/<world>/REPORT.md
# The reports' reliability tables bin the best hypothesis's confidence against how often it was
# right (~25 min on 2 cores, most of it the warehouse).
# Usage: scripts/bench_calibration.sh [extra krp-bench flags]   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bench=./build/mrpt_krp_plugin/apps/krp-bench
worlds=(office_two_zone warehouse office_cluttered)
common=(--lidars omni_12m --methods global-matcher --trials 100 --steps 0)
"$bench" --worlds "$(IFS=,; echo "${worlds[*]}")" "${common[@]}" --seed 7 --out reports/calibration "$@"
for w in "${worlds[@]}"; do
  "$bench" --worlds "$w" "${common[@]}" --seed 11 --out "out/calibration_fit/$w" \
    --fit-calibration "reports/calibration/$w.calibration.yaml" "$@"
  "$bench" --worlds "$w" "${common[@]}" --seed 7 --out "reports/calibration/calibrated/$w" \
    --calibration "reports/calibration/$w.calibration.yaml" "$@"
done
