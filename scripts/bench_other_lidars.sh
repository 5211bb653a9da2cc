#!/usr/bin/env bash
# Regenerates the relocalization reports for the other lidar profiles (issue 4), office_two_zone,
# 100 trials, 10 updates, the same trial seeds as scripts/bench_relocalization.sh:
#   lds01 (the thesis robot's 360 deg 3.5 m lidar): every method, the seeded ones with the models
#         trained for it (models/office_two_zone_lds01: krp-train-map --world office_two_zone
#         --lidar lds01 --out models/office_two_zone_lds01)              -> reports/relocalization/office_two_zone_lds01
#         with the path check (--path-ambiguity: what the scans allow a method on each trial)
#   safety_270 (270 deg 25 m, front-mounted): every method, the seeded ones with the models
#         trained for it (models/office_two_zone_safety_270: krp-train-map --world office_two_zone
#         --lidar safety_270 --out models/office_two_zone_safety_270)
#         with the path check                                            -> reports/relocalization/office_two_zone_safety_270
# Usage: scripts/bench_other_lidars.sh [lds01|safety_270|all] [extra krp-bench flags]
# (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
which="${1:-all}"
[[ $# -gt 0 ]] && shift
case "$which" in lds01|safety_270|all) ;; *) echo "usage: $0 [lds01|safety_270|all] [krp-bench flags]" >&2; exit 2;; esac
bench=./build/mrpt_krp_plugin/apps/krp-bench
common=(--worlds office_two_zone --models-root models --steps 10 --seed 1 --trials 100)
methods=uniform-mcl,amcl-kld,seeded,seeded-no-cross-check,seeded-no-guard,seeded-keypoints-only,global-matcher
if [[ "$which" == all || "$which" == lds01 ]]; then
  "$bench" "${common[@]}" --lidars lds01 --path-ambiguity --methods "$methods" \
    --out reports/relocalization/office_two_zone_lds01 "$@"
fi
if [[ "$which" == all || "$which" == safety_270 ]]; then
  "$bench" "${common[@]}" --lidars safety_270 --path-ambiguity --methods "$methods" \
    --out reports/relocalization/office_two_zone_safety_270 "$@"
fi
