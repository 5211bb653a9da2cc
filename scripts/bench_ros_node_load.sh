#!/usr/bin/env bash
# krp_relocalizer_node under load: scans at 10x a 10 Hz lidar for a minute while ~relocalize is
# called back to back; writes reports/ros_node_load/REPORT.md. Needs a built tree (scripts/build.sh).
#   scripts/bench_ros_node_load.sh [DURATION_S=60] [RATE_HZ=100] [OUT=reports/ros_node_load]
# KRP_BUILD_DIR: the build tree (default: <repo>/build).
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
duration="${1:-60}"; rate="${2:-100}"; out="${3:-$REPO_ROOT/reports/ros_node_load}"
build="${KRP_BUILD_DIR:-$REPO_ROOT/build}"
mkdir -p "$out"
work="$(mktemp -d)"
port="$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')"
export ROS_MASTER_URI="http://127.0.0.1:${port}" ROS_IP=127.0.0.1 ROS_HOME="$work" ROS_LOG_DIR="$work/log"
pids=()
cleanup() { for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null || true; done; sleep 1; for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT
roscore -p "$port" >"$work/roscore.log" 2>&1 & pids+=($!)
timeout 30 bash -c "until rosparam list >/dev/null 2>&1; do sleep 0.2; done"
world="$REPO_ROOT/sim_worlds/office_two_zone/office_two_zone.world.yaml"
"$build/devel/lib/krp_relocalizer/krp_relocalizer_node" _map_file:="$REPO_ROOT/sim_worlds/office_two_zone/office_two_zone.yaml" \
    _relocalize_on_startup:=false >"$work/node.log" 2>&1 &
node=$!; pids+=($node)
"$build/ros1_wrapper/krp_ros_node_load" "$world" "$node" "$duration" "$rate" "$out/REPORT.md"
