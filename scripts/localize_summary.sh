# Markdown tables from krp-localize's krp_localize_SUMMARY.txt, for the report scripts that run it
# (sourced by scripts/check_freiburg.sh and scripts/check_freiburg_learned.sh).

# summary_value FILE KEY: the value of the summary's `KEY: value` line.
summary_value() { sed -n "s/^$2: //p" "$1" | head -1; }

# single_scan_cells SUMMARY: the cells of a `--single-scan all` sweep's row, '|'-separated.
readonly single_scan_header="said localized | localized and right | localized but wrong | best right (any verdict) | median error when localized | localized from the keypoint model | time per scan, median / p95"
single_scan_cells() {
  local s="$1"
  echo "$(summary_value "$s" "said localized") | $(summary_value "$s" "localized and right") | $(summary_value "$s" "localized but wrong") | $(summary_value "$s" "best hypothesis right (any verdict)") | $(summary_value "$s" "median error when localized") | $(summary_value "$s" "localized from the keypoint model") | $(summary_value "$s" "time per scan" | sed 's/median //; s/, p95 / \/ /')"
}

# single_scan_table SUMMARY: header and row of a `--single-scan all` sweep.
single_scan_table() {
  echo "| scans | $single_scan_header |"
  echo "|---|---|---|---|---|---|---|---|"
  echo "| $(summary_value "$1" "scans relocalized") | $(single_scan_cells "$1") |"
}

# single_scan_comparison LABEL SUMMARY [LABEL SUMMARY...]: one row per sweep of the same scans.
single_scan_comparison() {
  echo "| relocalizer | $single_scan_header |"
  echo "|---|---|---|---|---|---|---|---|"
  while (($# >= 2)); do
    echo "| $1 | $(single_scan_cells "$2") |"
    shift 2
  done
}

# filter_table DIR METHOD...: one row per method, from DIR/filter_METHOD/krp_localize_SUMMARY.txt.
filter_table() {
  local dir="$1" m s
  shift
  echo "| method | initial particles | converged | updates to convergence | final error | median error | confident but wrong | localization CPU |"
  echo "|---|---|---|---|---|---|---|---|"
  for m in "$@"; do
    s="$dir/filter_$m/krp_localize_SUMMARY.txt"
    echo "| $m | $(summary_value "$s" "initial particles") | $(summary_value "$s" "converged") | $(summary_value "$s" "updates to convergence") | $(summary_value "$s" "final error") | $(summary_value "$s" "median error") | $(summary_value "$s" "confident but wrong") | $(summary_value "$s" "localization CPU") |"
  done
}
