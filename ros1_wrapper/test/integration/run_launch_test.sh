#!/usr/bin/env bash
# As a new user would: source the build's devel space, roslaunch a launch file of the package
# (roslaunch starts the roscore), wait for the node's services, call global_localization.
#   run_launch_test.sh BUILD_DIR LAUNCH_FILE [launch args ...]
set -o pipefail  # not -u: catkin's setup scripts read unset variables
build="$1"; launch="$2"; shift 2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
work="$(mktemp -d)"
port="$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')"
# shellcheck disable=SC1091
source "$build/devel/setup.bash"
export ROS_PACKAGE_PATH="$here/../..:${ROS_PACKAGE_PATH:-}"
export ROS_MASTER_URI="http://127.0.0.1:${port}" ROS_IP=127.0.0.1 ROS_HOME="$work" ROS_LOG_DIR="$work/log"
roslaunch -p "$port" krp_relocalizer "$launch" "$@" >"$work/launch.log" 2>&1 &
launcher=$!
cleanup() { kill -INT "$launcher" 2>/dev/null; sleep 2; kill -KILL "$launcher" 2>/dev/null; pkill -KILL -f "rosmaster --core -p $port" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
ok=0
for _ in $(seq 1 150); do
  if rosservice list 2>/dev/null | grep -qx /krp_relocalizer/relocalize; then ok=1; break; fi
  sleep 0.2
done
if [ "$ok" -ne 1 ]; then echo "FAIL: the node's services never appeared"; cat "$work/launch.log"; exit 1; fi
rosservice call /global_localization >/dev/null || { echo "FAIL: /global_localization call failed"; cat "$work/launch.log"; exit 1; }
echo "OK: $launch started the node; /global_localization answered"
