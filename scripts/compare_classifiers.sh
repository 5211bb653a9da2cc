#!/usr/bin/env bash
# Table 4.2's analogue (architectures with and without scenario generation), the
# leave-one-zone-out check and each compared architecture's inference latency for a world;
# writes <models>/comparison.json and refreshes REPORT.md.
#   scripts/compare_classifiers.sh office_two_zone [extra options of krp_training.compare]
# The model folder is models/WORLD unless the options give --out (a world's models for another
# lidar: --lidar lds01 --out models/office_two_zone_lds01).
# With --add, the architectures given are added to the existing comparison (same budget and
# datasets, checked), so that the thesis's large networks can be run one at a time.
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORLD="${1:?usage: $0 WORLD [options]}"
shift
OUT=""
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  case "${args[i]}" in
    --out) OUT="${args[i + 1]:?--out needs a folder}" ;;
    --out=*) OUT="${args[i]#--out=}" ;;
  esac
done
# Given once, so that the command the comparison records reads as it was meant.
[[ -z "$OUT" ]] && OUT="models/$WORLD" && args=(--out "$OUT" "${args[@]}")
cd "$REPO_ROOT"
"$REPO_ROOT/.venv/bin/python" -m krp_training.compare --world "$WORLD" "${args[@]}"
exec "$REPO_ROOT/.venv/bin/python" -m krp_training.architecture_latency --out "$OUT"
