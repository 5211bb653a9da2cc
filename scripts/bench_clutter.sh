#!/usr/bin/env bash
# Regenerates the committed heavy-clutter report (issue 6): the office under unmapped boxes,
# pallets and people (sim_worlds/office_cluttered: office_two_zone's map and zones), with every
# method, the learned one included. The seeded methods run the models trained on the clean
# office (models/office_two_zone, named with --models-for): what they meet here is a changed
# environment, 15 times the box density of their training scenes. A second run repeats the methods with the look-alike guard without its fit
# floor (--guard-min-fit-fraction 0), to show what the floor does. 100 trials, 10 steps,
# 360 deg 12 m lidar (about 12 min).
# Usage: scripts/bench_clutter.sh [extra krp-bench flags]   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bench=./build/mrpt_krp_plugin/apps/krp-bench
common=(--worlds office_cluttered --lidars omni_12m --models-for office_cluttered=models/office_two_zone --trials 100 --steps 10 --seed 1)
"$bench" "${common[@]}" \
  --methods uniform-mcl,amcl-kld,seeded,seeded-no-guard,seeded-keypoints-only,global-matcher,global-matcher-guarded \
  --out reports/clutter "$@"
"$bench" "${common[@]}" --methods seeded,global-matcher-guarded --guard-min-fit-fraction 0 \
  --out reports/clutter/no_fit_floor "$@"
