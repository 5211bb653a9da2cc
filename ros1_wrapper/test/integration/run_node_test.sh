#!/usr/bin/env bash
# Runs one integration test of krp_relocalizer_node against a real roscore on loopback:
# starts roscore on a free port and the node, runs the test binary, checks the node is still
# running, stops everything.
#   run_node_test.sh NODE_BIN TEST_BIN GTEST_FILTER [node args: _param:=value ...]
# With GTEST_FILTER "expect-node-exit", the node alone is run and must exit non-zero in time.
set -uo pipefail
node_bin="$1"; test_bin="$2"; filter="$3"; shift 3

work="$(mktemp -d)"
port="$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')"
export ROS_MASTER_URI="http://127.0.0.1:${port}" ROS_IP=127.0.0.1 ROS_HOME="$work" ROS_LOG_DIR="$work/log"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null; done
  sleep 0.5
  for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT

roscore -p "$port" >"$work/roscore.log" 2>&1 &
pids+=($!)
for _ in $(seq 1 100); do
  /usr/bin/python3 -c "import socket; socket.create_connection(('127.0.0.1', ${port}), 0.2)" 2>/dev/null && break
  sleep 0.2
done
# The master answers before the parameter server is ready to be used by rosparam/nodes.
timeout 20 bash -c "until rosparam list >/dev/null 2>&1; do sleep 0.2; done" || { cat "$work/roscore.log"; exit 1; }

if [ "$filter" = "expect-node-exit" ]; then
  timeout 30 "$node_bin" "$@" >"$work/node.log" 2>&1
  rc=$?
  cat "$work/node.log"
  if [ "$rc" -eq 0 ] || [ "$rc" -eq 124 ]; then echo "FAIL: the node should have exited with an error (rc $rc)"; exit 1; fi
  echo "OK: the node refused to start (rc $rc)"
  exit 0
fi

"$node_bin" "$@" >"$work/node.log" 2>&1 &
node_pid=$!
pids+=($node_pid)
"$test_bin" --gtest_filter="$filter"
rc=$?
if ! kill -0 "$node_pid" 2>/dev/null; then echo "FAIL: the node died during the test"; rc=1; fi
if [ "$rc" -ne 0 ]; then echo "--- node log"; cat "$work/node.log"; fi
exit $rc
