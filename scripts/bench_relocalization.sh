#!/usr/bin/env bash
# Regenerates the committed relocalization reports (issue 4), every method on the same simulated
# kidnaps with the same seeds, 360 deg 12 m lidar, 10 updates:
#   office_two_zone: 100 trials, uniform-mcl, amcl-kld, amcl-kld-50k (does AMCL reach the seeded
#                    method's success with ten times the particles?), seeded (shipped models + zone search +
#                    cross-check, filter with the look-alike guard), seeded-no-uniform,
#                    seeded-no-cross-check, seeded-no-guard, seeded-keypoints-only (the models
#                    alone), global-matcher (~6 min on 2 idle cores);
#   warehouse:       100 trials, the same methods but amcl-kld-50k (reports/baseline/warehouse has
#                    it over 40 updates); uniform-mcl starts with 92,537 particles (~26 min).
#   large_floor:     (only when asked) 30 trials, uniform-mcl (200,000 particles, the uniform
#                    initializer's cap), amcl-kld, seeded, seeded-keypoints-only and global-matcher,
#                    into reports/relocalization/large_floor (~15 min).
#   warehouse-40:    (only when asked) the warehouse over 40 updates with uniform-mcl, amcl-kld
#                    and seeded, into reports/relocalization/warehouse_40_updates (~13 min).
# Each trial is also checked for places that explain its whole path as well as the truth
# (--path-ambiguity): the reports split every method's outcome by that verdict.
# Usage: scripts/bench_relocalization.sh [office|warehouse|all|large_floor|warehouse-40] [extra krp-bench flags]
# (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
which="${1:-all}"
[[ $# -gt 0 ]] && shift
case "$which" in office|warehouse|all|large_floor|warehouse-40) ;; *) echo "usage: $0 [office|warehouse|all|large_floor|warehouse-40] [krp-bench flags]" >&2; exit 2;; esac
bench=./build/mrpt_krp_plugin/apps/krp-bench
common=(--lidars omni_12m --models-root models --steps 10 --seed 1 --path-ambiguity)
if [[ "$which" == all || "$which" == office ]]; then
  "$bench" --worlds office_two_zone "${common[@]}" --trials 100 \
    --methods uniform-mcl,amcl-kld,amcl-kld-50k,seeded,seeded-no-uniform,seeded-no-cross-check,seeded-no-guard,seeded-keypoints-only,global-matcher \
    --out reports/relocalization/office_two_zone "$@"
fi
if [[ "$which" == all || "$which" == warehouse ]]; then
  "$bench" --worlds warehouse "${common[@]}" --trials 100 \
    --methods uniform-mcl,amcl-kld,seeded,seeded-no-uniform,seeded-no-cross-check,seeded-no-guard,seeded-keypoints-only,global-matcher \
    --out reports/relocalization/warehouse "$@"
fi
# The 26-zone floor (not part of 'all'): the seeded method where the classifier has many zones
# to tell apart and uniform MCL hits its particle cap.
if [[ "$which" == large_floor ]]; then
  "$bench" --worlds large_floor "${common[@]}" --trials 30 \
    --methods uniform-mcl,amcl-kld,seeded,seeded-keypoints-only,global-matcher \
    --out reports/relocalization/large_floor "$@"
fi
# The warehouse over 40 updates (not part of 'all', ~13 min): what moving buys where 10 updates
# leave most trials ambiguous.
if [[ "$which" == warehouse-40 ]]; then
  "$bench" --worlds warehouse --lidars omni_12m --models-root models --steps 40 --seed 1 --path-ambiguity --trials 30 \
    --methods uniform-mcl,amcl-kld,seeded --out reports/relocalization/warehouse_40_updates "$@"
fi
