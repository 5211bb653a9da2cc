#!/usr/bin/env bash
# What the bag framing check costs (issue 6): readBag checks every record of a bag, decompressing
# bz2 and lz4 chunks, before rosbag reads it and decompresses them again. One simulated trial of
# 6,000 scans (10 min of a 10 Hz lidar) as an uncompressed, a bz2 and an lz4 bag, each checked
# and read 5 times in turn; writes reports/bag_read/REPORT.md (about 1 min).
# Usage: scripts/bench_bag_read.sh   (build first with scripts/build.sh; needs ROS 1)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bench=./build/ros1_wrapper/test/krp_ros_bag_read_bench
[[ -x "$bench" ]] || { echo "$0: $bench not built (scripts/build.sh, with ROS 1)" >&2; exit 2; }
# The bags go to a fixed folder in out/ (ignored by git), so the report's command line reads the
# same on every run; it is removed afterwards (about 50 MB).
work=out/bag_read_bench
mkdir -p "$work"
trap 'rm -rf "$work"' EXIT
mkdir -p reports/bag_read
{
  echo "# Bag framing check against bag reading"
  echo
  "$bench" sim_worlds/office_two_zone/office_two_zone.world.yaml 6000 5 "$work"
} > "$work/REPORT.md"
mv "$work/REPORT.md" reports/bag_read/REPORT.md
cat reports/bag_read/REPORT.md
