# The Freiburg 101 log, the report folder and the built apps, from a check script's arguments
# [DATA_DIR] [OUT_DIR]; sourced (with "$@") by check_freiburg.sh and check_freiburg_learned.sh
# once they have set `root` and changed to it.
data="${1:-$root/../shared/data/freiburg-101}"
out="${2:-reports/freiburg_101}"
log="$data/freiburg-101-corrected.log.gz"
bin=./build/mrpt_krp_plugin/apps
[[ -f "$log" ]] || { echo "$(basename "$0" .sh): $log not found (the shared data folder)" >&2; exit 2; }
