#!/usr/bin/env bash
# Regenerates the committed baseline reports under reports/baseline/ (issue 2):
#   warehouse: 360 deg 12 m lidar, uniform-mcl vs amcl-kld vs amcl-kld-50k, 30 trials (~30 min);
#   willow (only where ../shared/data/willow exists; the map itself is never committed): the
#   independent reference of ../shared/notes/baseline-willow.md redone with krp-bench, 10 trials (~5 min).
# Usage: scripts/bench_baselines.sh [warehouse|willow|all]   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
which="${1:-all}"
build="$root/build"
bench="$build/mrpt_krp_plugin/apps/krp-bench"
zones="$build/mrpt_krp_plugin/apps/krp-zones"
out="reports/baseline"
cd "$root"

if [[ "$which" == all || "$which" == warehouse ]]; then
  "$bench" --worlds warehouse --lidars omni_12m --methods uniform-mcl,amcl-kld,amcl-kld-50k --trials 30 --seed 1 \
    --out "$out/warehouse"
fi

willow_map="$root/../shared/data/willow/willow-full.yaml"
if [[ "$which" == all || "$which" == willow ]]; then
  if [[ ! -f "$willow_map" ]]; then
    echo "skipping willow: $willow_map not found"
    exit 0
  fi
  tmp="$(mktemp -d)"
  trap 'rm -rf "$tmp"' EXIT
  "$zones" --map "$willow_map" --out-yaml "$tmp/willow.zones.yaml" --out-png "$out/willow/willow.zones.png"
  cat > "$tmp/willow.world.yaml" <<YAML
name: willow
map: $(realpath "$willow_map")
zones: willow.zones.yaml
lidar_profiles: [omni_12m, safety_270]
default_lidar_profile: omni_12m
clutter: {boxes_per_100m2: 0, box_min_side_m: 0.3, box_max_side_m: 0.8, pallets_per_100m2: 0, people_per_100m2: 0, placement_clearance_m: 0.2}
YAML
  "$bench" --worlds "$tmp/willow.world.yaml" --lidars omni_12m --methods uniform-mcl,amcl-kld,amcl-kld-50k \
    --uniform-particles 100000 --trials 10 --seed 1 --out "$out/willow"
fi
