#!/usr/bin/env bash
# Regenerates reports/watch_rejected/: the look-alike guard with and without watching the
# look-alikes it decided against (LookAlikeGuardParams::watch_rejected; krp-bench
# --guard-forget-rejected turns it off). The office, 100 trials, 30 updates (three times the
# relocalization report's: a look-alike rejected on the first scans can take metres to come back),
# the methods with the guard. ~3 min.
# Usage: scripts/bench_watch_rejected.sh   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
for variant in watched forgotten; do
  flags=()
  [[ "$variant" == forgotten ]] && flags=(--guard-forget-rejected)
  ./build/mrpt_krp_plugin/apps/krp-bench --worlds office_two_zone --lidars omni_12m --models-root models \
    --methods seeded,global-matcher-guarded --trials 100 --steps 30 --seed 1 "${flags[@]}" \
    --out "reports/watch_rejected/$variant"
done
