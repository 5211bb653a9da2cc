#!/usr/bin/env bash
# A user's new map, end to end: train models for it with krp-train-map (automatic zoning), then
# run krp-bench on it, every method on the same simulated trials. This is what a robot's
# integrator does with a floor plan the project has never seen.
#   scripts/bench_new_map.sh MAP.yaml [NAME]
# Models and the world file go to out/models/NAME (kept: a second run skips training), the report
# to out/new_map/NAME (or OUT). The trials add the office worlds' clutter (boxes, pallets, people)
# to the map. Environment: OUT, TRIALS (30), STEPS (10), SEED (1), SAMPLES_PER_ZONE (1000: poses per zone for
# training; krp-train-map's default of 4000 takes about 4x longer on a large map),
# METHODS (uniform-mcl,amcl-kld,seeded,global-matcher-guarded), LIDAR (omni_12m: a built-in profile
# name, or your scanner's profile file NAME.yaml, which trains the models and simulates the trials).
# Installs what is missing and builds first (as krp-train-map does).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
map="${1:?usage: scripts/bench_new_map.sh MAP.yaml [NAME]}"
[[ -f "$map" ]] || { echo "bench_new_map: map file '$map' not found" >&2; exit 2; }
name="${2:-$(basename "${map%.*}")}"
models="out/models/$name"
out="${OUT:-out/new_map/$name}"
world="$models/$name.world.yaml"
lidar="${LIDAR:-omni_12m}"
if [[ "$lidar" == *.yaml || "$lidar" == *.yml ]]; then
  [[ -f "$lidar" ]] || { echo "bench_new_map: lidar profile file '$lidar' not found" >&2; exit 2; }
  lidar="$(realpath "$lidar")"
fi
if [[ ! -f "$models/manifest.json" ]]; then
  scripts/krp-train-map --map "$map" --lidar "$lidar" --samples-per-zone "${SAMPLES_PER_ZONE:-1000}" --out "$models"
else
  echo "bench_new_map: using the models already in $models (delete the folder to retrain)"
fi
mkdir -p "$out"
# The world: the map, the zones the models were trained with, and the clutter block of the
# office world (read from its file, so the two stay the same).
office_world=sim_worlds/office_two_zone/office_two_zone.world.yaml
clutter="$(awk '/^clutter:/ {on = 1; print; next} on && /^[^ ]/ {on = 0} on' "$office_world")"
[[ -n "$clutter" ]] || { echo "bench_new_map: no clutter block in $office_world" >&2; exit 1; }
cat > "$world.partial" <<YAML
name: $name
map: $(realpath "$map")
zones: $(realpath "$models/zones.yaml")
lidar_profiles: [$lidar]
default_lidar_profile: $lidar
$clutter
YAML
mv "$world.partial" "$world"
./build/mrpt_krp_plugin/apps/krp-bench --worlds "$world" --models-for "$name=$models" \
  --methods "${METHODS:-uniform-mcl,amcl-kld,seeded,global-matcher-guarded}" \
  --trials "${TRIALS:-30}" --steps "${STEPS:-10}" --seed "${SEED:-1}" --out "$out"
