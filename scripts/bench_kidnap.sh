#!/usr/bin/env bash
# Regenerates the committed kidnap-mid-run reports (issue 4): the robot tracks for 6 steps, is
# carried at least 5 m away with no odometry for the carry, and walks on for 14 more; every method
# runs with the filter's kidnap detector on and re-runs its own initializer when it fires; the
# seeded methods (shipped models) re-run the relocalizer, seeded with the look-alike guard and
# seeded-no-guard without it.
# 20 trials per world, 360 deg 12 m lidar, seed 1. uniform-mcl runs on office_two_zone only: on the
# warehouse (92,000 particles per initialization) it alone would take most of an hour.
# (~3 min on 2 idle cores.)
# Usage: scripts/bench_kidnap.sh [extra krp-bench flags]   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
common=(--lidars omni_12m --trials 20 --steps 20 --kidnap-at 6 --seed 1)
./build/mrpt_krp_plugin/apps/krp-bench --worlds office_two_zone \
  --methods uniform-mcl,amcl-kld,seeded,seeded-no-guard,global-matcher --models-root models \
  "${common[@]}" --out reports/kidnap/office_two_zone "$@"
./build/mrpt_krp_plugin/apps/krp-bench --worlds warehouse --methods amcl-kld,seeded,seeded-no-guard,global-matcher \
  --models-root models \
  "${common[@]}" --out reports/kidnap/warehouse "$@"
