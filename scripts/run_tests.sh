#!/usr/bin/env bash
# One command for all tests: installs what is missing (apt, onnxruntime, the Python training environment),
# builds, runs CTest: GoogleTest, app tests, pytest of models/training, C++/Python parity; then the
# sanitizer build (clang, ASan + UBSan) of the unit tests and a short run of each fuzzer.
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$REPO_ROOT/scripts/install_deps.sh"
bash "$REPO_ROOT/scripts/setup_python.sh"
bash "$REPO_ROOT/scripts/build.sh"
cd "$REPO_ROOT/build"
ctest -j"$(nproc)" --output-on-failure
bash "$REPO_ROOT/scripts/run_sanitizers.sh"
