#!/usr/bin/env bash
# Regenerates the committed scaling study (issue 4): what localizing from nothing costs as the free
# area grows, office_two_zone (713 m^2) -> warehouse (2,313 m^2) -> large_floor (5,217 m^2), for
# uniform MCL (particles by density), the global-matcher relocalizer seeding the filter, and the
# seeded method with each world's shipped models (models/<world>).
# 10 trials, 5 steps, 360 deg 12 m lidar, seed 3 (~3 min on 2 idle cores). The report's last section
# has the table and scaling.png.
# Usage: scripts/bench_scaling.sh [extra krp-bench flags]   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
./build/mrpt_krp_plugin/apps/krp-bench --worlds office_two_zone,warehouse,large_floor --lidars omni_12m \
  --methods uniform-mcl,global-matcher,seeded --models-root models --trials 10 --steps 5 --seed 3 --out reports/scaling "$@"
