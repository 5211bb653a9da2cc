#!/usr/bin/env bash
# Regenerates the committed degenerate-scene report (issue 6): scenes where any method should say
# "not localized" rather than guess. A 60 m featureless corridor, an empty 40 x 30 m hall, and
# office_two_zone under heavy unmapped clutter (sim_worlds/office_cluttered). 30 trials, 10 steps,
# 360 deg 12 m lidar (~10 min on 2 cores). global-matcher-guarded is the matcher-seeded filter with
# the look-alike guard, as the ROS node tracks by default. The report's relocalizer table gives the relocalizer's
# own confident-but-wrong rate ("localized but wrong"); the main table gives the filters'.
# Usage: scripts/bench_degenerate.sh [extra krp-bench flags]   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
./build/mrpt_krp_plugin/apps/krp-bench --worlds corridor,empty_hall,office_cluttered --lidars omni_12m \
  --methods uniform-mcl,amcl-kld,global-matcher,global-matcher-guarded --trials 30 --steps 10 --seed 1 --out reports/degenerate "$@"
