#!/usr/bin/env bash
# Regenerates the committed relocalization report (issue 4): every initialization method on the same
# simulated kidnaps in office_two_zone (360 deg 12 m lidar), including `seeded` with the shipped
# models/office_two_zone and the `global-matcher` baseline. 30 trials, 10 steps (~5 min on 2 cores).
# Usage: scripts/bench_relocalization.sh [extra krp-bench flags]   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
./build/mrpt_krp_plugin/apps/krp-bench --worlds office_two_zone --lidars omni_12m \
  --methods uniform-mcl,amcl-kld,seeded,seeded-no-uniform,global-matcher --models-root models \
  --trials 30 --steps 10 --seed 1 --out reports/relocalization/office_two_zone "$@"
