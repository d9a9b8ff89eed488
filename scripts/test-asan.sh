#!/usr/bin/env bash
# The whole suite built with AddressSanitizer and UndefinedBehaviorSanitizer
# (CMake preset `asan`, tree build-asan/); under Xvfb when there is no display.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
cmake --preset asan >/dev/null
cmake --build build-asan -j "$(nproc)"
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  exec xvfb-run -a -s "-screen 0 1920x1080x24" ctest --preset asan -j "$(nproc)"
fi
exec ctest --preset asan -j "$(nproc)"
