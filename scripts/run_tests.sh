#!/usr/bin/env bash
# One command for all tests: installs what is missing, builds, runs CTest (GoogleTest + app tests).
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$REPO_ROOT/scripts/install_deps.sh"
bash "$REPO_ROOT/scripts/build.sh"
cd "$REPO_ROOT/build"
ctest -j"$(nproc)" --output-on-failure
