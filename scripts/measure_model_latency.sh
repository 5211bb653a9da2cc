#!/usr/bin/env bash
# C++ onnxruntime latency of a model folder's two models, one thread, median of 300 runs on a
# submap rendered by krp-dataset; writes <folder>/latency.json and refreshes REPORT.md.
#   scripts/measure_model_latency.sh models/office_two_zone
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
FOLDER="${1:?usage: $0 MODEL_FOLDER}"
RUNS="${KRP_LATENCY_RUNS:-300}"
APPS="$REPO_ROOT/build/mrpt_krp_plugin/apps"
[[ -f "$FOLDER/manifest.json" ]] || { echo "$0: $FOLDER has no manifest.json (a folder krp-train-map wrote?)" >&2; exit 1; }
# One read of the manifest gives the world and the models' own lidar (the submap is rendered
# for it: a user's profile file goes with the models).
{ read -r world; read -r lidar; } < <("$REPO_ROOT/.venv/bin/python" -c \
    "import json,sys; m=json.load(open(sys.argv[1])); print(m['world']); print(m['lidar']['name'])" \
    "$FOLDER/manifest.json")
[[ -n "${world:-}" && -n "${lidar:-}" ]] || { echo "$0: cannot read world and lidar from $FOLDER/manifest.json" >&2; exit 1; }
[[ -f "$FOLDER/lidar.yaml" ]] && lidar="$FOLDER/lidar.yaml"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
"$APPS/krp-dataset" --world "$world" --world-dir "$REPO_ROOT/sim_worlds" --lidar "$lidar" --out "$tmp/d" --samples-per-zone 4 \
    --changed-per-zone 1 --seed 3 >"$tmp/dataset.log" 2>&1 \
  || { cat "$tmp/dataset.log" >&2; echo "$0: krp-dataset failed (its output above)" >&2; exit 1; }
occ="$(find "$tmp/d/classifier/train" -name '*.png' | sort | head -n1)"
sdt="$(find "$tmp/d/keypoints/images/train" -name '*.png' | sort | head -n1)"
"$APPS/krp-infer" --models "$FOLDER" --occupancy "$occ" --sdt "$sdt" --threads 1 --latency "$RUNS" \
    --latency-json "$FOLDER/latency.json"
"$REPO_ROOT/.venv/bin/python" -m krp_training.report "$FOLDER"
