#!/usr/bin/env bash
# Runs every test. Rendering and GUI tests need an X display: without one,
# the whole run goes under Xvfb (Debian's VTK renders through X only).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  exec xvfb-run -a -s "-screen 0 1920x1080x24" ctest --preset default -j "$(nproc)"
fi
exec ctest --preset default -j "$(nproc)"
