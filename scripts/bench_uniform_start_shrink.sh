#!/usr/bin/env bash
# A seeded filter that had to start uniform (the relocalizer had no hypothesis), with its count
# kept to the end and with KLD sizing once converged (SeededInitParams::fallback_shrinks, the
# default), on the trials of scripts/bench_new_map.sh (same world file, models, seed, 30 trials,
# 10 updates), one run after the other. Writes OUT/REPORT.md (scripts/uniform_start_shrink_report.py)
# and each run's trials.csv / updates.csv under OUT/{fixed,kld}/. Run scripts/bench_new_map.sh
# first: it writes the world file and trains the models (~7 min on 2 cores for Willow).
# Usage: scripts/bench_uniform_start_shrink.sh NAME [OUT]   (e.g. willow; default OUT:
#        reports/new_map/NAME/uniform_start_shrink)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
name="${1:?usage: $0 NAME [OUT]}"
out="${2:-reports/new_map/$name/uniform_start_shrink}"
models="out/models/$name"
world="$models/$name.world.yaml"
[[ -f "$world" ]] || { echo "$world not found: run scripts/bench_new_map.sh for '$name' first" >&2; exit 2; }
commands=()
for setting in fixed kld; do
  cmd=(./build/mrpt_krp_plugin/apps/krp-bench --worlds "$world" --models-for "$name=$models" --methods seeded
       --trials "${TRIALS:-30}" --steps 10 --seed "${SEED:-1}" --out "$out/$setting")
  [[ $setting == fixed ]] && cmd+=(--seeded-uniform-start-fixed)
  echo "== $name, $setting"
  "${cmd[@]}" >/dev/null
  rm -f "$out/$setting"/*.png
  commands+=("$setting: \`${cmd[*]}\`")
done
python3 scripts/uniform_start_shrink_report.py "$out" "$out/REPORT.md" "scripts/bench_uniform_start_shrink.sh $name" \
  "${commands[@]}"
cat "$out/REPORT.md"
