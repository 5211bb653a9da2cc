#!/usr/bin/env bash
# Regenerates reports/fresh_seeds/: the office relocalization table on base seeds the project
# never tuned on (the committed relocalization reports use seed 1; the relocalizer's thresholds
# were chosen on seeds 1 and 2 of other scenes). 100 trials per seed, 10 updates, 360 deg 12 m
# lidar, uniform-mcl, amcl-kld and seeded, as a reviewer re-running krp-bench would. ~3 min a seed.
# Usage: scripts/bench_fresh_seeds.sh [SEED ...]   (default: 4 5; build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
seeds=("$@")
[[ ${#seeds[@]} -eq 0 ]] && seeds=(4 5)
for seed in "${seeds[@]}"; do
  [[ "$seed" =~ ^[0-9]+$ ]] || { echo "bench_fresh_seeds: seed '$seed' is not a non-negative integer" >&2; exit 2; }
  ./build/mrpt_krp_plugin/apps/krp-bench --worlds office_two_zone --lidars omni_12m --models-root models \
    --methods uniform-mcl,amcl-kld,seeded --trials 100 --steps 10 --seed "$seed" --out "reports/fresh_seeds/seed_$seed"
done
