#!/usr/bin/env bash
# Regenerates the committed calibration check (issue 4): does the relocalizer's confidence mean
# what it says, and does a calibration fitted on held-out trials make it so? Per world, the
# global-matcher relocalizer answers 100 first scans (no motion: --steps 0, 360 deg 12 m lidar):
#   1. a Platt calibration fitted on seed 11          -> reports/calibration/<world>.calibration.yaml
#   2. raw confidences on seed 7                      -> reports/calibration/<world>/raw/REPORT.md
#   3. the same seed-7 trials with the calibration    -> reports/calibration/<world>/calibrated/REPORT.md
# Each world runs alone, because trial seeds depend on a world's place in the run: 2 and 3 replay
# the same trials. The reports' reliability tables bin the best hypothesis's confidence against
# how often it was right. The learned relocalizer (`seeded`: shipped models, zone search and
# cross-check) gets
# the same treatment on the worlds that have models, under reports/calibration/learned/
# (~40 min on 2 cores in all, most of it the warehouse).
# Usage: scripts/bench_calibration.sh [matcher|learned|all] [extra krp-bench flags]
# (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
which="${1:-all}"
[[ $# -gt 0 ]] && shift
case "$which" in matcher|learned|all) ;; *) echo "usage: $0 [matcher|learned|all] [krp-bench flags]" >&2; exit 2;; esac
bench=./build/mrpt_krp_plugin/apps/krp-bench
extra=("$@")
# fit on seed 11, then seed 7 raw and calibrated, for one world and relocalizer.
#   $1: folder of the reports and calibration, $2: folder of the fit run, $3: world, rest: krp-bench flags
calibrate() {
  local reports="$1" fit_out="$2" w="$3"
  shift 3
  "$bench" --worlds "$w" "$@" --seed 11 --out "$fit_out/$w" --fit-calibration "$reports/$w.calibration.yaml" "${extra[@]}"
  "$bench" --worlds "$w" "$@" --seed 7 --out "$reports/$w/raw" "${extra[@]}"
  "$bench" --worlds "$w" "$@" --seed 7 --out "$reports/$w/calibrated" --calibration "$reports/$w.calibration.yaml" "${extra[@]}"
}
if [[ "$which" == all || "$which" == matcher ]]; then
  for w in office_two_zone warehouse office_cluttered; do
    calibrate reports/calibration out/calibration_fit "$w" --lidars omni_12m --methods global-matcher --trials 100 --steps 0
  done
fi
if [[ "$which" == all || "$which" == learned ]]; then
  for w in office_two_zone warehouse; do
    calibrate reports/calibration/learned out/calibration_fit/learned "$w" \
      --lidars omni_12m --methods seeded --models-root models --trials 100 --steps 0
  done
fi
