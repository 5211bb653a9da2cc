#!/usr/bin/env bash
# Test helper: rewrites a CARMEN log's ROBOTLASER1 lines as a robot without a pose-stamping
# logger writes them, an ODOM line (the robot pose) and a RAWLASER1 line (the scan, no pose),
# so that the reader's RAWLASER1 path can be run on a simulated trial.
#   carmen_as_rawlaser.sh IN.log OUT.log
set -euo pipefail
[[ $# -eq 2 ]] || { echo "usage: $0 IN.log OUT.log" >&2; exit 2; }
awk '$1 != "ROBOTLASER1" { print; next }
{
  n = $9; m = $(10 + n)
  pose = 11 + n + m + 3           # after the laser pose: the robot pose
  last = NF - 2                   # ipc_timestamp ipc_hostname logger_timestamp
  printf "ODOM %s %s %s 0 0 0 %s %s %s\n", $pose, $(pose + 1), $(pose + 2), $last, $(last + 1), $(last + 2)
  line = "RAWLASER1"
  for (i = 2; i < 11 + n + m; ++i) line = line " " $i
  print line, $last, $(last + 1), $(last + 2)
}' "$1" > "$2"
