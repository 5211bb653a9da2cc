#!/usr/bin/env bash
# Regenerates reports/see_through_speed (issue 4): the see-through charge a filter update puts on
# each particle, with the rays marched side by side (SeeThroughPenalty::Scan::count, what the
# filter and the look-alike guard run) against one at a time (countOneRayAtATime), on the same
# simulated first scans and particle clouds (krp-bench-see-through; both must count alike).
# Worlds office_two_zone and warehouse with their default lidar, 30 scans, 500 particles, seed 1
# (seconds on 2 cores).
# Usage: scripts/bench_see_through.sh   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
for world in office_two_zone warehouse; do
  ./build/mrpt_krp_plugin/apps/krp-bench-see-through --world "$world" --scans 30 --particles 500 --seed 1 \
    --out "reports/see_through_speed/$world"
done
