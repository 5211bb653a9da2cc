#!/usr/bin/env bash
# Pins scripts/rerun_model_reports.sh to the reports it must rerun: every command it lists is a
# script that exists, every bench script that reads the shipped models (models/office_two_zone,
# models/warehouse, or --models-root models) is listed, and an unknown world or argument is
# refused.
# bench_other_lidars.sh reads models/office_two_zone_lds01 and models/office_two_zone_safety_270,
# folders of their own.
set -euo pipefail
root="${1:?usage: $0 REPO_ROOT}"
script="$root/scripts/rerun_model_reports.sh"
listed="$("$script" --list all)"
[[ -n "$listed" ]] || { echo "nothing listed"; exit 1; }
while read -r line; do
  cmd="${line#KRP_SKIP_SETUP=1 }"
  exe="${cmd%% *}"
  [[ -x "$root/$exe" ]] || { echo "listed but not an executable script: $exe"; exit 1; }
done <<< "$listed"
for f in "$root"/scripts/bench_*.sh; do
  name="scripts/$(basename "$f")"
  [[ "$name" == scripts/bench_other_lidars.sh ]] && continue
  if grep -qE 'models-root models|models/office_two_zone([^_]|$)|models/warehouse' "$f"; then
    grep -q "^$name\( \|$\)" <<< "$listed" || { echo "$name reads the shipped models but is not rerun"; exit 1; }
  fi
done
if "$script" --list nowhere >/dev/null 2>&1; then echo "an unknown world was accepted"; exit 1; fi
# A misplaced or misspelt flag must not start hours of reruns: each of these either lists or
# is refused, and none reaches a bench script (the listing stands in for one here).
[[ "$("$script" warehouse --list)" == "$("$script" --list warehouse)" ]] || { echo "a trailing --list did not list"; exit 1; }
for bad in "warehouse --lsit" "--list warehouse office_two_zone" "--list" "--dry-run all"; do
  # shellcheck disable=SC2086  # word splitting is the point: each is an argument list
  if "$script" $bad >/dev/null 2>&1; then echo "accepted: $bad"; exit 1; fi
done
echo "rerun_model_reports: $(wc -l <<< "$listed") commands, all present"
