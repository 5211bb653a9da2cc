#!/usr/bin/env bash
# Regenerates the committed calibration check (issue 4): does the relocalizer's confidence mean
# what it says? 100 first scans per world (no motion: --steps 0), the global-matcher relocalizer,
# 360 deg 12 m lidar, seed 7, which no threshold was chosen on. The report's reliability tables
# bin the best hypothesis's confidence against how often it was right (~10 min on 2 cores).
# Usage: scripts/bench_calibration.sh [extra krp-bench flags]   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
./build/mrpt_krp_plugin/apps/krp-bench --worlds office_two_zone,warehouse,office_cluttered --lidars omni_12m \
  --methods global-matcher --trials 100 --steps 0 --seed 7 --out reports/calibration "$@"
